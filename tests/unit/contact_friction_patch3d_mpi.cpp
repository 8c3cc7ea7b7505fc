// Frictional patch tests in 3D (xml/friction_patch_3d.xml): stick and
// imposed slip on the non-matching and the matching HEX8 patch meshes. Every
// run happens at np = 1, 2, 3 (ctest MpiTests.np*).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "FrictionDeckSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

// 3D (xml/friction_patch_3d.xml) with the shear halved: tau = mu p / 2 sticks.
std::string stickPatch3dDeck(const std::string& mesh) {
  ShippedDeck deck("friction_patch_3d", "contact_patch3d.e");
  deck.replace("<Parameter name=\"Value\" type=\"double\" value=\"0.002\"/>", "");
  deck.replace("0.0078000000000000005", "0.0039000000000000003");
  deck.replace("-630.0}", "-315.0}");
  deck.replace("630.0}", "315.0}");
  deck.replace(shippedMesh("contact_patch3d.e"), shippedMesh(mesh));
  // Newton to 1e-12 of the force scale, so that the exactness bounds below
  // (1e-8 of the displacement) measure the discretisation, not where a
  // Newton run at the default 1e-8 happened to stop.
  const auto end = deck.text.rfind("</ParameterList>");
  deck.text.insert(end, "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" "
                        "value=\"1e-12\"/></ParameterList>\n");
  return deck.text;
}

constexpr double kPatch3dShear = kMu * kE * 0.01 / 2;

/// Largest nodal deviation from the homogeneous stick state of the 3D patch.
double stickPatch3dError(const solver::Simulation& simulation) {
  const double gamma = kPatch3dShear / kShearModulus;
  double error = 0;
  forOwnedNodes(simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[0] - (0.003 * X[0] + gamma * X[2])), std::abs(u[1] - 0.003 * X[1]),
                      std::abs(u[2] + 0.01 * X[2])});
  });
  return globalMax(error);
}

// 3D: stick with tau = mu p / 2 is exact across the non-matching HEX8
// interface; the imposed slip along x carries mu p against the slip at every node.
TEST(FrictionPatch, ThreeDimensionalStickIsExactAndSlipCarriesMuP) {
  const double p = kE * 0.01, tau = kPatch3dShear, s = 0.002;
  auto stick = runDeckText("friction_patch_3d_stick", stickPatch3dDeck("contact_patch3d.e"));
  // Newton at 1e-12 (stickPatch3dDeck): the bound is far above the solver's
  // error; a wrong contact state (a node slipping or open) leaves errors of
  // 1e-4 (seen while developing).
  EXPECT_LT(stickPatch3dError(*stick.simulation), 1e-8 * 0.01);
  auto slip = runDeck("friction_patch_3d");
  if (worldComm()->getRank() != 0) return;
  const double area = (1 + 0.003) * (1 + 0.003);  // tractions per current area
  const auto stuck = checkTractions(stick.results, [&](double) { return -tau / area; }, 1e-8 * p, 3);
  EXPECT_EQ(stuck.stick, 25);
  EXPECT_NEAR(lastGlobal(stick.results, "contact_force_punch_x"), -tau, 1e-8 * p);
  const auto slipping = checkTractions(slip.results, [](double pressure) { return -kMu * pressure; }, 1e-8 * p, 3);
  EXPECT_EQ(slipping.slip, 25);
  const auto& slipX = lastNodal(slip.results, "contact_slip_x");
  const auto& state = lastNodal(slip.results, "contact_state");
  for (std::size_t i = 0; i < state.size(); ++i)
    if (state[i] > 0.5) EXPECT_GT(slipX[i], 0.5 * s) << "node " << i + 1;
}

// The same stick with Load Stepping/Boundary Increment = Tangent: the top's
// prescribed displacement and shear reach the contact through the first
// Newton step's linear solve (fem/DirichletConstraints.hpp) instead of the
// imposed values; the answer is the same homogeneous state.
TEST(FrictionPatch, ThreeDimensionalStickIsExactWithTheBoundaryIncrementThroughTheTangent) {
  std::string text = stickPatch3dDeck("contact_patch3d.e");
  const std::string stepping = "<ParameterList name=\"Load Stepping\">";
  const auto at = text.find(stepping);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + stepping.size(), "<Parameter name=\"Boundary Increment\" type=\"string\" value=\"Tangent\"/>");
  auto stick = runDeckText("friction_patch_3d_stick_tangent", text);
  EXPECT_LT(stickPatch3dError(*stick.simulation), 1e-8 * 0.01);
  EXPECT_EQ(stick.simulation->settings().boundaryThroughTangent, true);
}

// The same 3D stick on matching meshes (3 x 3 punch faces on 3 x 3 base
// faces): every slave edge lies on a master edge, the clipping's degenerate
// case. Its second step starts at equilibrium (the response is linear); with
// a clipping tolerance inside the iterates' scatter (1e-10 of the face) the
// objective slip's derivative flipped between Newton iterates and the step
// cycled at 1e-9 of the contact force until it was cut back and failed.
TEST(FrictionPatch, ThreeDimensionalStickIsExactOnMatchingMeshes) {
  const double p = kE * 0.01, tau = kPatch3dShear;
  auto stick = runDeckText("friction_patch_3d_stick_matching", stickPatch3dDeck("contact_patch3d_matching.e"));
  EXPECT_EQ(stick.summary.cutbacks, 0);
  for (int iterations : stick.summary.stepNewtonIterations) EXPECT_LE(iterations, 6);
  EXPECT_LT(stickPatch3dError(*stick.simulation), 1e-8 * 0.01);
  if (worldComm()->getRank() != 0) return;
  const double area = (1 + 0.003) * (1 + 0.003);
  const auto stuck = checkTractions(stick.results, [&](double) { return -tau / area; }, 1e-8 * p, 3);
  EXPECT_EQ(stuck.stick, 16);
  EXPECT_NEAR(lastGlobal(stick.results, "contact_force_punch_x"), -tau, 1e-8 * p);
}

// The imposed slip of xml/friction_patch_3d.xml on the matching mesh: mu p
// against the slip at every node, as on the non-matching one.
TEST(FrictionPatch, ThreeDimensionalSlipOnMatchingMeshesCarriesMuP) {
  ShippedDeck deck("friction_patch_3d", "contact_patch3d.e");
  deck.replace(shippedMesh("contact_patch3d.e"), shippedMesh("contact_patch3d_matching.e"));
  auto slip = runDeckText("friction_patch_3d_slip_matching", deck.text);
  EXPECT_EQ(slip.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(slip.results, [](double pressure) { return -kMu * pressure; }, 1e-8 * kE * 0.01, 3);
  EXPECT_EQ(nodes.stick, 0);
  EXPECT_EQ(nodes.slip, 16);
}

// The same on the HEX27, HEX20 and TET10 patch meshes (QUAD9 contact faces
// with the biquadratic dual basis, QUAD8 and TRI6 faces with the
// transformed one and its transformed slip, SlaveTransform.hpp; issue 18,
// item 2): stick exact at every slave node (81, 65, 81: corners, mid-sides,
// centres), and the imposed slip carrying mu p at every one.
TEST(FrictionPatch, ThreeDimensionalQuadraticStickIsExactAndSlipCarriesMuP) {
  for (const auto& [cells, slaveNodes] :
       {std::pair<std::string, int>{"hex27", 81}, {"hex20", 65}, {"tet10", 81}}) {
    SCOPED_TRACE(cells);
    const double p = kE * 0.01, tau = kPatch3dShear;
    const std::string mesh = "contact_patch3d_" + cells + ".e";
    auto stick = runDeckText("friction_patch_3d_stick_" + cells, stickPatch3dDeck(mesh));
    EXPECT_LT(stickPatch3dError(*stick.simulation), 1e-8 * 0.01);
    ShippedDeck slipDeck("friction_patch_3d", "contact_patch3d.e");
    slipDeck.replace(shippedMesh("contact_patch3d.e"), shippedMesh(mesh));
    auto slip = runDeckText("friction_patch_3d_slip_" + cells, slipDeck.text);
    if (worldComm()->getRank() != 0) continue;
    const double area = (1 + 0.003) * (1 + 0.003);  // tractions per current area
    const auto stuck = checkTractions(stick.results, [&](double) { return -tau / area; }, 1e-8 * p, 3);
    EXPECT_EQ(stuck.stick, slaveNodes);
    EXPECT_NEAR(lastGlobal(stick.results, "contact_force_punch_x"), -tau, 1e-8 * p);
    const auto slipping = checkTractions(slip.results, [](double pressure) { return -kMu * pressure; }, 1e-8 * p, 3);
    EXPECT_EQ(slipping.slip, slaveNodes);
  }
}

}  // namespace
}  // namespace coulomb::test
