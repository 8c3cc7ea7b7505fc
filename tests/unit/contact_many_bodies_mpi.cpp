// Assemblies of several bodies (issue 18, item 4): a body in two contact
// pairs (three stacked blocks, the middle one master above and slave below,
// or slave on both sides), and a punch on two neighbouring blocks (one slave
// surface on two master bodies, as one pair with a master list or as one
// pair per block, which share a slave node and are joined). Every case has a
// uniform exact state that dual mortar reproduces on non-matching meshes, so
// the displacements, the pressures and the forces are checked to round-off.
// np = 1, 2, 3 (ctest MpiTests.np*).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::test {
namespace {

/// Largest |u - (a X, -delta Y / H)| over every node of every rank.
double linearFieldError(const ContactRun& run, double a, double delta, double H) {
  double error = 0;
  forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[0] - a * X[0]), std::abs(u[1] + delta * X[1] / H)});
  });
  return globalMax(error);
}

/// Every active slave node of the run carries one of the pressures
/// `expected` (to 1e-8 of it; the nearest one). Returns the number of nodes
/// at each, in the order of `expected`.
std::vector<int> countPressures(const ContactRun& run, const std::vector<double>& expected) {
  std::vector<int> count(expected.size(), 0);
  const auto& p = lastNodal(run.results, "contact_pressure");
  const auto& state = lastNodal(run.results, "contact_state");
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < expected.size(); ++k)
      if (std::abs(p[i] - expected[k]) < std::abs(p[i] - expected[nearest])) nearest = k;
    ++count[nearest];
    EXPECT_NEAR(p[i], expected[nearest], 1e-8 * expected[nearest]) << "node " << i + 1;
  }
  return count;
}

// Three blocks of heights 0.5 stacked (H = 1.5), pressed by delta, free to
// expand sideways: the uniaxial stress sigma = E delta / ((1 - nu^2) H)
// everywhere (plane strain), u_x = nu / (1 - nu) delta x / H. Both
// interfaces carry sigma; the middle block is in both pairs, first master
// of the upper pair and slave of the lower, then slave of both.
TEST(ContactManyBodies, StackedBlocksTransmitTheUniformStressThroughBothInterfaces) {
  const double E = 210000, nu = 0.3, delta = 0.01, H = 1.5;
  const double sigma = E * delta / ((1 - nu * nu) * H);
  const double a = nu / (1 - nu) * delta / H;
  const std::vector<std::string> blocks{"bottom_block", "middle_block", "top_block"};
  for (const bool middleSlaveAbove : {false, true}) {
    SCOPED_TRACE(middleSlaveAbove ? "middle block slave of both pairs" : "middle block master above, slave below");
    const AssemblyPair upper = middleSlaveAbove ? AssemblyPair{"upper", "middle_block_top", "top_block_bottom"}
                                                : AssemblyPair{"upper", "top_block_bottom", "middle_block_top"};
    const AssemblyPair lower{"lower", "middle_block_bottom", "bottom_block_top"};
    auto run = runDeckText(middleSlaveAbove ? "stacked_slave_both" : "stacked",
                           assemblyDeck("stacked_blocks2d.e", blocks, {{"left", "x"}}, delta, {upper, lower}));
    EXPECT_LT(linearFieldError(run, a, delta, H), 1e-9 * delta);
    if (worldComm()->getRank() != 0) continue;
    // Per current length: the interfaces stretch by 1 + a.
    // Every slave node: 8 on the middle block's faces (7 elements) of each
    // pair it is the slave of, 6 on the top block's (5).
    EXPECT_EQ(countPressures(run, {sigma / (1 + a)}), std::vector<int>{middleSlaveAbove ? 16 : 14});
    // The force on each pair's slave body: up when the slave is above.
    EXPECT_NEAR(lastGlobal(run.results, "contact_force_upper_y"), middleSlaveAbove ? -sigma : sigma, 1e-8 * sigma);
    EXPECT_NEAR(lastGlobal(run.results, "contact_force_lower_y"), sigma, 1e-8 * sigma);
    EXPECT_NEAR(lastGlobal(run.results, "reaction_top_y"), -sigma, 1e-8 * sigma);
    EXPECT_NEAR(lastGlobal(run.results, "reaction_bottom_y"), sigma, 1e-8 * sigma);
  }
}

// A condensed pair whose slave surface (the middle block's bottom) and
// master surface share a node: here the master list also holds the side set
// `left`, whose faces on the middle block meet its bottom at (0, 0.5). The
// node's rows cannot take both its conditions and master forces: refused
// with one line naming the pair and the node, on every rank.
TEST(ContactManyBodies, NodeOnBothSurfacesOfAPairIsRefused) {
  const AssemblyPair upper{"upper", "top_block_bottom", "middle_block_top"};
  const AssemblyPair lower{"lower", "middle_block_bottom", "bottom_block_top, left"};
  const std::string dir = scratchDirectory("stacked_crosspoint");
  writeOnRoot(dir + "/deck.xml", assemblyDeck("stacked_blocks2d.e", {"bottom_block", "middle_block", "top_block"},
                                               {{"left", "x"}}, 0.01, {upper, lower}));
  try {
    solver::Simulation simulation(dir + "/deck.xml", worldComm(), nullptr, dir + "/out.e");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Contact/Pairs/lower: node"), std::string::npos) << what;
    EXPECT_NE(what.find("both the slave and the master surface"), std::string::npos) << what;
  }
}

// A punch [0,2] x [0.5,1] on two blocks [0,1] and [1,2] x [0,0.5] that touch
// at x = 1, everything held at x = 0 and x = 2, pressed by delta (H = 1):
// uniaxial strain, u_x = 0, u_y = -delta y; sigma_yy = E (1 - nu) delta /
// ((1 + nu)(1 - 2 nu)) under the punch and sigma_xx = nu / (1 - nu) sigma_yy
// between the blocks (the pair `bases`, whose slave corner at (1, 0.5) is a
// master node of the punch's pair). The punch's slave surface lies on two
// master bodies: one pair with a master list, or one pair per block, which
// share the punch's node at x = 1 and are joined into "left+right".
TEST(ContactManyBodies, PunchOnTwoBlocksTransmitsTheUniformStrainState) {
  const double E = 210000, nu = 0.3, delta = 0.01;
  const double sigmaY = E * (1 - nu) * delta / ((1 + nu) * (1 - 2 * nu));
  const double sigmaX = nu / (1 - nu) * sigmaY;
  const std::vector<std::string> blocks{"left_base", "right_base", "punch"};
  const AssemblyPair bases{"bases", "left_base_right", "right_base_left"};
  for (const bool perBlock : {false, true}) {
    SCOPED_TRACE(perBlock ? "one pair per block, joined" : "one pair with a master list");
    const std::vector<AssemblyPair> pairs =
        perBlock ? std::vector<AssemblyPair>{{"left", "punch_bottom_left", "left_base_top"},
                                     {"right", "punch_bottom_right", "right_base_top"},
                                     bases}
                 : std::vector<AssemblyPair>{{"punch", "punch_bottom", "left_base_top, right_base_top"}, bases};
    auto run = runDeckText(perBlock ? "punch_per_block" : "punch_master_list",
                           assemblyDeck("punch_two_blocks2d.e", blocks, {{"left", "x"}, {"right", "x"}}, delta, pairs));
    EXPECT_LT(linearFieldError(run, 0.0, delta, 1.0), 1e-9 * delta);
    if (worldComm()->getRank() != 0) continue;
    const std::string punch = perBlock ? "left+right" : "punch";
    // The blocks' interface shortens by 1 - delta: its pressure per current length.
    // Every slave node: the punch's 8 (7 faces), the left block's side 3 (2).
    EXPECT_EQ(countPressures(run, {sigmaY, sigmaX / (1 - delta)}), (std::vector<int>{8, 3}));
    EXPECT_NEAR(lastGlobal(run.results, "contact_force_" + punch + "_y"), 2 * sigmaY, 1e-8 * sigmaY);
    EXPECT_NEAR(lastGlobal(run.results, "contact_force_bases_x"), -0.5 * sigmaX, 1e-8 * sigmaX);
    EXPECT_NEAR(lastGlobal(run.results, "reaction_top_y"), -2 * sigmaY, 1e-8 * sigmaY);
    EXPECT_NEAR(lastGlobal(run.results, "reaction_bottom_y"), 2 * sigmaY, 1e-8 * sigmaY);
    EXPECT_NEAR(lastGlobal(run.results, "reaction_left_x") + lastGlobal(run.results, "reaction_right_x"), 0.0,
                1e-8 * sigmaY);
  }
}

// The same punch on two blocks in 3D (exodus_meshes/punch_two_blocks3d.geo,
// HEX8, no interface matching): held at x = 0, 2 and y = 0, 1, pressed by
// delta along z (H = 1): u = (0, 0, -delta z), sigma_zz under the punch and
// sigma_xx = nu / (1 - nu) sigma_zz between the blocks. The punch's slave
// surface lies on both blocks' tops (a master list), the left block's top
// edge at x = 1 is slave of `bases` and master of `punch`.
TEST(ContactManyBodies, PunchOnTwoBlocks3DTransmitsTheUniformStrainState) {
  const double E = 210000, nu = 0.3, delta = 0.01;
  const double sigmaZ = E * (1 - nu) * delta / ((1 + nu) * (1 - 2 * nu));
  const double sigmaX = nu / (1 - nu) * sigmaZ;
  const std::vector<AssemblyPair> pairs{{"punch", "punch_bottom", "left_base_top, right_base_top"},
                                        {"bases", "left_base_right", "right_base_left"}};
  auto run = runDeckText("punch_two_blocks_3d",
                         assemblyDeck("punch_two_blocks3d.e", {"left_base", "right_base", "punch"},
                                      {{"left", "x"}, {"right", "x"}, {"front", "y"}, {"back", "y"}}, delta, pairs, "z"));
  double error = 0;
  forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[0]), std::abs(u[1]), std::abs(u[2] + delta * X[2])});
  });
  EXPECT_LT(globalMax(error), 1e-9 * delta);
  if (worldComm()->getRank() != 0) return;
  // Every slave node: the punch's 6 x 4, the left block's side 3 x 3.
  EXPECT_EQ(countPressures(run, {sigmaZ, sigmaX / (1 - delta)}), (std::vector<int>{24, 9}));
  EXPECT_NEAR(lastGlobal(run.results, "contact_force_punch_z"), 2 * sigmaZ, 1e-8 * sigmaZ);
  EXPECT_NEAR(lastGlobal(run.results, "contact_force_bases_x"), -0.5 * sigmaX, 1e-8 * sigmaX);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_top_z"), -2 * sigmaZ, 1e-8 * sigmaZ);
  EXPECT_NEAR(lastGlobal(run.results, "reaction_bottom_z"), 2 * sigmaZ, 1e-8 * sigmaZ);
}

// The punch of the last 2D test tilted (top u_y = -delta - 0.004 x): the
// left block's corner (1, 0.5), a slave node of `bases`, is a master node of
// the punch's pair, whose force there now has a part along the normal of
// `bases`. The condensed form takes it into that node's conditions
// (PairChaining.hpp; without it Newton does not converge); the saddle-point
// form, whose multipliers are unknowns, needs nothing of the kind: the two
// agree to solver tolerance.
TEST(ContactManyBodies, SlaveNodeThatIsAnotherPairsMasterNodeMatchesTheSaddlePointForm) {
  const std::vector<std::string> blocks{"left_base", "right_base", "punch"};
  const std::vector<AssemblyPair> pairs{{"punch", "punch_bottom", "left_base_top, right_base_top"},
                                {"bases", "left_base_right", "right_base_left"}};
  std::string deck = assemblyDeck("punch_two_blocks2d.e", blocks, {{"left", "x"}, {"right", "x"}}, 0.01, pairs);
  const std::string top = dirichletXml("top", "top", "y", -0.01);
  const auto at = deck.find(top);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, top.size(), dirichletXml("top", "top", "y", -0.01, {-0.004, 0.0}));
  auto condensed = runDeckText("punch_tilted", deck);
  const std::string contact = "<ParameterList name=\"Contact\">";
  deck.replace(deck.find(contact), contact.size(),
               contact + "<Parameter name=\"System Form\" type=\"string\" value=\"Saddle Point\"/>");
  auto saddle = runDeckText("punch_tilted_saddle_point", deck);
  EXPECT_LE(condensed.summary.newtonIterations, 6);
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure"})
    EXPECT_LT(nodalDifference(condensed.results, saddle.results, field), 1e-8) << field;
  EXPECT_NEAR(lastGlobal(condensed.results, "contact_force_bases_x"), lastGlobal(saddle.results, "contact_force_bases_x"),
              1e-8 * std::abs(lastGlobal(saddle.results, "contact_force_bases_x")));
}

}  // namespace
}  // namespace coulomb::test
