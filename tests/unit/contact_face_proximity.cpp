// Point against one contact face (FaceProximity.hpp): distance, signed normal
// distance along the outward normal and the footprint test, on a Line2, a
// Tri3 and a rotated, translated Quad4 whose answers are known in its own frame.
#include <gtest/gtest.h>

#include <cmath>

#include "coulomb/contact/interface/FaceProximity.hpp"

namespace coulomb::contact {
namespace {

using V3 = std::array<double, 3>;
using Nodes = std::array<V3, 4>;

TEST(FaceProximity, Line2FrontBehindAndBeyondItsEnds) {
  const Nodes line{{{0, 0, 0}, {1, 0, 0}}};  // outward normal (dy, -dx) = (0, -1)
  const auto front = faceProximity(2, 2, line, {0.5, -0.3, 0});
  EXPECT_TRUE(front.overFace);
  EXPECT_NEAR(front.normalDistance, 0.3, 1e-15);
  EXPECT_NEAR(front.distance, 0.3, 1e-15);
  const auto behind = faceProximity(2, 2, line, {0.25, 0.2, 0});
  EXPECT_TRUE(behind.overFace);
  EXPECT_NEAR(behind.normalDistance, -0.2, 1e-15);
  const auto beyond = faceProximity(2, 2, line, {1.5, 0.2, 0});
  EXPECT_FALSE(beyond.overFace);
  EXPECT_NEAR(beyond.distance, std::hypot(0.5, 0.2), 1e-15);
}

TEST(FaceProximity, Tri3InsideAndOutsideItsEdges) {
  const Nodes tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};  // outward normal +z
  const auto inside = faceProximity(3, 3, tri, {0.2, 0.2, -0.5});
  EXPECT_TRUE(inside.overFace);
  EXPECT_NEAR(inside.normalDistance, -0.5, 1e-15);
  EXPECT_NEAR(inside.distance, 0.5, 1e-15);
  // Beyond the hypotenuse: nearest point (0.5, 0.5, 0) on the edge.
  const auto outside = faceProximity(3, 3, tri, {0.8, 0.8, 0.1});
  EXPECT_FALSE(outside.overFace);
  EXPECT_NEAR(outside.normalDistance, 0.1, 1e-15);
  EXPECT_NEAR(outside.distance, std::sqrt(0.09 + 0.09 + 0.01), 1e-15);
}

// The unit square rotated (axis (1, 2, 2)/3, angle 0.7) and moved: the
// answers are those of the square in its own frame.
TEST(FaceProximity, RotatedQuad4IsFrameIndependent) {
  const double angle = 0.7, c = std::cos(angle), s = std::sin(angle);
  const V3 k{1.0 / 3, 2.0 / 3, 2.0 / 3}, shift{3.0, -1.0, 2.5};
  auto place = [&](const V3& p) {  // Rodrigues' rotation, then the shift
    const V3 kxp{k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0]};
    const double kp = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
    V3 q;
    for (int i = 0; i < 3; ++i) q[i] = p[i] * c + kxp[i] * s + k[i] * kp * (1 - c) + shift[i];
    return q;
  };
  const Nodes quad{{place({0, 0, 0}), place({1, 0, 0}), place({1, 1, 0}), place({0, 1, 0})}};
  const auto behind = faceProximity(3, 4, quad, place({0.9, 0.3, -0.25}));
  EXPECT_TRUE(behind.overFace);
  EXPECT_NEAR(behind.normalDistance, -0.25, 1e-13);
  EXPECT_NEAR(behind.distance, 0.25, 1e-13);
  const auto aside = faceProximity(3, 4, quad, place({1.3, 0.5, 0.4}));
  EXPECT_FALSE(aside.overFace);
  EXPECT_NEAR(aside.normalDistance, 0.4, 1e-13);
  EXPECT_NEAR(aside.distance, std::hypot(0.3, 0.4), 1e-13);
}

TEST(FaceProximity, DegenerateFaceIsNeverOverTheFace) {
  const Nodes point{{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}};
  const auto r = faceProximity(3, 3, point, {1, 1, 0});
  EXPECT_FALSE(r.overFace);
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
}

}  // namespace
}  // namespace coulomb::contact
