// Self-contact (issue 18, item 5): a C-shaped body closing onto itself
// (xml/c_ring_closing_2d.xml) and a tube crushed until its inner walls
// touch (xml/tube_crush_3d.xml), each inner surface one pair with the same
// side set as slave and master. The roles the surface's faces get
// (SelfContactRoles.hpp) make the bottom arm's (wall's) faces the slave
// side, so each run must be the ordinary pair of those faces on the facing
// ones: the same displacements and pressures to solver tolerance,
// frictionless and with Coulomb friction (mu = 0.3, which must change the
// answer); no penetration; only slave-face nodes carry pressure.
// np = 1, 2, 3 (ctest MpiTests.np*).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/io/ExodusReader.hpp"

namespace coulomb::test {
namespace {

/// A shipped self-contact deck and the ordinary pair it must equal.
struct SelfCase {
  std::string deck, mesh;             ///< the shipped deck and the mesh it names
  std::string runMesh;                 ///< the mesh to run it on
  std::string pairSlave, pairMaster;  ///< the ordinary pair with the self pair's slave side
  int axis;                            ///< the slave face lies at X[axis] = at
  double at, faceSize;                 ///< (reference), faces about faceSize wide
  std::string forceAxis;               ///< the pair force's normal component ("y")
};

/// c_ring_closing_2d: the bottom arm's faces (y = 0.4, 0.1 wide) are slave.
const SelfCase kRing{"c_ring_closing_2d", "c_ring2d.e", "c_ring2d.e", "bottom_arm_top", "top_arm_bottom", 1, 0.4, 0.1, "y"};
/// tube_crush_3d: the bottom wall's inner faces (y = 0.3, at least 0.15 wide) are slave.
const SelfCase kTube{"tube_crush_3d", "tube3d.e", "tube3d.e", "inner_bottom", "inner_top", 1, 0.3, 0.15, "y"};
/// The same on tube3d.geo refined 3 times (every element count x 3, 18k
/// DoFs): with friction, a self pair that only linked the faces of the step
/// start missed the mortar values D^t, M^t of faces that came within reach
/// during the step before contact, and settled into another stick zone
/// than the ordinary pair here (63 against 77 sticking nodes), not on the
/// coarse mesh.
const SelfCase kTubeFine{"tube_crush_3d", "tube3d.e", "tube3d_r3.e", "inner_bottom", "inner_top", 1, 0.3, 0.05, "y"};
/// The tube of HEX20 cells (tube3d.geo at order 2, serendipity): QUAD8
/// faces, whose slave side takes the transformed basis (SlaveTransform.hpp)
/// on the faces of the slave role alone.
const SelfCase kTubeHex20{"tube_crush_3d", "tube3d.e", "tube3d_hex20.e", "inner_bottom", "inner_top", 1, 0.3, 0.15, "y"};
/// The tube of TET10 cells (tube3d.geo with tet = 1 at order 2): TRI6 faces.
const SelfCase kTubeTet10{"tube_crush_3d", "tube3d.e", "tube3d_tet10.e", "inner_bottom", "inner_top", 1, 0.3, 0.15, "y"};

/// The shipped deck, solved to 1e-12 of the force scale, with the pair's
/// sides and options replaced; `newton`: more parameters of the Newton list.
ContactRun runCase(const SelfCase& c, const std::string& name, const std::string& slave, const std::string& master,
                   const std::string& options, const std::string& newton = "") {
  ShippedDeck deck(c.deck, c.mesh);
  if (c.runMesh != c.mesh) deck.replace(shippedMesh(c.mesh), shippedMesh(c.runMesh));
  deck.replace("name=\"Slave\" type=\"string\" value=\"inner\"/>",
               "name=\"Slave\" type=\"string\" value=\"" + slave + "\"/>" + options);
  deck.replace("name=\"Master\" type=\"string\" value=\"inner\"", "name=\"Master\" type=\"string\" value=\"" + master + "\"");
  const auto end = deck.text.rfind("</ParameterList>");
  deck.text.insert(end, "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" "
                        "value=\"1e-12\"/>" + newton + "</ParameterList>\n");
  return runDeckText(name, deck.text);
}

/// Self-contact against the ordinary pair on rank 0: displacements and
/// pressures over every step, the pair force of the last one; the active
/// nodes all on the slave face, none penetrating.
void expectSelfContactEqualsPair(const SelfCase& c, const ContactRun& self, const ContactRun& pair) {
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure"})
    EXPECT_LT(nodalDifference(self.results, pair.results, field), 1e-8) << field;
  const std::string forceName = "contact_force_inner_" + c.forceAxis;
  const double force = lastGlobal(pair.results, forceName);
  EXPECT_GT(std::abs(force), 1000.0) << "the walls must be pressed together";
  EXPECT_NEAR(lastGlobal(self.results, forceName), force, 1e-8 * std::abs(force));
  const mesh::GlobalMesh mesh = io::readExodus(shippedMesh(c.runMesh));
  const auto& state = lastNodal(self.results, "contact_state");
  const auto& gap = lastNodal(self.results, "contact_gap");
  int active = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    ++active;
    EXPECT_NEAR(mesh.coordinates[mesh.dimension * i + c.axis], c.at, 1e-12) << "active node " << i + 1 << " off the slave face";
    EXPECT_GT(gap[i], -1e-6 * c.faceSize) << "node " << i + 1 << " penetrates";
  }
  EXPECT_GE(active, 10);
}

const std::string kFriction =
    "<Parameter name=\"Friction Law\" type=\"string\" value=\"Coulomb\"/>"
    "<Parameter name=\"Friction Coefficient\" type=\"double\" value=\"0.3\"/>";

/// The frictional self pair against the frictional ordinary pair, and
/// against the frictionless self pair: friction must act.
void expectFrictionalSelfContactEqualsPair(const SelfCase& c) {
  const std::string stem = c.runMesh.substr(0, c.runMesh.find('.'));
  const auto self = runCase(c, stem + "_self_mu", "inner", "inner", kFriction);
  const auto pair = runCase(c, stem + "_pair_mu", c.pairSlave, c.pairMaster, kFriction);
  expectSelfContactEqualsPair(c, self, pair);
  const auto frictionless = runCase(c, stem + "_self_mu0", "inner", "inner", "");
  if (worldComm()->getRank() != 0) return;
  EXPECT_GT(nodalDifference(self.results, frictionless.results, "displacement_x"), 1e-4);
}

TEST(ContactSelf, ClosingRingEqualsThePairOfItsTwoArms) {
  expectSelfContactEqualsPair(kRing, runCase(kRing, "c_ring_self", "inner", "inner", ""),
                              runCase(kRing, "c_ring_pair", kRing.pairSlave, kRing.pairMaster, ""));
}

TEST(ContactSelf, ClosingRingWithCoulombFrictionEqualsThePairOfItsTwoArms) {
  expectFrictionalSelfContactEqualsPair(kRing);
}

TEST(ContactSelf, CrushedTubeEqualsThePairOfItsTwoWalls) {
  expectSelfContactEqualsPair(kTube, runCase(kTube, "tube_self", "inner", "inner", ""),
                              runCase(kTube, "tube_pair", kTube.pairSlave, kTube.pairMaster, ""));
}

TEST(ContactSelf, CrushedTubeWithCoulombFrictionEqualsThePairOfItsTwoWalls) {
  expectFrictionalSelfContactEqualsPair(kTube);
  expectFrictionalSelfContactEqualsPair(kTubeFine);
}

/// Self-contact on QUAD8 and TRI6 faces: the transformed slave rows follow the
/// faces' roles, which every search decides anew; a master face's nodes
/// keep physical rows (transforming every face of the surface, both roles,
/// gives another answer than the ordinary pair).
TEST(ContactSelf, CrushedHex20TubeEqualsThePairOfItsTwoWalls) {
  expectSelfContactEqualsPair(kTubeHex20, runCase(kTubeHex20, "tube20_self", "inner", "inner", ""),
                              runCase(kTubeHex20, "tube20_pair", kTubeHex20.pairSlave, kTubeHex20.pairMaster, ""));
  expectFrictionalSelfContactEqualsPair(kTubeHex20);
}

TEST(ContactSelf, CrushedTet10TubeEqualsThePairOfItsTwoWalls) {
  expectSelfContactEqualsPair(kTubeTet10, runCase(kTubeTet10, "tube10_self", "inner", "inner", ""),
                              runCase(kTubeTet10, "tube10_pair", kTubeTet10.pairSlave, kTubeTet10.pairMaster, ""));
  expectFrictionalSelfContactEqualsPair(kTubeTet10);
}

/// Every Krylov solve to 1e-10 (Linear Tolerance = Fixed) on the fine
/// frictional tube: the stick rows had a negative diagonal, which Ifpack2's
/// l1 Gauss-Seidel brought near zero at a rank boundary, and at np 3 GMRES
/// stalled at 1000 iterations in the first contact iterate (the iterate
/// rejected, the step cut back three times, 2119 GMRES iterations in all).
/// Every condensed row now has a positive diagonal (FrictionalNode.hpp).
TEST(ContactSelf, FineFrictionalTubeSolvesEveryKrylovSystemTo1e10) {
  const auto run = runCase(kTubeFine, "tube_r3_fixed_linear", "inner", "inner", kFriction,
                           "<Parameter name=\"Linear Tolerance\" type=\"string\" value=\"Fixed\"/>");
  EXPECT_EQ(run.summary.cutbacks, 0);
  EXPECT_EQ(run.summary.steps, 3);
  EXPECT_LT(run.summary.linearIterations, 1000);
}

/// Interface Distribution: the default (Balanced) spreads the tube's inner
/// faces over the ranks by their candidates, so at np 2 and 3 a face is
/// integrated on another rank than its element's, and a rank integrates
/// faces of walls it holds no element of; the answer must be that of every
/// face on its element's rank, to solver tolerance, with friction.
TEST(ContactSelf, CrushedTubeTheSameWhicheverRankIntegratesAFace) {
  const auto balanced = runCase(kTube, "tube_self_balanced", "inner", "inner", kFriction);
  const auto byElements =
      runCase(kTube, "tube_self_element_owners", "inner", "inner",
              kFriction + "<Parameter name=\"Interface Distribution\" type=\"string\" value=\"Element Owners\"/>");
  if (worldComm()->getRank() != 0) return;
  // Each displacement component against the whole displacement: u_z is zero
  // by symmetry (1e-16), and relative to itself would compare round-off.
  const std::vector<std::string> displacement{"displacement_x", "displacement_y", "displacement_z"};
  for (const std::string& field : displacement)
    EXPECT_LT(nodalDifference(balanced.results, byElements.results, field, displacement), 1e-9) << field;
  EXPECT_LT(nodalDifference(balanced.results, byElements.results, "contact_pressure"), 1e-9);
  const auto& state = lastNodal(balanced.results, "contact_state");
  EXPECT_GE(std::count_if(state.begin(), state.end(), [](double s) { return s > 0.5; }), 10);
}

}  // namespace
}  // namespace coulomb::test
