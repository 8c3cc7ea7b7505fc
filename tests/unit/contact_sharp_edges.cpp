// The kernels of SharpEdges.hpp: feature groups of the faces around a node,
// the group facing a master, the search's facing test.
#include <gtest/gtest.h>

#include <cmath>

#include "coulomb/contact/interface/SharpEdges.hpp"

namespace coulomb::contact {
namespace {

using Vec = std::array<double, 3>;

Vec unitAt(double degrees) { return {std::cos(degrees * M_PI / 180), std::sin(degrees * M_PI / 180), 0.0}; }

constexpr double k60 = 60 * M_PI / 180;

// A cube corner: three faces, each pair at 90 degrees: three groups; a node
// on an edge with two faces on each side: two groups.
TEST(SharpEdges, CubeCornerAndEdgeMakeOneGroupPerSide) {
  EXPECT_EQ(featureGroups({{0, 0, -1}, {1, 0, 0}, {0, 1, 0}}, k60), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(featureGroups({{0, 0, -1}, {1, 0, 0}, {0, 0, -1}, {1, 0, 0}}, k60), (std::vector<int>{0, 1, 0, 1}));
}

// A smooth surface stays one group, also where the spread of its faces'
// normals exceeds the angle (single linkage: 0, 40, 80 degrees).
TEST(SharpEdges, SmoothBendIsOneGroup) {
  EXPECT_EQ(featureGroups({unitAt(0), unitAt(30)}, k60), (std::vector<int>{0, 0}));
  EXPECT_EQ(featureGroups({unitAt(80), unitAt(0), unitAt(40)}, k60), (std::vector<int>{0, 0, 0}));
  // Just beyond the angle: split; just within: one group.
  EXPECT_EQ(featureGroups({unitAt(0), unitAt(60.5)}, k60), (std::vector<int>{0, 1}));
  EXPECT_EQ(featureGroups({unitAt(0), unitAt(59.5)}, k60), (std::vector<int>{0, 0}));
}

// A block's bottom edge above a flat master (normal up): the bottom faces
// the master, the side does not; a master wall beside it turns the choice.
TEST(SharpEdges, TheGroupOpposingTheMasterFacesIt) {
  const std::vector<Vec> groups{{0, 0, -1}, {1, 0, 0}};
  const double cos60 = std::cos(k60);
  EXPECT_EQ(facingGroups(groups, {{0, 0, 1}}, cos60), (std::vector<int>{0}));
  EXPECT_EQ(facingGroups(groups, {{0, 0, 1}, {-0.8, 0, 0.6}}, cos60), (std::vector<int>{0}));  // best wins
  EXPECT_EQ(facingGroups(groups, {{-1, 0, 0}}, cos60), (std::vector<int>{1}));
  // Both opposed equally (a convex edge in a concave one): both groups.
  const double s = std::sqrt(0.5);
  EXPECT_EQ(facingGroups(groups, {{-s, 0, s}}, 0.5), (std::vector<int>{0, 1}));
  // No master within the feature angle of opposite: none (the plain average).
  EXPECT_TRUE(facingGroups(groups, {{-s, 0, s}}, cos60 + 0.3).empty());
  EXPECT_TRUE(facingGroups(groups, {}, cos60).empty());
  EXPECT_TRUE(facingGroups(groups, {{0, 1, 0}}, cos60).empty());
}

TEST(SharpEdges, FacingTestOfTheSearch) {
  EXPECT_NEAR(facingNormalDot(60), -0.5, 1e-15);
  EXPECT_NEAR(facingNormalDot(90), 0.0, 1e-15);
  EXPECT_EQ(facingNormalDot(180), 1.0);  // off: every box candidate stays
}

}  // namespace
}  // namespace coulomb::contact
