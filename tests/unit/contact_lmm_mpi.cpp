// Formulation = LMM (Lagrange multipliers as unknowns with the NCP
// functions of seed 4.79, formulation/LagrangeNcp.cpp) against the
// condensed ALM on the same decks: both solve the same discrete contact
// problem (no penalty in either converged answer), so reactions, pressures,
// tangential tractions and stick/slip states agree to solver tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "FrictionDeckSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

const std::string kLmm = "<Parameter name=\"Formulation\" type=\"string\" value=\"LMM\"/>";

/// The largest difference of nodal `field` over every step, relative to its largest magnitude in `a`.
double fieldDifference(const io::ExodusResults& a, const io::ExodusResults& b, const std::string& field) {
  EXPECT_EQ(a.nodal.size(), b.nodal.size()) << field;
  double scale = 0, difference = 0;
  for (std::size_t s = 0; s < std::min(a.nodal.size(), b.nodal.size()); ++s) {
    const auto &x = a.nodal[s][a.nodalIndex(field)], &y = b.nodal[s][b.nodalIndex(field)];
    for (std::size_t i = 0; i < x.size(); ++i) {
      scale = std::max(scale, std::abs(x[i]));
      difference = std::max(difference, std::abs(x[i] - y[i]));
    }
  }
  return scale > 0 ? difference / scale : difference;
}

/// Every converged step of `a` and `b` has the same contact states.
void expectSameStates(const io::ExodusResults& a, const io::ExodusResults& b) {
  for (std::size_t s = 0; s < std::min(a.nodal.size(), b.nodal.size()); ++s)
    EXPECT_EQ(a.nodal[s][a.nodalIndex("contact_state")], b.nodal[s][b.nodalIndex("contact_state")]) << "step " << s;
}

TEST(LagrangeNcp, FrictionlessHertzEqualsAlm) {
  ShippedDeck lmm("hertz2d", "hertz2d.e");
  lmm.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>", kLmm);
  auto alm = runDeck("hertz2d");
  auto ncp = runDeckText("lmm_hertz2d", lmm.text);
  if (worldComm()->getRank() != 0) return;
  const double reference = lastGlobal(alm.results, "reaction_top_y");
  EXPECT_NEAR(lastGlobal(ncp.results, "reaction_top_y"), reference, 1e-6 * std::abs(reference));
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "contact_pressure"), 1e-5);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "displacement_y"), 1e-6);
  expectSameStates(alm.results, ncp.results);
}

// Imposed slip on the 2D patch: every slave node slides with mu p (as the ALM).
TEST(LagrangeNcp, ImposedSlipCarriesMuTimesPressure) {
  ShippedDeck lmm("friction_patch_2d", "contact_patch2d.e");
  lmm.replace(kCoulombLaw, kCoulombLaw + kLmm);
  auto ncp = runDeckText("lmm_friction_patch_2d", lmm.text);
  auto alm = runDeck("friction_patch_2d");
  if (worldComm()->getRank() != 0) return;
  const auto nodes = checkTractions(ncp.results, [](double p) { return -kMu * p; }, 1e-8 * kPressure);
  EXPECT_EQ(nodes.slip, 8);
  EXPECT_EQ(nodes.stick, 0);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "displacement_x"), 1e-6);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "contact_tangential_traction_x"), 1e-6);
}

// Cattaneo–Mindlin: a stick core with slipping edges, step by step as the ALM.
TEST(LagrangeNcp, PartialSlipEqualsAlm) {
  ShippedDeck lmm("cattaneo_mindlin_2d", "hertz2d.e");
  lmm.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>", kLmm);
  auto alm = runDeck("cattaneo_mindlin_2d");
  auto ncp = runDeckText("lmm_cattaneo_mindlin_2d", lmm.text);
  if (worldComm()->getRank() != 0) return;
  expectSameStates(alm.results, ncp.results);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "contact_pressure"), 1e-5);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "contact_tangential_traction_x"), 1e-5);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "contact_slip_x"), 1e-5);
  const double q = lastGlobal(alm.results, "contact_force_cylinder_x");
  EXPECT_NEAR(lastGlobal(ncp.results, "contact_force_cylinder_x"), q, 1e-6 * std::abs(q));
}

// 3D: the quarter Hertz model, frictionless.
TEST(LagrangeNcp, FrictionlessHertz3dEqualsAlm) {
  ShippedDeck lmm("hertz3d_quarter", "hertz3d_quarter.e");
  lmm.replace("<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>", kLmm);
  auto alm = runDeck("hertz3d_quarter");
  auto ncp = runDeckText("lmm_hertz3d_quarter", lmm.text);
  if (worldComm()->getRank() != 0) return;
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "contact_pressure"), 1e-5);
  EXPECT_LT(fieldDifference(alm.results, ncp.results, "displacement_z"), 1e-6);
  expectSameStates(alm.results, ncp.results);
}

}  // namespace
}  // namespace coulomb::test
