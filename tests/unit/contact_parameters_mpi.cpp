// The contact pair parameters at non-default values, each in a test that
// fails if the parameter were ignored, on Cattaneo–Mindlin
// (xml/cattaneo_mindlin_2d.xml: pressing, then a stick core with slipping
// edges under a rising shear). The ALM answer must not depend on the
// parameters that only steer the semi-smooth Newton (κ, α, the reset
// frequency, the search); the penalty answer depends on ε_n, κ and the
// slip threshold exactly as the penalty law says. Scale Factor and Penalty
// Factor with ALM: tests/regression/penalty_independence.cmake; Pure Slip:
// contact_friction_semantics_mpi.cpp; the convergence tolerances of the
// criteria: contact_criteria_mpi.cpp.
#include <gtest/gtest.h>

#include <Teuchos_TimeMonitor.hpp>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

constexpr double kMu = 0.3;
const std::string kAlm = "<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>";

std::string parameter(const std::string& name, const std::string& type, const std::string& value) {
  return "<Parameter name=\"" + name + "\" type=\"" + type + "\" value=\"" + value + "\"/>";
}
std::string real(const std::string& name, double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return parameter(name, "double", text.str());
}

/// Cattaneo–Mindlin with `pairParameters` added to the pair, its
/// formulation replaced when `formulation` is not ALM, `contactParameters`
/// added to the Contact list.
ContactRun cattaneo(const std::string& name, const std::string& pairParameters,
                    const std::string& formulation = "ALM", const std::string& contactParameters = "") {
  ShippedDeck deck("cattaneo_mindlin_2d", "hertz2d.e");
  deck.replace(kAlm, parameter("Formulation", "string", formulation) + pairParameters);
  deck.replace("<ParameterList name=\"Pairs\">", contactParameters + "<ParameterList name=\"Pairs\">");
  return runDeckText(name, deck.text);
}

/// The ALM answer of `run` is the default one (the tolerances of the
/// contact rows bound the difference: 1e-6 of the contact forces).
void expectSameAnswer(const ContactRun& reference, const ContactRun& run, const std::string& what) {
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure", "contact_tangential_traction_x",
                            "contact_slip_x"})
    EXPECT_LT(nodalDifference(reference.results, run.results, field), 1e-5) << what << ": " << field;
  EXPECT_EQ(lastNodal(reference.results, "contact_state"), lastNodal(run.results, "contact_state")) << what;
}

const std::vector<double>& field(const io::ExodusResults& r, std::size_t step, const std::string& name) {
  return r.nodal[step][r.nodalIndex(name)];
}

// κ and α weigh the slip in the ALM stick/slip decision and the slip
// direction only: the converged answer is the default one, the path is not
// (the relations of the augmented traction that show κ and α at work:
// contact_augmented_output_mpi.cpp).
TEST(ContactParameters, AlmAnswerDoesNotDependOnTangentFactorOrSlipAugmentation) {
  auto reference = cattaneo("parameters_alm_default", "");
  auto kappa = cattaneo("parameters_alm_kappa", real("Tangent Factor", 0.1));
  auto alpha = cattaneo("parameters_alm_alpha", real("Slip Augmentation Coefficient", 5.0));
  expectSameAnswer(reference, kappa, "Tangent Factor 0.1");
  expectSameAnswer(reference, alpha, "Slip Augmentation Coefficient 5");
}

// Penalty: the normal penalty is Penalty Factor × E / h, so at every active
// node p / (-g) is ten times the default's with Penalty Factor 10 (the same
// mesh and material: the same h and E per node).
TEST(ContactParameters, PenaltyFactorScalesThePenaltyPressure) {
  auto reference = cattaneo("parameters_penalty_default", "", "Penalty");
  auto stiff = cattaneo("parameters_penalty_factor", real("Penalty Factor", 10.0), "Penalty");
  if (worldComm()->getRank() != 0) return;
  const auto &p1 = lastNodal(reference.results, "contact_pressure"), &g1 = lastNodal(reference.results, "contact_gap");
  const auto &p10 = lastNodal(stiff.results, "contact_pressure"), &g10 = lastNodal(stiff.results, "contact_gap");
  int compared = 0;
  for (std::size_t i = 0; i < p1.size(); ++i) {
    if (!(p1[i] > 0.0 && p10[i] > 0.0)) continue;
    ++compared;
    EXPECT_NEAR((p10[i] / -g10[i]) / (p1[i] / -g1[i]), 10.0, 1e-8) << "node " << i + 1;
  }
  EXPECT_GT(compared, 5);
}

// Penalty: Tangent Factor κ is the stiffness of a sticking contact, the
// trial traction of the return map t* = P (t_old + κ ε_n w / D) (t_old the
// traction of the last step, w the weighted slip of the step): every
// sticking node's traction follows it with κ = 0.25, which the default
// κ = 1 would miss by a factor 4.
TEST(ContactParameters, PenaltyTangentFactorIsTheStickStiffness) {
  constexpr double kPenalty = 2.0e6, kKappa = 0.25;
  auto run = cattaneo("parameters_penalty_kappa", real("Penalty", kPenalty) + real("Tangent Factor", kKappa),
                      "Penalty");
  EXPECT_EQ(run.summary.cutbacks, 0);  // t_old is the traction of the step written before
  if (worldComm()->getRank() != 0) return;
  const auto& r = run.results;
  int checked = 0;
  for (std::size_t s = 1; s < r.nodal.size(); ++s) {
    const auto &state = field(r, s, "contact_state"), &oldState = field(r, s - 1, "contact_state"),
               &tx = field(r, s, "contact_tangential_traction_x"), &ty = field(r, s, "contact_tangential_traction_y"),
               &ox = field(r, s - 1, "contact_tangential_traction_x"),
               &oy = field(r, s - 1, "contact_tangential_traction_y"), &nx = field(r, s, "contact_normal_x"),
               &ny = field(r, s, "contact_normal_y"), &wx = field(r, s, "contact_weighted_slip_x"),
               &wy = field(r, s, "contact_weighted_slip_y"), &D = field(r, s, "contact_area"),
               &p = field(r, s, "contact_pressure"), &oldP = field(r, s - 1, "contact_pressure"),
               &oldNx = field(r, s - 1, "contact_normal_x"), &oldNy = field(r, s - 1, "contact_normal_y");
    double pMax = 0;
    for (double v : p) pMax = std::max(pMax, v);
    for (std::size_t i = 0; i < state.size(); ++i) {
      if (state[i] < 1.5 || oldState[i] < 0.5) continue;  // sticking now, in contact in the last step
      // t_old the whole traction of the last step, -p n + t_tau: its normal
      // part, projected on the new tangent, is -p times the normal's turn.
      const double oldX = ox[i] - oldP[i] * oldNx[i], oldY = oy[i] - oldP[i] * oldNy[i];
      const double on = oldX * nx[i] + oldY * ny[i];
      const double wn = wx[i] * nx[i] + wy[i] * ny[i];
      const double ex = oldX - on * nx[i] + kKappa * kPenalty * (wx[i] - wn * nx[i]) / D[i];
      const double ey = oldY - on * ny[i] + kKappa * kPenalty * (wy[i] - wn * ny[i]) / D[i];
      EXPECT_NEAR(tx[i], ex, 1e-8 * pMax) << "step " << s << " node " << i + 1;
      EXPECT_NEAR(ty[i], ey, 1e-8 * pMax) << "step " << s << " node " << i + 1;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

// Stick and Slip Relative Tolerance bound the stick and slip rows at
// convergence: much tighter ones cost Newton iterations (quadratic
// convergence: one more where the default stopped), at the same answer.
TEST(ContactParameters, StickAndSlipTolerancesAreUsed) {
  auto reference = cattaneo("parameters_tolerance_default", "");
  auto stick = cattaneo("parameters_tolerance_stick", "", "ALM", real("Stick Relative Tolerance", 1e-11));
  auto slip = cattaneo("parameters_tolerance_slip", "", "ALM", real("Slip Relative Tolerance", 1e-11));
  EXPECT_GT(stick.summary.newtonIterations, reference.summary.newtonIterations);
  EXPECT_GT(slip.summary.newtonIterations, reference.summary.newtonIterations);
  expectSameAnswer(reference, stick, "Stick Relative Tolerance 1e-11");
  expectSameAnswer(reference, slip, "Slip Relative Tolerance 1e-11");
}

// Search Every Iteration: the candidate search runs at every evaluation
// instead of once per step (its own timer counts the calls); on this small
// slide the candidates do not change, nor does the answer.
TEST(ContactParameters, SearchEveryIterationSearchesAtEveryIterate) {
  const auto searches = [] {
    const auto counter = Teuchos::TimeMonitor::lookupCounter("Coulomb: contact search");
    return counter.is_null() ? 0 : counter->numCalls();
  };
  const int before = searches();
  auto reference = cattaneo("parameters_search_step", "");
  const int perStep = searches() - before;
  auto every = cattaneo("parameters_search_every", parameter("Search Every Iteration", "bool", "true"));
  const int perIterate = searches() - before - perStep;
  EXPECT_LE(perStep, reference.summary.steps + reference.summary.cutbacks + 1);
  EXPECT_GE(perIterate, every.summary.newtonIterations);
  expectSameAnswer(reference, every, "Search Every Iteration");
}

// Slip Threshold is the hysteresis of slip -> stick: a slipping penalty node
// sticks again only when its trial traction falls below (1 - threshold) μ p.
// Cattaneo–Mindlin unloaded by a tenth of the shear in its last deck step:
// the edges that slipped stop, their trial traction falls inside the cone.
// Kept slipping (Slip Reset Frequency 0), with threshold 0.5 they carry μ p
// with |t*| down to 0.79 μ p (measured; never below 0.5 μ p), with the
// default 0.02 they stick. Slip Reset Frequency restarts them as stick at
// deck steps 1, 1 + n, ...: 1 sticks them at once; 2 keeps them slipping
// when the unloading step is the 10th, sticks them when it is the 11th.
ContactRun unloadedPenalty(const std::string& name, const std::string& pairParameters, int steps = 10) {
  ShippedDeck deck("cattaneo_mindlin_2d", "hertz2d.e");
  const std::string t = std::to_string(steps);
  deck.replace("<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 5, 10}\"/><Parameter name=\"Values\" "
               "type=\"Array(double)\" value=\"{0, 0, 1}\"/>",
               "<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 5, " + std::to_string(steps - 1) + ", " + t +
                   "}\"/><Parameter name=\"Values\" type=\"Array(double)\" value=\"{0, 0, 1, 0.9}\"/>");
  deck.replace("<Parameter name=\"Number of Steps\" type=\"int\" value=\"10\"/><Parameter name=\"Final Time\" "
               "type=\"double\" value=\"10\"/>",
               "<Parameter name=\"Number of Steps\" type=\"int\" value=\"" + t +
                   "\"/><Parameter name=\"Final Time\" type=\"double\" value=\"" + t + "\"/>");
  deck.replace(kAlm, parameter("Formulation", "string", "Penalty") + pairParameters);
  return runDeckText(name, deck.text);
}

/// Slipping nodes of the last step whose trial traction is below `below` μ p.
int slippingInsideTheCone(const io::ExodusResults& r, double below) {
  const std::size_t s = r.nodal.size() - 1;
  const auto &state = field(r, s, "contact_state"), &p = field(r, s, "contact_pressure"),
             &ax = field(r, s, "contact_augmented_traction_x"), &ay = field(r, s, "contact_augmented_traction_y");
  int inside = 0;
  for (std::size_t i = 0; i < state.size(); ++i)
    if (state[i] > 0.5 && state[i] < 1.5 && std::hypot(ax[i], ay[i]) < below * kMu * p[i]) ++inside;
  return inside;
}

TEST(ContactParameters, SlipThresholdAndResetFrequencyOnUnloading) {
  const auto frequency = [](int n) { return parameter("Slip Reset Frequency", "int", std::to_string(n)); };
  const std::string threshold = real("Slip Threshold", 0.5);
  auto plain = unloadedPenalty("parameters_unload_default", frequency(0));
  auto kept = unloadedPenalty("parameters_unload_threshold", frequency(0) + threshold);
  auto reset = unloadedPenalty("parameters_unload_reset_1", threshold);
  auto even = unloadedPenalty("parameters_unload_reset_2_even", frequency(2) + threshold);
  auto odd = unloadedPenalty("parameters_unload_reset_2_odd", frequency(2) + threshold, 11);
  if (worldComm()->getRank() != 0) return;
  constexpr double kInside = 0.98 - 1e-9;  // below the default band
  EXPECT_EQ(slippingInsideTheCone(plain.results, kInside), 0);
  EXPECT_GT(slippingInsideTheCone(kept.results, kInside), 0);
  EXPECT_EQ(slippingInsideTheCone(kept.results, 0.5 - 1e-9), 0);
  EXPECT_EQ(slippingInsideTheCone(reset.results, kInside), 0);
  EXPECT_GT(slippingInsideTheCone(even.results, kInside), 0);
  EXPECT_EQ(slippingInsideTheCone(odd.results, kInside), 0);
}

}  // namespace
}  // namespace coulomb::test
