// The augmented nodal values the state rule judges, written per slave node
// (`contact_augmented_pressure`, `contact_augmented_traction_*`,
// the seed's AUGMENTED_NORMAL_CONTACT_PRESSURE and ..._TANGENT_...), checked
// against their definitions at every converged step, with an explicit
// penalty eps_n so that the laws can be evaluated from the output alone:
//   ALM   p̄ = -(k lambda_n + eps_n g~ / D): active nodes p̄ = p (g~ = 0 at
//         convergence), open nodes p̄ = -eps_n g; lambdā_tau = k lambda_tau +
//         a kappa eps_n w / D, so stick nodes (w = 0) carry lambdā_tau = t_tau
//         and slip nodes (a = alpha, w parallel to t_tau) |lambdā_tau| =
//         |t_tau| + alpha kappa eps_n |w| / D along t_tau;
//   Penalty p̄ = -eps_n g~ / D = p on active nodes; lambdā_tau = t* the trial
//         traction: t* = t_tau when sticking, t_tau = mu p t* / |t*| when slipping.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

constexpr double kPenalty = 2.0e6;  // eps_n [pressure/length], about 5 E / h on this mesh
constexpr double kTangentFactor = 0.5, kSlipAugmentation = 2.0, kMu = 0.3;

ContactRun runCattaneoMindlin(const std::string& name, const std::string& formulation) {
  ShippedDeck deck("cattaneo_mindlin_2d", "hertz2d.e");
  const std::string alm = "<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>";
  deck.replace(alm, "<Parameter name=\"Formulation\" type=\"string\" value=\"" + formulation +
                        "\"/><Parameter name=\"Penalty\" type=\"double\" value=\"" + std::to_string(kPenalty) +
                        "\"/><Parameter name=\"Tangent Factor\" type=\"double\" value=\"" +
                        std::to_string(kTangentFactor) +
                        "\"/><Parameter name=\"Slip Augmentation Coefficient\" type=\"double\" value=\"" +
                        std::to_string(kSlipAugmentation) + "\"/>");
  return runDeckText(name, deck.text);
}

struct Counts {
  int stick = 0, slip = 0, open = 0;
};

/// Checks every step of `r`; `alm` selects the ALM laws, else the penalty ones.
Counts checkAugmented(const io::ExodusResults& r, bool alm) {
  Counts counts;
  const auto field = [&](std::size_t step, const char* name) -> const std::vector<double>& {
    return r.nodal[step][r.nodalIndex(name)];
  };
  for (std::size_t s = 0; s < r.nodal.size(); ++s) {
    const auto &state = field(s, "contact_state"), &p = field(s, "contact_pressure"),
               &pBar = field(s, "contact_augmented_pressure"), &gap = field(s, "contact_gap"),
               &area = field(s, "contact_area"), &tx = field(s, "contact_tangential_traction_x"),
               &ty = field(s, "contact_tangential_traction_y"), &ax = field(s, "contact_augmented_traction_x"),
               &ay = field(s, "contact_augmented_traction_y"), &wx = field(s, "contact_weighted_slip_x"),
               &wy = field(s, "contact_weighted_slip_y");
    double pMax = 0;
    for (double v : p) pMax = std::max(pMax, v);
    if (pMax == 0.0) continue;
    const double tolerance = 1e-5 * pMax;  // the contact rows' tolerance, 1e-6 of the contact forces
    for (std::size_t i = 0; i < state.size(); ++i) {
      const std::string where = "step " + std::to_string(s) + " node " + std::to_string(i + 1);
      if (state[i] < 0.5) {
        // An open node with a master in reach: p̄ = -eps_n g (lambda = 0).
        if (area[i] > 0.0 && gap[i] > 0.0) {
          EXPECT_NEAR(pBar[i], -kPenalty * gap[i], 1e-9 * kPenalty * gap[i]) << where;
          ++counts.open;
        }
        EXPECT_EQ(ax[i], 0.0) << where;
        continue;
      }
      EXPECT_NEAR(pBar[i], p[i], alm ? tolerance : 1e-9 * pMax) << where;
      const double t = std::hypot(tx[i], ty[i]), a = std::hypot(ax[i], ay[i]);
      if (state[i] > 1.5) {  // stick
        ++counts.stick;
        EXPECT_NEAR(ax[i], tx[i], tolerance) << where;
        EXPECT_NEAR(ay[i], ty[i], tolerance) << where;
        continue;
      }
      ++counts.slip;
      EXPECT_GT(t, 0.0) << where;
      if (!(t > 0.0)) continue;
      EXPECT_GT((ax[i] * tx[i] + ay[i] * ty[i]) / (a * t), 1.0 - 1e-8) << where;  // along t_tau
      if (alm) {
        // |w_tau|: w along t_tau (its normal part does not enter lambdā_tau).
        const double w = std::abs(wx[i] * tx[i] + wy[i] * ty[i]) / t;
        EXPECT_NEAR(a, t + kSlipAugmentation * kTangentFactor * kPenalty * w / area[i], tolerance) << where;
      } else {
        EXPECT_NEAR(t, kMu * p[i], 1e-9 * pMax) << where;
        EXPECT_GE(a, t * (1 - 1e-12)) << where;
      }
    }
  }
  return counts;
}

TEST(AugmentedOutput, AlmFollowsItsDefinition) {
  auto run = runCattaneoMindlin("augmented_alm", "ALM");
  if (worldComm()->getRank() != 0) return;
  const Counts c = checkAugmented(run.results, true);
  // The case has all three kinds of node (Cattaneo–Mindlin: a stick core,
  // slipping edges, open nodes beside the contact zone).
  EXPECT_GT(c.stick, 0);
  EXPECT_GT(c.slip, 0);
  EXPECT_GT(c.open, 0);
}

TEST(AugmentedOutput, PenaltyIsTheTrialTraction) {
  auto run = runCattaneoMindlin("augmented_penalty", "Penalty");
  if (worldComm()->getRank() != 0) return;
  const Counts c = checkAugmented(run.results, false);
  EXPECT_GT(c.stick, 0);
  EXPECT_GT(c.slip, 0);
  EXPECT_GT(c.open, 0);
}

}  // namespace
}  // namespace coulomb::test
