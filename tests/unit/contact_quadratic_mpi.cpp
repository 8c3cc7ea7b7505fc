// Contact on quadratic faces (issue 18, item 2): the 2D patch tests,
// frictionless and with Coulomb friction (stick and imposed slip), with
// QUAD9 and QUAD8 cells, whose LINE3 contact faces take the standard
// quadratic dual basis (MortarSegmentCurved2D.hpp), and the 3D patch with
// HEX27 and HEX20 cells (QUAD9 and QUAD8 faces, MortarSegmentQuadratic3D.hpp).
// np = 1, 2, 3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "FrictionDeckSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

// xml/contact_patch_2d.xml on its meshes of order 2 (non-matching: 4 and 7
// elements along the interface): the uniform state sigma_yy = -E delta / (1 -
// nu^2), u_y = -delta y, u_x = nu / (1 - nu) delta x, which quadratic cells
// represent exactly, to round-off, with every one of the 15 slave nodes
// (corners and mid-side nodes alike) at the same pressure. Linear
// multipliers on the LINE3 faces (tried first) gave 925 and 3696 at corners
// and mid-side nodes against 2308: the dual basis must be quadratic.
TEST(ContactPatch, QuadraticLine3FacesTransmitUniformPressure) {
  const double E = 210000, nu = 0.3, delta = 0.01;
  const double sigma = E * delta / (1 - nu * nu);
  const double current = sigma / (1 + nu / (1 - nu) * delta);  // per current length
  for (const std::string cells : {"quad9", "quad8"}) {
    SCOPED_TRACE(cells);
    ShippedDeck deck("contact_patch_2d", "contact_patch2d.e");
    deck.replace(shippedMesh("contact_patch2d.e"), shippedMesh("contact_patch2d_" + cells + ".e"));
    deck.fixLinearTolerance();  // every Krylov solve to 1e-10: a check to round-off
    auto run = runDeckText("contact_patch_2d_" + cells, deck.text);
    double error = 0;
    forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
      error = std::max({error, std::abs(u[1] + delta * X[1]), std::abs(u[0] - nu / (1 - nu) * delta * X[0])});
    });
    EXPECT_LT(globalMax(error), 1e-9 * delta);
    EXPECT_LE(run.summary.newtonIterations, 4);
    if (worldComm()->getRank() == 0) expectUniformPressure(run, current, 15, "y", sigma);  // 7 LINE3 faces
  }
}

// The QUAD9 patch as an axisymmetric section (x = r; the LINE3 dual basis
// biorthogonal in the ring measure 2 pi r ds, lineMass): stacked discs in
// uniaxial stress, u_z = -delta z, u_r = nu delta r, to round-off, the slave
// nodes at the same pressure, contact force = reaction = pi R^2 E delta.
// The slave node on the axis has no ring measure with LINE3 faces
// (int N_0 2 pi r ds = 0 for the quadratic corner function when r_0 = 0),
// so it carries no multiplier: 14 of the 15 nodes are in contact.
TEST(ContactPatch, QuadraticLine3FacesAxisymmetric) {
  ShippedDeck deck("contact_patch_2d", "contact_patch2d.e");
  deck.replace(shippedMesh("contact_patch2d.e"), shippedMesh("contact_patch2d_quad9.e"));
  deck.solveToRoundOff();
  const std::string mesh = "<ParameterList name=\"Mesh\">";
  deck.replace(mesh, "<ParameterList name=\"Problem\"><Parameter name=\"Plane Assumption\" type=\"string\" "
                     "value=\"Axisymmetric\"/></ParameterList>\n  " + mesh);
  auto run = runDeckText("contact_patch_axisymmetric_quad9", deck.text);
  const double E = 210000, nu = 0.3, delta = 0.01;
  double error = 0;
  forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[1] + delta * X[1]), std::abs(u[0] - nu * delta * X[0])});
  });
  EXPECT_LT(globalMax(error), 1e-9 * delta);
  if (worldComm()->getRank() != 0) return;
  const double sigma = E * delta, force = M_PI * sigma;
  const double current = sigma / ((1 + nu * delta) * (1 + nu * delta));  // per current area
  expectUniformPressure(run, current, 14, "y", force);
}

// xml/contact_patch_3d.xml on its quadratic meshes (4 x 4 slave faces on
// 3 x 3 master faces): HEX27 (QUAD9 faces, the standard biquadratic dual
// basis) and HEX20 (QUAD8 faces, the transformed basis of SlaveTransform.hpp,
// whose rows combine a node's residual with its edges'), and TET10
// (contact_patch3d_tet.geo: 32 structured TRI6 slave faces on 44
// unstructured master faces, transformed too), all segmented on sub-facets
// (MortarSegmentQuadratic3D.hpp): the uniaxial stress E delta, u_z = -delta
// z, u_x = nu delta x, u_y = nu delta y to round-off, every slave node (81,
// 65, 81: corners, mid-sides and centres) at the same pressure; HEX20
// on matching meshes (3 x 3 on 3 x 3, 40 slave nodes: every slave edge on a
// master edge); and mixed meshes (contact_patch3d.geo's tetbase / tetpunch):
// a HEX27 punch on a TET10 base (QUAD9 slave on TRI6 master), a TET10 punch
// on a HEX27 base (TRI6 on QUAD9), a HEX20 punch on a TET10 base (QUAD8 on TRI6).
TEST(ContactPatch, Quadratic3DFacesTransmitUniformPressure) {
  for (const auto& [cells, slaveNodes] :
       {std::pair<std::string, int>{"hex27", 81}, {"hex20", 65}, {"tet10", 81}, {"matching_hex20", 40},
        {"hex27_on_tet10", 81}, {"tet10_on_hex27", 81}, {"hex20_on_tet10", 65}}) {
    SCOPED_TRACE(cells);
    ShippedDeck deck("contact_patch_3d", "contact_patch3d.e");
    deck.replace(shippedMesh("contact_patch3d.e"), shippedMesh("contact_patch3d_" + cells + ".e"));
    deck.solveToRoundOff();
    auto run = runDeckText("contact_patch_3d_" + cells, deck.text);
    const double E = 210000, nu = 0.3, delta = 0.01;
    double error = 0;
    forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
      error = std::max({error, std::abs(u[2] + delta * X[2]), std::abs(u[0] - nu * delta * X[0]),
                        std::abs(u[1] - nu * delta * X[1])});
    });
    EXPECT_LT(globalMax(error), 1e-9 * delta);
    EXPECT_LE(run.summary.newtonIterations, 4);
    if (worldComm()->getRank() != 0) continue;
    const double sigma = E * delta;
    const double current = sigma / ((1 + nu * delta) * (1 + nu * delta));  // per current area
    expectUniformPressure(run, current, slaveNodes, "z", sigma);
  }
}

// Perfect stick below the cone (contact_friction_decks_mpi.cpp,
// FrictionPatch.StickBelowTheConeIsExact) with QUAD9 cells: the homogeneous
// field to round-off (the deck solves every linear system to 1e-10), all 15
// slave nodes sticking at traction -tau.
TEST(FrictionPatch, QuadraticStickBelowTheConeIsExact) {
  auto run = runDeckText("friction_patch_stick_quad9", stickPatchDeck("contact_patch2d_quad9.e"));
  const double tau = kMu * kPressure / 2;
  EXPECT_LT(homogeneousFieldError(*run.simulation, tau, 0.0), 1e-9 * 0.01);
  if (worldComm()->getRank() != 0) return;
  const double stretch = 1 + kEpsXX;  // tractions are per current length
  const auto nodes = checkTractions(run.results, [&](double) { return -tau / stretch; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.stick, 15);
  EXPECT_EQ(nodes.slip, 0);
  EXPECT_NEAR(lastGlobal(run.results, "contact_force_punch_x"), -tau, 1e-8 * kPressure);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_top_x"), tau, 1e-8 * kPressure);
}

// The imposed slide of xml/friction_patch_2d.xml with QUAD9 cells: every
// one of the 15 slave nodes slips with the traction mu p (the objective
// slip with the quadratic D and M), momentum balance.
TEST(FrictionPatch, QuadraticImposedSlipCarriesMuTimesPressure) {
  ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
  deck.replace(shippedMesh("contact_patch2d.e"), shippedMesh("contact_patch2d_quad9.e"));
  auto run = runDeckText("friction_patch_slip_quad9", deck.text);
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(run.results, [](double p) { return -kMu * p; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.slip, 15);
  EXPECT_EQ(nodes.stick, 0);
  const auto& slip = lastNodal(run.results, "contact_slip_x");
  const auto& state = lastNodal(run.results, "contact_state");
  for (std::size_t i = 0; i < slip.size(); ++i)
    if (state[i] > 0.5) {
      EXPECT_GT(slip[i], 0.5 * kImposedSlip) << "node " << i + 1;
      EXPECT_LT(slip[i], 1.5 * kImposedSlip) << "node " << i + 1;
    }
  const double Q = lastGlobal(run.results, "contact_force_punch_x"), P = lastGlobal(run.results, "contact_force_punch_y");
  EXPECT_NEAR(Q / P, -kMu, 1e-3 * kMu);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_top_x"), -Q, 1e-8 * kPressure);
}

}  // namespace
}  // namespace coulomb::test
