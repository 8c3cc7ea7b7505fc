// Frictional contact end to end (ALM, penalty and MPC, Coulomb and Tresca): patch tests on
// the 2D patch meshes, matching and non-matching (stick, imposed slip, mu = 0,
// Tresca; 3D: contact_friction_patch3d_mpi.cpp), and the sliding punch (stick,
// partial slip, gross slip). Every run happens at
// np = 1, 2, 3 (ctest MpiTests.np*); the decks are the shipped ones, edited.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ContactTestSupport.hpp"
#include "FrictionDeckSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"

namespace coulomb::test {
namespace {

/// The sliding punch of a variant (xml/friction_punch.xml edited): no
/// cutback, at most 4 Newton iterations per increment on average, and in
/// gross slip Q = mu P within 1 % (checked on rank 0). Prints the figures.
void expectGrossSlipAtMu(const ContactRun& sliding, const char* variant) {
  EXPECT_EQ(sliding.summary.cutbacks, 0);
  int newton = 0;
  for (int iterations : sliding.summary.stepNewtonIterations) newton += iterations;
  EXPECT_LE(newton, 4 * 24);
  if (worldComm()->getRank() != 0) return;
  const auto& r = sliding.results;
  const double Q = std::abs(lastGlobal(r, "reaction_top_x")), P = -lastGlobal(r, "reaction_top_z");
  EXPECT_NEAR(Q / P, kMu, 0.01 * kMu);
  std::printf("%s sliding punch: Q/P %.5f, %d Newton iterations\n", variant, Q / P, newton);
}

}  // namespace

// Perfect stick under a tangential load below mu P: the two bodies deform as
// one, the homogeneous field is reproduced to round-off across the
// non-matching interface, no node slips, traction = -tau / p per node.
TEST(FrictionPatch, StickBelowTheConeIsExact) {
  auto run = runDeckText("friction_patch_stick", stickPatchDeck());
  const double tau = kMu * kPressure / 2;
  EXPECT_LT(homogeneousFieldError(*run.simulation, tau, 0.0), 1e-9 * 0.01);
  for (int iterations : run.summary.stepNewtonIterations) EXPECT_LE(iterations, 3);
  if (worldComm()->getRank() != 0) return;
  const double stretch = 1 + kEpsXX;  // tractions are per current length
  const auto nodes = checkTractions(run.results, [&](double) { return -tau / stretch; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.stick, 8);
  EXPECT_EQ(nodes.slip, 0);
  const auto& slip = lastNodal(run.results, "contact_slip_x");
  for (double s : slip) EXPECT_LT(std::abs(s), 1e-12);
  EXPECT_NEAR(lastGlobal(run.results, "contact_force_punch_x"), -tau, 1e-8 * kPressure);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_top_x"), tau, 1e-8 * kPressure);
  EXPECT_EQ(lastGlobal(run.results, "contact_stick_nodes_punch"), 8.0);
}

// The same stick patch on matching meshes (4 punch faces on 4 base faces).
TEST(FrictionPatch, StickIsExactOnMatchingMeshes) {
  std::string text = stickPatchDeck();
  const std::string from = shippedMesh("contact_patch2d.e"), to = shippedMesh("contact_patch2d_matching.e");
  text.replace(text.find(from), from.size(), to);
  auto run = runDeckText("friction_patch_stick_matching", text);
  EXPECT_LT(homogeneousFieldError(*run.simulation, kMu * kPressure / 2, 0.0), 1e-9 * 0.01);
  if (worldComm()->getRank() != 0) return;
  const double tau = kMu * kPressure / 2, stretch = 1 + kEpsXX;
  const auto nodes = checkTractions(run.results, [&](double) { return -tau / stretch; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.stick, 5);
}

// Coulomb with mu = 0 runs frictionless sliding, with or without Pure Slip:
// the Hertz 2D result equals the frictionless one.
TEST(FrictionPatch, ZeroFrictionIsFrictionless) {
  const std::string alm = "<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>";
  const std::string zeroMu = "<Parameter name=\"Friction Law\" type=\"string\" value=\"Coulomb\"/><Parameter "
                             "name=\"Friction Coefficient\" type=\"double\" value=\"0\"/>";
  ShippedDeck zero("hertz2d", "hertz2d.e"), pure("hertz2d", "hertz2d.e");
  zero.replace(alm, alm + zeroMu);
  pure.replace(alm, alm + zeroMu + "<Parameter name=\"Pure Slip\" type=\"bool\" value=\"true\"/>");
  auto frictionless = runDeck("hertz2d");
  auto mu0 = runDeckText("friction_zero_mu", zero.text);
  auto slip = runDeckText("friction_zero_mu_pure_slip", pure.text);
  if (worldComm()->getRank() != 0) return;
  const double reference = lastGlobal(frictionless.results, "reaction_top_y");
  EXPECT_NEAR(lastGlobal(mu0.results, "reaction_top_y"), reference, 1e-9 * std::abs(reference));
  EXPECT_NEAR(lastGlobal(slip.results, "reaction_top_y"), reference, 1e-9 * std::abs(reference));
  EXPECT_NEAR(lastGlobal(slip.results, "contact_force_cylinder_x"), lastGlobal(frictionless.results, "contact_force_cylinder_x"),
              1e-9 * std::abs(reference));
}

// Imposed slip: the punch is dragged by s over the base; every slave node
// slips and carries exactly mu p against the slip (the ratio per node and in
// total; the overlap of the shifted punch ends differs from the homogeneous
// state, so the pressure itself is not uniform near the ends).
TEST(FrictionPatch, ImposedSlipCarriesMuTimesPressure) {
  auto run = runDeck("friction_patch_2d");
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(run.results, [](double p) { return -kMu * p; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.slip, 8);
  EXPECT_EQ(nodes.stick, 0);
  const auto& slip = lastNodal(run.results, "contact_slip_x");
  const auto& state = lastNodal(run.results, "contact_state");
  for (std::size_t i = 0; i < slip.size(); ++i)
    if (state[i] > 0.5) {
      EXPECT_GT(slip[i], 0.5 * kImposedSlip) << "node " << i + 1;  // the punch moved along +x over the base
      EXPECT_LT(slip[i], 1.5 * kImposedSlip) << "node " << i + 1;
    }
  // In total: the nodal normals tilt by up to 3e-3 near the deformed ends,
  // so the x/y ratio of the sums is mu only to about 1e-3 of mu.
  const double Q = lastGlobal(run.results, "contact_force_punch_x"), P = lastGlobal(run.results, "contact_force_punch_y");
  EXPECT_NEAR(Q / P, -kMu, 1e-3 * kMu);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_top_x"), -Q, 1e-8 * kPressure);  // momentum balance
}

// Translation without rotation: the objective slip (4.69b) and the
// non-objective one (4.65a) are the same measure of the imposed slip, at
// every node — also at the node x = 6/7 whose support leaves the base's
// master faces during the slide. There the rate form counts the moving
// edge of the overlap as slip (measured before the coverage rule of
// ContactPairSlip.cpp: 2.84e-3 against 1.94e-3); with it the objective
// measure falls back to the non-objective one where the support is partly
// off the master (measured: equal to 1e-4 relative at every node).
TEST(FrictionPatch, ObjectiveSlipEqualsTheNonObjectiveOnAnImposedSlip) {
  ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
  deck.replace("<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>",
               "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/><Parameter name=\"Slip "
               "Measure\" type=\"string\" value=\"Non-Objective\"/>");
  auto objective = runDeck("friction_patch_2d");
  auto nonObjective = runDeckText("friction_patch_non_objective", deck.text);
  if (worldComm()->getRank() != 0) return;
  const auto& a = lastNodal(objective.results, "contact_slip_x");
  const auto& b = lastNodal(nonObjective.results, "contact_slip_x");
  const auto& state = lastNodal(objective.results, "contact_state");
  int slipping = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (state[i] < 0.5) continue;
    ++slipping;
    EXPECT_NEAR(a[i], b[i], 1e-3 * kImposedSlip) << "node " << i + 1;
  }
  EXPECT_EQ(slipping, 8);
}

// Imposed slip on matching meshes (every punch node starts on a base node)
// carries mu p per node as on the non-matching ones; with mu = 0 the same
// slip carries no tangential traction at all (pure slip, automatic).
TEST(FrictionPatch, ImposedSlipOnMatchingMeshesAndWithoutFriction) {
  ShippedDeck matching("friction_patch_2d", "contact_patch2d.e"), mu0("friction_patch_2d", "contact_patch2d.e"),
      noLaw("friction_patch_2d", "contact_patch2d.e");
  matching.replace(shippedMesh("contact_patch2d.e"), shippedMesh("contact_patch2d_matching.e"));
  mu0.replace("<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>",
              "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0\"/>");
  noLaw.replace(kCoulombLaw, "");
  noLaw.replace("<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>", "");
  auto slip = runDeckText("friction_patch_slip_matching", matching.text);
  auto free = runDeckText("friction_patch_mu0", mu0.text);
  auto frictionless = runDeckText("friction_patch_frictionless", noLaw.text);
  EXPECT_EQ(slip.summary.cutbacks, 0);
  EXPECT_EQ(free.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(slip.results, [](double p) { return -kMu * p; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.stick, 0);
  EXPECT_EQ(nodes.slip, 5);
  // mu = 0 is frictionless (no tangential fields are written): every active
  // node's multiplier lies along its normal, nothing resists the slip. (The
  // total x force is not zero: the normals tilt by ~5e-3 at the deformed
  // punch ends.)
  const auto& state = lastNodal(free.results, "contact_state");
  const auto &lx = lastNodal(free.results, "contact_multiplier_x"), &ly = lastNodal(free.results, "contact_multiplier_y");
  const auto &nx = lastNodal(free.results, "contact_normal_x"), &ny = lastNodal(free.results, "contact_normal_y");
  int active = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    ++active;
    const double tangential = -lx[i] * ny[i] + ly[i] * nx[i], size = std::hypot(lx[i], ly[i]);
    EXPECT_LT(std::abs(tangential), 1e-10 * size) << "node " << i + 1;
  }
  EXPECT_EQ(active, 8);
  // ... and the run is the frictionless one (the deck without a friction law).
  for (const char* name : {"reaction_top_x", "reaction_top_y", "contact_force_punch_x"})
    EXPECT_NEAR(lastGlobal(free.results, name), lastGlobal(frictionless.results, name), 1e-9 * kPressure) << name;
}

// Penalty friction (no multipliers, traction from a return map with the
// converged traction as history): the imposed slip carries mu p per node,
// and the sliding punch reaches gross slip at mu P.
TEST(FrictionPenalty, ImposedSlipAndSlidingPunch) {
  const std::string penalty = "<Parameter name=\"Formulation\" type=\"string\" value=\"Penalty\"/>" + kCoulombLaw;
  ShippedDeck patch("friction_patch_2d", "contact_patch2d.e");
  patch.replace(kCoulombLaw, penalty);
  auto slip = runDeckText("friction_penalty_patch", patch.text);
  ShippedDeck punch("friction_punch", "friction_punch.e");
  // The punch deck names its formulation (ALM): replaced, not given twice
  // (a parameter given twice is a deck error; Teuchos kept one of the two).
  punch.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>",
                "<Parameter name=\"Formulation\" type=\"string\" value=\"Penalty\"/>");
  auto sliding = runDeckText("friction_penalty_punch", punch.text);
  expectGrossSlipAtMu(sliding, "Penalty");
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(slip.results, [](double p) { return -kMu * p; }, 1e-6 * kPressure);
  EXPECT_EQ(nodes.slip, 8);
  EXPECT_EQ(lastGlobal(sliding.results, "contact_stick_nodes_punch"), 0.0);
}

// MPC (Formulation = MPC: ties, states from reactions and gaps, the Coulomb
// force on slipping nodes): the stick patch exact, the imposed slip carrying
// mu p per node, the sliding punch reaching gross slip at mu P, and the
// frictionless Hertz contact equal to the ALM one (same conditions at a
// solution, decided differently on the way).
TEST(FrictionMpc, StickSlipAndSlidingPunch) {
  const std::string mpc = "<Parameter name=\"Formulation\" type=\"string\" value=\"MPC\"/>" + kCoulombLaw;
  std::string stickText = stickPatchDeck();
  stickText.replace(stickText.find(kCoulombLaw), kCoulombLaw.size(), mpc);
  auto stick = runDeckText("friction_mpc_stick", stickText);
  EXPECT_LT(homogeneousFieldError(*stick.simulation, kMu * kPressure / 2, 0.0), 1e-9 * 0.01);
  ShippedDeck patch("friction_patch_2d", "contact_patch2d.e");
  patch.replace(kCoulombLaw, mpc);
  auto slip = runDeckText("friction_mpc_patch", patch.text);
  ShippedDeck punch("friction_punch", "friction_punch.e");
  punch.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>",
                "<Parameter name=\"Formulation\" type=\"string\" value=\"MPC\"/>");
  auto sliding = runDeckText("friction_mpc_punch", punch.text);
  expectGrossSlipAtMu(sliding, "MPC");
  if (worldComm()->getRank() != 0) return;
  const double tau = kMu * kPressure / 2, stretch = 1 + kEpsXX;
  const auto stuck = checkTractions(stick.results, [&](double) { return -tau / stretch; }, 1e-8 * kPressure);
  EXPECT_EQ(stuck.stick, 8);
  const auto slipping = checkTractions(slip.results, [](double p) { return -kMu * p; }, 1e-8 * kPressure);
  EXPECT_EQ(slipping.slip, 8);
  EXPECT_EQ(lastGlobal(sliding.results, "contact_stick_nodes_punch"), 0.0);
}

// Slip Reset Frequency < 0: never reset, a slipping node keeps the direction
// of its slip in the last converged step. The imposed slip still carries
// mu p per node and the punch reaches gross slip at mu P.
TEST(FrictionPatch, SlipDirectionFromTheSlip) {
  const std::string never = kCoulombLaw + "<Parameter name=\"Slip Reset Frequency\" type=\"int\" value=\"-1\"/>";
  ShippedDeck patch("friction_patch_2d", "contact_patch2d.e"), punch("friction_punch", "friction_punch.e");
  patch.replace(kCoulombLaw, never);
  punch.replace(kCoulombLaw, never);
  // This variant sits near the 4-per-increment bound: 93 Newton iterations
  // with exact linear solves at np = 1, 2, 3; with the adaptive Krylov
  // tolerance its stick/slip path varies from 90 to 97 with the rank count.
  // The bound is checked on exact solves here and on the adaptive default by
  // FrictionPunch and the penalty and MPC punches.
  punch.fixLinearTolerance();
  auto slip = runDeckText("friction_slip_direction_patch", patch.text);
  auto sliding = runDeckText("friction_slip_direction_punch", punch.text);
  expectGrossSlipAtMu(sliding, "Slip Reset Frequency -1");
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(slip.results, [](double p) { return -kMu * p; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.slip, 8);
}

TEST(FrictionMpc, FrictionlessHertzEqualsAlm) {
  ShippedDeck deck("hertz2d", "hertz2d.e");
  deck.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>",
               "<Parameter name=\"Formulation\" type=\"string\" value=\"MPC\"/>");
  auto alm = runDeck("hertz2d");
  auto mpc = runDeckText("frictionless_mpc_hertz", deck.text);
  EXPECT_EQ(mpc.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  const double reference = lastGlobal(alm.results, "reaction_top_y");
  EXPECT_NEAR(lastGlobal(mpc.results, "reaction_top_y"), reference, 1e-9 * std::abs(reference));
  EXPECT_EQ(lastGlobal(mpc.results, "contact_active_nodes_cylinder"),
            lastGlobal(alm.results, "contact_active_nodes_cylinder"));
}

// Coulomb's mu per node from a nodal variable of the mesh file: the imposed
// slip carries mu_j p at every node j (0.3 on x < 0.5, 0.15 beyond).
TEST(FrictionPatch, NodalFrictionCoefficientField) {
  const std::string dir = scratchDirectory("friction_field");
  const std::string meshCopy = dir + "/patch_mu.e";
  if (worldComm()->getRank() == 0) {
    const mesh::GlobalMesh m = io::readExodus(shippedMesh("contact_patch2d.e"));
    std::vector<double> mu(static_cast<std::size_t>(m.numNodes()));
    for (long long n = 0; n < m.numNodes(); ++n) mu[n] = m.coordinates[2 * n] < 0.5 ? 0.3 : 0.15;
    io::ExodusWriter writer(meshCopy, m, {"mu"}, {}, "patch with a friction coefficient field");
    writer.writeStep(0.0, {mu}, {});
    writer.close();
  }
  worldComm()->barrier();
  ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
  deck.replace(shippedMesh("contact_patch2d.e"), meshCopy);
  deck.replace("<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>",
               "<Parameter name=\"Friction Coefficient Field\" type=\"string\" value=\"mu\"/>");
  auto run = runDeckText("friction_field_run", deck.text);
  if (worldComm()->getRank() != 0) return;
  const auto& coordinates = run.simulation->mesh().global().coordinates;
  const auto& state = lastNodal(run.results, "contact_state");
  const auto& pressure = lastNodal(run.results, "contact_pressure");
  const auto& tx = lastNodal(run.results, "contact_tangential_traction_x");
  const auto& ty = lastNodal(run.results, "contact_tangential_traction_y");
  int low = 0, high = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    ASSERT_LT(state[i], 1.5) << "node " << i + 1 << " sticks";
    const double mu = coordinates[2 * i] < 0.5 ? 0.3 : 0.15;
    (mu > 0.2 ? high : low)++;
    EXPECT_NEAR(std::hypot(tx[i], ty[i]), mu * pressure[i], 1e-8 * kPressure) << "node " << i + 1;
  }
  EXPECT_GT(low, 2);
  EXPECT_GT(high, 2);
}

// Tresca: the tangential traction of a slipping node is the threshold,
// whatever the pressure.
TEST(FrictionPatch, TrescaSaturatesAtTheThreshold) {
  ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
  const double threshold = 400;
  deck.replace("<Parameter name=\"Friction Law\" type=\"string\" value=\"Coulomb\"/>\n        <Parameter "
               "name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>",
               "<Parameter name=\"Friction Law\" type=\"string\" value=\"Tresca\"/><Parameter name=\"Tresca "
               "Threshold\" type=\"double\" value=\"400\"/>");
  auto run = runDeckText("friction_patch_tresca", deck.text);
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(run.results, [&](double) { return -threshold; }, 1e-8 * threshold);
  EXPECT_EQ(nodes.slip, 8);
  // The pressure is not uniform (see above), the traction is.
  const auto& pressure = lastNodal(run.results, "contact_pressure");
  const auto range = std::minmax_element(pressure.begin(), pressure.end());
  EXPECT_GT(*range.second - *range.first, 1.0);
}

// Cattaneo-Mindlin partial slip (xml/cattaneo_mindlin_2d.xml): at every
// sheared step the stick zone |x| < c of the nodes brackets the analytic
// c = a (1 - Q / (mu P))^(1/2), a the Hertz half-width at the measured P:
// the half-width of the stick nodes' zone is at most c and that of the
// first slip nodes at least c, up to a tenth of the node spacing.
TEST(FrictionCattaneoMindlin, StickZoneFollowsTheory) {
  auto run = runDeck("cattaneo_mindlin_2d");
  EXPECT_EQ(run.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  const auto& r = run.results;
  const auto& coordinates = run.simulation->mesh().global().coordinates;
  const double Es = kE / (2 * (1 - kNu * kNu)), R = 10, pi = std::acos(-1.0);
  int measured = 0;
  for (std::size_t s = 5; s < r.global.size(); ++s) {
    const double Q = std::abs(r.global[s][r.globalIndex("reaction_top_x")]);
    const double P = std::abs(r.global[s][r.globalIndex("reaction_top_y")]);
    const double a = std::sqrt(4 * P * R / (pi * Es));
    const double c = a * std::sqrt(1 - Q / (kMu * P));
    const auto& state = r.nodal[s][r.nodalIndex("contact_state")];
    // The stick zone [left, right] of the nodes and the nearest slip nodes
    // outside it on each side: the half-widths (right - left) / 2 of the two
    // bracket c.
    double left = 1e30, right = -1e30;
    for (std::size_t i = 0; i < state.size(); ++i)
      if (state[i] > 1.5) left = std::min(left, coordinates[2 * i]), right = std::max(right, coordinates[2 * i]);
    double slipLeft = -1e30, slipRight = 1e30;
    for (std::size_t i = 0; i < state.size(); ++i) {
      if (state[i] < 0.5 || state[i] > 1.5) continue;
      const double x = coordinates[2 * i];
      if (x > right) slipRight = std::min(slipRight, x);
      if (x < left) slipLeft = std::max(slipLeft, x);
    }
    ASSERT_LT(left, right) << "step " << s + 1 << ": no stick zone";
    ASSERT_LT(slipRight, 1e29) << "step " << s + 1 << ": no slip on the right";
    ASSERT_GT(slipLeft, -1e29) << "step " << s + 1 << ": no slip on the left";
    const double inner = (right - left) / 2, outer = (slipRight - slipLeft) / 2;
    // Node spacing in the contact zone: the largest gap between active nodes.
    std::vector<double> active;
    for (std::size_t i = 0; i < state.size(); ++i)
      if (state[i] > 0.5) active.push_back(coordinates[2 * i]);
    std::sort(active.begin(), active.end());
    double spacing = 0;
    for (std::size_t k = 1; k < active.size(); ++k) spacing = std::max(spacing, active[k] - active[k - 1]);
    EXPECT_GT(Q / (kMu * P), 0.1 * static_cast<double>(s - 4)) << "step " << s + 1;  // the load rises
    EXPECT_LT(Q / (kMu * P), 1.0) << "step " << s + 1;
    // A tight bracket: at most two node spacings wide (the nodal stick zone
    // may sit off-centre by one node; the spacing is a / 13 to a / 8).
    EXPECT_LE(outer - inner, 2 * spacing) << "step " << s + 1;
    EXPECT_LE(inner, c + 0.1 * spacing) << "step " << s + 1 << ": Q/muP " << Q / (kMu * P) << " c " << c;
    EXPECT_GE(outer, c - 0.1 * spacing) << "step " << s + 1 << ": Q/muP " << Q / (kMu * P) << " c " << c;
    ++measured;
  }
  EXPECT_EQ(measured, 5);
}

/// Pressed (t = 5) against turned by 30 degrees (last step), per active node.
struct RotationChange {
  bool sameStates = false;
  double pressure = 0, traction = 0, slip = 0, force = 0, peakPressure = 0;
};
RotationChange changeUnderRotation(const ContactRun& run) {
  const auto& r = run.results;
  std::size_t pressed = 0;
  for (std::size_t s = 0; s < r.times.size(); ++s)
    if (std::abs(r.times[s] - 5.0) < 1e-12) pressed = s;
  const std::size_t turned = r.times.size() - 1;
  auto nodal = [&r](std::size_t s, const char* name) { return r.nodal[s][r.nodalIndex(name)]; };
  RotationChange c;
  const auto state0 = nodal(pressed, "contact_state"), state1 = nodal(turned, "contact_state");
  const auto p0 = nodal(pressed, "contact_pressure"), p1 = nodal(turned, "contact_pressure");
  const auto tx0 = nodal(pressed, "contact_tangential_traction_x"), ty0 = nodal(pressed, "contact_tangential_traction_y");
  const auto tx1 = nodal(turned, "contact_tangential_traction_x"), ty1 = nodal(turned, "contact_tangential_traction_y");
  const auto sx0 = nodal(pressed, "contact_slip_x"), sy0 = nodal(pressed, "contact_slip_y");
  const auto sx1 = nodal(turned, "contact_slip_x"), sy1 = nodal(turned, "contact_slip_y");
  // The same states, except that a node exactly on the cone (|t| = mu p: it
  // slipped while pressed and restarts each step as stick) may carry either
  // label: stick and slip coincide there.
  c.sameStates = true;
  for (std::size_t i = 0; i < state0.size(); ++i) {
    if (state0[i] == state1[i]) continue;
    const bool onCone = std::abs(std::hypot(tx1[i], ty1[i]) - kMu * p1[i]) <= 1e-6 * kMu * p1[i];
    c.sameStates = c.sameStates && state0[i] > 0.5 && state1[i] > 0.5 && onCone;
  }
  for (std::size_t i = 0; i < state0.size(); ++i) {
    if (state0[i] < 0.5) continue;
    c.peakPressure = std::max(c.peakPressure, p0[i]);
    c.pressure = std::max(c.pressure, std::abs(p1[i] - p0[i]));
    c.traction = std::max(c.traction, std::abs(std::hypot(tx1[i], ty1[i]) - std::hypot(tx0[i], ty0[i])));
    c.slip = std::max(c.slip, std::hypot(sx1[i] - sx0[i], sy1[i] - sy0[i]));
  }
  // The contact force turns with the bodies.
  const double angle = std::acos(-1.0) / 6;
  const double fx = r.global[pressed][r.globalIndex("contact_force_cylinder_x")];
  const double fy = r.global[pressed][r.globalIndex("contact_force_cylinder_y")];
  const double gx = r.global[turned][r.globalIndex("contact_force_cylinder_x")];
  const double gy = r.global[turned][r.globalIndex("contact_force_cylinder_y")];
  c.force = std::hypot(gx - (std::cos(angle) * fx - std::sin(angle) * fy), gy - (std::sin(angle) * fx + std::cos(angle) * fy)) /
            std::hypot(fx, fy);
  return c;
}

// Frame indifference (xml/frame_indifference_2d.xml): both bodies, pressed
// and sticking, turn rigidly by 30 degrees. With the objective slip (4.69b)
// nothing changes but the orientation (measured 1e-10 p0, 2e-12 mm); the
// non-objective slip (4.65a) fails the test (measured 3e-5 p0 and 8e-6 mm).
TEST(FrictionFrameIndifference, ObjectiveSlipKeepsTheContactUnderRigidRotation) {
  auto objective = runDeck("frame_indifference_2d");
  ShippedDeck deck("frame_indifference_2d", "hertz2d.e");
  deck.replace("<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>",
               "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/><Parameter name=\"Slip "
               "Measure\" type=\"string\" value=\"Non-Objective\"/>");
  auto nonObjective = runDeckText("frame_indifference_non_objective", deck.text);
  // An operator threshold above every relative change of D and M (a rigid
  // rotation changes none) falls back to the non-objective measure.
  ShippedDeck threshold("frame_indifference_2d", "hertz2d.e");
  threshold.replace("<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>",
                    "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/><Parameter name=\"Operator "
                    "Threshold\" type=\"double\" value=\"1e-3\"/>");
  auto switched = runDeckText("frame_indifference_operator_threshold", threshold.text);
  if (worldComm()->getRank() != 0) return;
  const auto o = changeUnderRotation(objective), n = changeUnderRotation(nonObjective);
  const auto t = changeUnderRotation(switched);
  std::printf("operator threshold 1e-3: traction %.2e, slip %.2e\n", t.traction, t.slip);
  EXPECT_GT(t.slip, 1e-7);
  std::printf("objective: pressure %.2e, traction %.2e (of p0 %.4g), slip %.2e, force %.2e\n", o.pressure, o.traction,
              o.peakPressure, o.slip, o.force);
  std::printf("non-objective: pressure %.2e, traction %.2e, slip %.2e, force %.2e\n", n.pressure, n.traction, n.slip,
              n.force);
  EXPECT_TRUE(o.sameStates);
  EXPECT_LT(o.pressure, 1e-8 * o.peakPressure);
  EXPECT_LT(o.traction, 1e-8 * o.peakPressure);
  EXPECT_LT(o.slip, 1e-10);
  EXPECT_LT(o.force, 1e-8);
  // The non-objective measure sees the rotation as slip.
  EXPECT_GT(n.traction, 1e-6 * n.peakPressure);
  EXPECT_GT(n.slip, 1e-7);
}

// The objective slip from the first load step (issue 16): the operators of
// the initial configuration are the D^t, M^t of step 1. The first two steps
// of xml/frame_indifference_2d's press, once with both bodies turned
// rigidly by 5 degrees while they are pressed and once by 0: the contact is
// the same up to the rotation, node by node. Measured: 4e-10 p0 in pressure
// and traction; with the non-objective measure in step 1 (the rule before)
// the traction of the turned run was off by 58 of 154 MPa.
TEST(FrictionFrameIndifference, ObjectiveSlipFromTheFirstStep) {
  const auto pressing = [](const std::string& name, const char* angle) {
    ShippedDeck deck("frame_indifference_2d", "hertz2d.e");
    deck.replace("<Parameter name=\"Number of Steps\" type=\"int\" value=\"13\"/><Parameter name=\"Final Time\" "
                 "type=\"double\" value=\"13\"/>",
                 "<Parameter name=\"Number of Steps\" type=\"int\" value=\"2\"/><Parameter name=\"Final Time\" "
                 "type=\"double\" value=\"2\"/>");
    deck.replace("<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 5, 13}\"/><Parameter "
                 "name=\"Values\" type=\"Array(double)\" value=\"{0, 0, 1}\"/>",
                 "<Parameter name=\"Times\" type=\"Array(double)\" value=\"{0, 2, 13}\"/><Parameter "
                 "name=\"Values\" type=\"Array(double)\" value=\"{0, 1, 1}\"/>");
    for (int k = 0; k < 2; ++k)
      deck.replace("<Parameter name=\"Rotation Angle\" type=\"double\" value=\"0.5235987755982988\"/>",
                   std::string("<Parameter name=\"Rotation Angle\" type=\"double\" value=\"") + angle + "\"/>");
    return runDeckText(name, deck.text);
  };
  auto still = pressing("first_step_still", "0");
  auto turned = pressing("first_step_turned", "0.08726646259971647");
  EXPECT_EQ(still.summary.cutbacks, 0);
  EXPECT_EQ(turned.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  const auto& a = still.results;
  const auto& b = turned.results;
  ASSERT_EQ(a.times.size(), b.times.size());
  for (std::size_t s = 0; s < a.times.size(); ++s) {
    auto nodal = [s](const auto& r, const char* name) { return r.nodal[s][r.nodalIndex(name)]; };
    const auto pa = nodal(a, "contact_pressure"), pb = nodal(b, "contact_pressure");
    const auto txa = nodal(a, "contact_tangential_traction_x"), tya = nodal(a, "contact_tangential_traction_y");
    const auto txb = nodal(b, "contact_tangential_traction_x"), tyb = nodal(b, "contact_tangential_traction_y");
    double peak = 0, pressure = 0, traction = 0, tractionPeak = 0;
    for (std::size_t i = 0; i < pa.size(); ++i) {
      peak = std::max(peak, pa[i]);
      tractionPeak = std::max(tractionPeak, std::hypot(txa[i], tya[i]));
      pressure = std::max(pressure, std::abs(pa[i] - pb[i]));
      traction = std::max(traction, std::abs(std::hypot(txa[i], tya[i]) - std::hypot(txb[i], tyb[i])));
    }
    std::printf("step %zu: p0 %.4g, peak traction %.4g, turned against still: pressure %.2e, traction %.2e\n", s,
                peak, tractionPeak, pressure, traction);
    EXPECT_GT(tractionPeak, 0.02 * peak) << "step " << s;  // friction at work (measured 0.04 to 0.07)
    EXPECT_LT(pressure, 1e-8 * peak) << "step " << s;
    EXPECT_LT(traction, 1e-8 * peak) << "step " << s;
  }
}

// `Rotation Angle` 0 given in a deck is a rotation by 0: the node set
// keeps the displacement the earlier conditions prescribe (here the press
// of `top`). Before, an angle of 0 made the condition a plain one with
// Value 0 on all components: `top` fixed, the press lost, and the nearly
// unloaded step never converged. Two pressing steps of
// xml/frame_indifference_2d, the turn function on from the start.
TEST(DirichletRotation, ZeroAngleKeepsThePrescribedDisplacement) {
  const auto pressing = [](const std::string& name, bool zeroAngle) {
    ShippedDeck deck("frame_indifference_2d", "hertz2d.e");
    deck.replace("<Parameter name=\"Number of Steps\" type=\"int\" value=\"13\"/><Parameter name=\"Final Time\" "
                 "type=\"double\" value=\"13\"/>",
                 "<Parameter name=\"Number of Steps\" type=\"int\" value=\"2\"/><Parameter name=\"Final Time\" "
                 "type=\"double\" value=\"2\"/>");
    if (zeroAngle) {
      deck.replace("value=\"{0, 0, 1}\"", "value=\"{0, 1, 1}\"");  // the turn function
      for (int k = 0; k < 2; ++k)
        deck.replace("<Parameter name=\"Rotation Angle\" type=\"double\" value=\"0.5235987755982988\"/>",
                     "<Parameter name=\"Rotation Angle\" type=\"double\" value=\"0\"/>");
    }
    return runDeckText(name, deck.text);
  };
  auto plain = pressing("rotation_angle_none", false);
  auto zero = pressing("rotation_angle_zero", true);
  EXPECT_EQ(zero.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure"})
    EXPECT_LT(nodalDifference(plain.results, zero.results, field), 1e-12) << field;
}

// Sliding punch (the peer benchmark's friction case, coarse shipped mesh):
// Q/P grows while the contact sticks, slip spreads (the stick zone only
// shrinks, through partial slip), and in gross slip Q = mu P within 1 %.
// (Where: the pressing already makes the punch's x edges slip outward; the
// pull then keeps the leading edge slipping and unloads the trailing one,
// so the stick zone retreats towards the trailing edge — xml/friction_punch.xml.)
// The objective slip does not depend on where the origin of the
// coordinates is. A punch overhanging its base (the 2D patch with the punch
// moved 0.25 to the right: the slave nodes at the base's corner are only
// partly covered by the master) pressed and sheared with Coulomb friction,
// once as meshed and once with the whole mesh moved by (1000, 1000): the
// displacements agree to 1e-9 of the largest (measured: 1e-11). Any use of
// absolute coordinates in the slip, the gap or the search would show here.
// (4.69b) as written differs from the translation-invariant form used by
// (D - D^t - sum_l (M - M^t)) x_j, which the lumped D makes zero up to
// round-off: both forms pass this test.
TEST(FrictionFrameIndifference, ObjectiveSlipIsTranslationInvariant) {
  const std::string dir = scratchDirectory("friction_translation");
  writeMovedPatch2d(dir + "/here.e", {0.25, 0.0}, {0.0, 0.0}, "2D patch, punch overhanging by 0.25");
  writeMovedPatch2d(dir + "/there.e", {0.25, 0.0}, {1000.0, 1000.0}, "the same moved by (1000, 1000)");
  ShippedDeck deck("contact_patch_2d", "contact_patch2d.e");
  deck.replace("<Parameter name=\"Master\" type=\"string\" value=\"master\"/>",
               "<Parameter name=\"Master\" type=\"string\" value=\"master\"/>"
               "<Parameter name=\"Friction Law\" type=\"string\" value=\"Coulomb\"/>"
               "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>");
  deck.replace("<ParameterList name=\"top\">",
               "<ParameterList name=\"top x\"><Parameter name=\"Node Set\" type=\"string\" value=\"top\"/>"
               "<Parameter name=\"Component\" type=\"string\" value=\"x\"/>"
               "<Parameter name=\"Value\" type=\"double\" value=\"0.02\"/></ParameterList>"
               "<ParameterList name=\"top\">");
  // The base held in x at its bottom instead of both bodies at x = 0: the
  // punch is held sideways by friction alone.
  deck.replace("<Parameter name=\"Node Set\" type=\"string\" value=\"left\"/>",
               "<Parameter name=\"Node Set\" type=\"string\" value=\"bottom\"/>");
  std::vector<std::vector<double>> displacement;
  for (const std::string mesh : {"here", "there"}) {
    std::string text = deck.text;
    const auto at = text.find(shippedMesh("contact_patch2d.e"));
    ASSERT_NE(at, std::string::npos);
    text.replace(at, shippedMesh("contact_patch2d.e").size(), dir + "/" + mesh + ".e");
    auto run = runDeckText("friction_translation_" + mesh, text);
    ASSERT_EQ(run.summary.stepTimes.back(), 1.0);
    if (worldComm()->getRank() != 0) continue;
    std::vector<double> u = lastNodal(run.results, "displacement_x");
    const auto& uy = lastNodal(run.results, "displacement_y");
    u.insert(u.end(), uy.begin(), uy.end());
    displacement.push_back(u);
    if (mesh == "here") {  // the punch is in contact over the base and slides
      EXPECT_GE(lastGlobal(run.results, "contact_active_nodes_punch"), 6.0);
      EXPECT_LT(lastGlobal(run.results, "contact_stick_nodes_punch"),
                lastGlobal(run.results, "contact_active_nodes_punch"));
    }
  }
  if (worldComm()->getRank() != 0) return;
  ASSERT_EQ(displacement.size(), 2u);
  ASSERT_EQ(displacement[0].size(), displacement[1].size());
  double largest = 0, difference = 0;
  for (std::size_t i = 0; i < displacement[0].size(); ++i) {
    largest = std::max(largest, std::abs(displacement[0][i]));
    difference = std::max(difference, std::abs(displacement[0][i] - displacement[1][i]));
  }
  std::printf("translation: max |u| %.6e, max difference %.3e\n", largest, difference);
  EXPECT_LT(difference, 1e-9 * largest);
}

TEST(FrictionPunch, StickPartialSlipThenGrossSlipAtMuP) {
  auto run = runDeck("friction_punch");
  EXPECT_EQ(run.summary.cutbacks, 0);
  EXPECT_EQ(run.summary.steps, 24);
  int newton = 0;
  for (int iterations : run.summary.stepNewtonIterations) newton += iterations;
  EXPECT_LE(newton, 4 * 24);  // at most 4 Newton iterations per increment on average
  if (worldComm()->getRank() != 0) return;
  const auto& r = run.results;
  const int steps = static_cast<int>(r.global.size());
  ASSERT_GE(steps, 24);
  double previousRatio = 0;
  int previousStick = 1 << 30;
  bool partialSeen = false;
  for (int s = steps - 24; s < steps; ++s) {
    const auto& g = r.global[s];
    const double Q = std::abs(g[r.globalIndex("reaction_top_x")]), P = -g[r.globalIndex("reaction_top_z")];
    const int stick = static_cast<int>(g[r.globalIndex("contact_stick_nodes_punch")]);
    const int active = static_cast<int>(g[r.globalIndex("contact_active_nodes_punch")]);
    if (s - (steps - 24) < 4) {  // pressing: no tangential load
      EXPECT_LT(Q, 1e-6 * P) << "step " << s + 1;
      continue;
    }
    EXPECT_GE(Q / P, previousRatio - 1e-9) << "step " << s + 1;
    EXPECT_LE(Q / P, kMu * (1 + 1e-6)) << "step " << s + 1;
    EXPECT_LE(stick, previousStick) << "step " << s + 1;
    previousRatio = Q / P;
    previousStick = stick;
    if (stick > 0 && stick < active) partialSeen = true;
  }
  EXPECT_TRUE(partialSeen);
  EXPECT_NEAR(previousRatio, kMu, 0.01 * kMu);
  EXPECT_EQ(previousStick, 0);
}

}  // namespace coulomb::test
