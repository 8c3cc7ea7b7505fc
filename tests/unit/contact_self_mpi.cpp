// Self-contact (issue 18, item 5): a C-shaped body closing onto itself
// (xml/c_ring_closing_2d.xml), its inner surface one pair with the same
// side set as slave and master. The roles the surface's faces get
// (SelfContactRoles.hpp) make the bottom arm's faces the slave side, so the
// run must be the ordinary pair bottom_arm_top on top_arm_bottom: the same
// displacements and pressures to solver tolerance, frictionless and with
// Coulomb friction; no penetration; only bottom-arm nodes carry pressure.
// np = 1, 2, 3 (ctest MpiTests.np*).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/io/ExodusReader.hpp"

namespace coulomb::test {
namespace {

constexpr double kArmThickness = 0.4;  // c_ring2d.geo: t
constexpr double kFaceSize = 0.1;      // the bottom arm's faces: 1.6 / 16

/// The shipped deck, solved to round-off, with the pair's sides and
/// options replaced.
ContactRun runRing(const std::string& name, const std::string& slave, const std::string& master,
                   const std::string& options) {
  ShippedDeck deck("c_ring_closing_2d", "c_ring2d.e");
  deck.replace("name=\"Slave\" type=\"string\" value=\"inner\"/>",
               "name=\"Slave\" type=\"string\" value=\"" + slave + "\"/>" + options);
  deck.replace("name=\"Master\" type=\"string\" value=\"inner\"", "name=\"Master\" type=\"string\" value=\"" + master + "\"");
  deck.solveToRoundOff();
  return runDeckText(name, deck.text);
}

/// Self-contact against the ordinary pair on rank 0: displacements and
/// pressures over every step, the pair force of the last one; the active
/// nodes all on the bottom arm's top face, none penetrating.
void expectSelfContactEqualsPair(const ContactRun& self, const ContactRun& pair) {
  EXPECT_EQ(self.summary.newtonIterations > 0, true);
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure"})
    EXPECT_LT(nodalDifference(self.results, pair.results, field), 1e-8) << field;
  const double force = lastGlobal(pair.results, "contact_force_inner_y");
  EXPECT_LT(force, -1000.0) << "the arms must be pressed together";
  EXPECT_NEAR(lastGlobal(self.results, "contact_force_inner_y"), force, 1e-8 * std::abs(force));
  const mesh::GlobalMesh mesh = io::readExodus(shippedMesh("c_ring2d.e"));
  const auto& state = lastNodal(self.results, "contact_state");
  const auto& gap = lastNodal(self.results, "contact_gap");
  int active = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    ++active;
    EXPECT_NEAR(mesh.coordinates[2 * i + 1], kArmThickness, 1e-12) << "active node " << i + 1 << " off the bottom arm";
    EXPECT_GT(gap[i], -1e-6 * kFaceSize) << "node " << i + 1 << " penetrates";
  }
  EXPECT_GE(active, 10);
}

TEST(ContactSelf, ClosingRingEqualsThePairOfItsTwoArms) {
  const auto self = runRing("c_ring_self", "inner", "inner", "");
  const auto pair = runRing("c_ring_pair", "bottom_arm_top", "top_arm_bottom", "");
  expectSelfContactEqualsPair(self, pair);
}

TEST(ContactSelf, ClosingRingWithCoulombFrictionEqualsThePairOfItsTwoArms) {
  const std::string friction =
      "<Parameter name=\"Friction Law\" type=\"string\" value=\"Coulomb\"/>"
      "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>";
  const auto self = runRing("c_ring_self_mu", "inner", "inner", friction);
  const auto pair = runRing("c_ring_pair_mu", "bottom_arm_top", "top_arm_bottom", friction);
  expectSelfContactEqualsPair(self, pair);
  const auto frictionless = runRing("c_ring_self_mu0", "inner", "inner", "");
  if (worldComm()->getRank() != 0) return;
  // Friction acts (the displacements differ from the frictionless run's)
  // and the pair's force stays inside the cone.
  EXPECT_GT(nodalDifference(self.results, frictionless.results, "displacement_x"), 1e-4);
  EXPECT_LE(std::abs(lastGlobal(self.results, "contact_force_inner_x")),
            0.3 * std::abs(lastGlobal(self.results, "contact_force_inner_y")));
}

}  // namespace
}  // namespace coulomb::test
