// Sutherland–Hodgman clipping of convex polygons against closed-form intersection
// areas, and its derivative with a Sacado scalar.
#include <gtest/gtest.h>

#include <Sacado.hpp>
#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "coulomb/contact/mortar/PolygonClipping.hpp"

namespace coulomb::contact {
namespace {

template <typename T = double>
Polygon2<T> polygon(std::initializer_list<Point2<T>> points) {
  Polygon2<T> p;
  for (const auto& v : points) p.push(v);
  return p;
}

Polygon2<double> reversed(Polygon2<double> p) {
  for (int i = 0, j = p.size - 1; i < j; ++i, --j) std::swap(p.vertex[i], p.vertex[j]);
  return p;
}

const Polygon2<double> kUnitSquare = polygon({{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}});

template <typename T>
Polygon2<T> diamond(const T& r) {  // the square |x - 1/2| + |y - 1/2| <= r (rotated by 45 degrees)
  return polygon<T>({{T(0.5 + r), T(0.5)}, {T(0.5), T(0.5 + r)}, {T(0.5 - r), T(0.5)}, {T(0.5), T(0.5 - r)}});
}

constexpr double kTol = 1e-12;

TEST(MortarClipping, SignedAreaAndOrientation) {
  EXPECT_DOUBLE_EQ(signedArea(kUnitSquare), 1.0);
  Polygon2<double> cw = reversed(kUnitSquare);
  EXPECT_DOUBLE_EQ(signedArea(cw), -1.0);
  makeCounterClockwise(cw);
  EXPECT_DOUBLE_EQ(signedArea(cw), 1.0);
  const Point2<double> c = vertexAverage(kUnitSquare);
  EXPECT_DOUBLE_EQ(c[0], 0.5);
  EXPECT_DOUBLE_EQ(c[1], 0.5);
}

TEST(MortarClipping, SquareAndRotatedSquare) {
  // For 1/2 <= r <= 1 the diamond cuts four corner triangles with legs 1 - r off
  // the unit square: area 1 - 2 (1 - r)^2, an octagon for r < 1.
  for (double r : {std::sqrt(0.5), 0.6, 0.9}) {
    const double expected = 1.0 - 2.0 * (1.0 - r) * (1.0 - r);
    for (const auto& [subject, clip] : {std::pair{diamond(r), kUnitSquare}, std::pair{kUnitSquare, diamond(r)},
                                        std::pair{diamond(r), reversed(kUnitSquare)},
                                        std::pair{kUnitSquare, reversed(diamond(r))}}) {
      const Polygon2<double> c = clipConvexPolygon(subject, clip, kTol);
      EXPECT_EQ(c.size, 8);
      EXPECT_NEAR(signedArea(c), expected, 1e-15);
    }
  }
  // r = 1/2: the diamond inscribed in the square (its vertices are the edge
  // midpoints, on the clip edges): area 2 r^2 = 1/2.
  const Polygon2<double> inscribed = clipConvexPolygon(diamond(0.5), kUnitSquare, kTol);
  EXPECT_EQ(inscribed.size, 4);
  EXPECT_NEAR(signedArea(inscribed), 0.5, 1e-15);
}

TEST(MortarClipping, Triangles) {
  const Polygon2<double> tri = polygon({{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}});
  // x >= 1/4, y >= 1/4, x + y <= 1: the triangle (1/4,1/4) (3/4,1/4) (1/4,3/4), area 1/8.
  const Polygon2<double> corner = polygon({{0.25, 0.25}, {1.0, 0.25}, {1.0, 1.0}, {0.25, 1.0}});
  const Polygon2<double> c1 = clipConvexPolygon(tri, corner, kTol);
  EXPECT_EQ(c1.size, 3);
  EXPECT_NEAR(signedArea(c1), 0.125, 1e-15);
  // An equilateral triangle and its point reflection through the centroid: a
  // regular hexagon of 2/3 of the triangle area.
  const double s = std::sqrt(3.0);
  const Polygon2<double> up = polygon({{-1.0, -1.0 / s}, {1.0, -1.0 / s}, {0.0, 2.0 / s}});
  const Polygon2<double> down = polygon({{1.0, 1.0 / s}, {-1.0, 1.0 / s}, {0.0, -2.0 / s}});
  const Polygon2<double> hexagon = clipConvexPolygon(up, down, kTol);
  EXPECT_EQ(hexagon.size, 6);
  EXPECT_NEAR(signedArea(hexagon), 2.0 / 3.0 * signedArea(up), 1e-15);
}

TEST(MortarClipping, DisjointAndTouchingPolygonsGiveNothing) {
  const Polygon2<double> right = polygon({{1.5, 0.0}, {2.5, 0.0}, {2.5, 1.0}, {1.5, 1.0}});
  EXPECT_EQ(clipConvexPolygon(right, kUnitSquare, kTol).size, 0);
  const Polygon2<double> edge = polygon({{1.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 1.0}});
  EXPECT_EQ(clipConvexPolygon(edge, kUnitSquare, kTol).size, 0);
  EXPECT_EQ(clipConvexPolygon(kUnitSquare, edge, kTol).size, 0);
  const Polygon2<double> cornerOnly = polygon({{1.0, 1.0}, {2.0, 1.0}, {2.0, 2.0}, {1.0, 2.0}});
  EXPECT_EQ(clipConvexPolygon(cornerOnly, kUnitSquare, kTol).size, 0);
  // Separated by a diagonal line only (bounding boxes overlap).
  const Polygon2<double> lower = polygon({{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}});
  const Polygon2<double> upper = polygon({{1.0, 0.2}, {1.0, 1.0}, {0.2, 1.0}});
  EXPECT_EQ(clipConvexPolygon(lower, upper, kTol).size, 0);
}

TEST(MortarClipping, Containment) {
  const Polygon2<double> small = polygon({{0.2, 0.3}, {0.7, 0.25}, {0.6, 0.8}});
  const double area = signedArea(small);
  const Polygon2<double> a = clipConvexPolygon(small, kUnitSquare, kTol);
  const Polygon2<double> b = clipConvexPolygon(kUnitSquare, small, kTol);
  EXPECT_EQ(a.size, 3);
  EXPECT_EQ(b.size, 3);
  EXPECT_NEAR(signedArea(a), area, 1e-15);
  EXPECT_NEAR(signedArea(b), area, 1e-15);
  // Identical polygons.
  const Polygon2<double> same = clipConvexPolygon(kUnitSquare, kUnitSquare, kTol);
  EXPECT_EQ(same.size, 4);
  EXPECT_NEAR(signedArea(same), 1.0, 1e-15);
}

TEST(MortarClipping, AreaDerivativeWithFadScalar) {
  // d/dr [1 - 2 (1 - r)^2] = 4 (1 - r): the Fad arithmetic follows the intersection
  // points while the clip decisions are taken on the values.
  using Fad = Sacado::Fad::SFad<double, 27>;
  for (double r0 : {0.6, 0.75, 0.95}) {
    const Fad r(27, 0, r0);
    Polygon2<Fad> square;
    for (int i = 0; i < kUnitSquare.size; ++i) square.push({Fad(kUnitSquare.vertex[i][0]), Fad(kUnitSquare.vertex[i][1])});
    const Polygon2<Fad> c = clipConvexPolygon(diamond(r), square, kTol);
    const Fad area = signedArea(c);
    EXPECT_NEAR(area.val(), 1.0 - 2.0 * (1.0 - r0) * (1.0 - r0), 1e-15);
    EXPECT_NEAR(area.dx(0), 4.0 * (1.0 - r0), 1e-14);
  }
}

// A subject corner just outside a clip edge, from inside the on-edge band
// (kOnEdgeFactor merge tolerances) to the end of the snap zone (2
// kSnapRelative edge lengths): the polygon keeps its four corners and its
// right edge on the clip line x = 1 (the matching-mesh case: iterates
// scatter about coincident edges and must not switch the polygon's form).
// Within the snap zone the corner is moved onto the line; beyond it, it is
// cut off by the intersection, which lies on the line too.
TEST(MortarClipping, CornerNearAClipEdgeKeepsTheFourCorners) {
  const double tol = 1e-10;
  for (double outside : {5 * tol, 0.5 * kOnEdgeFactor * tol, 2.0 * kOnEdgeFactor * tol, 0.5 * kSnapRelative,
                         1.5 * kSnapRelative, 3.0 * kSnapRelative}) {
    const Polygon2<double> subject = polygon({{0.0, 0.0}, {1.0, 0.0}, {1.0 + outside, 1.0}, {0.0, 1.0}});
    const Polygon2<double> c = clipConvexPolygon(subject, kUnitSquare, tol);
    EXPECT_EQ(c.size, 4) << outside;
    double maxX = 0.0;
    for (int k = 0; k < c.size; ++k) maxX = std::max(maxX, c.vertex[k][0]);
    EXPECT_NEAR(maxX, 1.0, 1e-15) << outside;
  }
}

// A subject edge nearly collinear with a clip edge: the subject's bottom edge
// from (0, c - m/2) to (1, c + m/2) against the unit square's y = 0, slope
// m = 1e-6. Exact clipping cuts off the sliver below y = 0, of area
// (c + m/2)^2 / (2 m) while the edges cross inside (|c| < m/2): the area's
// second derivative in c is 1/m = 1e6, the curvature that stalled Newton on
// two coincident cylinder rims (tests/zoo/pressed_torsion_3d). Snapped,
// both ends lie on the clip line and the area is 1 for every such c:
// second differences at the round-off of the area.
TEST(MortarClipping, NearlyCollinearEdgesGiveASmoothArea) {
  const double tol = 1e-10, m = 1e-6, h = 1e-7;
  auto area = [&](double c) {
    return signedArea(clipConvexPolygon(polygon({{0.0, c - m / 2}, {1.0, c + m / 2}, {1.0, 1.0}, {0.0, 1.0}}),
                                        kUnitSquare, tol));
  };
  for (double c : {-2 * h, 0.0, 2 * h}) {
    EXPECT_NEAR(area(c), 1.0, 1e-15) << c;
    const double second = (area(c + h) - 2 * area(c) + area(c - h)) / (h * h);
    EXPECT_LT(std::abs(second), 1.0) << c;  // 1e6 without the snap
  }
}

// In the snap zone's outer half the move is a C2 fading fraction of the
// distance: the area of the unit square whose bottom edge is lifted to
// y = c, clipped by the unit square, is 1 - c beyond 2 snap, 1 within snap,
// and in between a C1 blend whose Fad derivative matches central
// differences (the move's derivative reaches the vertices).
TEST(MortarClipping, SnapIsContinuousWithItsFadDerivative) {
  using Fad = Sacado::Fad::SFad<double, 27>;
  const double tol = 1e-10, snap = kSnapRelative;  // the clip edges are 1 long
  auto lifted = [](auto c) {
    using T = decltype(c);
    Polygon2<T> p;
    p.push({T(0.0), c});
    p.push({T(1.0), c});
    p.push({T(1.0), T(1.0)});
    p.push({T(0.0), T(1.0)});
    return p;
  };
  Polygon2<Fad> square;
  for (int i = 0; i < kUnitSquare.size; ++i) square.push({Fad(kUnitSquare.vertex[i][0]), Fad(kUnitSquare.vertex[i][1])});
  auto value = [&](double c) { return signedArea(clipConvexPolygon(lifted(c), kUnitSquare, tol)); };
  EXPECT_NEAR(value(0.5 * snap), 1.0, 1e-15);
  EXPECT_NEAR(value(2.5 * snap), 1.0 - 2.5 * snap, 1e-15);
  auto derivative = [&](double x) {
    const Fad c(27, 0, x * snap);
    const Fad a = signedArea(clipConvexPolygon(lifted(c), square, tol));
    EXPECT_NEAR(a.val(), value(x * snap), 1e-15) << x;
    return a.dx(0);
  };
  for (double x : {1.25, 1.5, 1.75}) {
    const double c0 = x * snap, h = 1e-3 * snap;
    EXPECT_NEAR(derivative(x), (value(c0 + h) - value(c0 - h)) / (2 * h), 1e-5) << x;
  }
  // C1 at the zone's two ends: dA/dc is 0 (snapped) and -1 (not moved) there.
  EXPECT_NEAR(derivative(1.0 + 1e-8), 0.0, 1e-6);
  EXPECT_NEAR(derivative(2.0 - 1e-8), -1.0, 1e-6);
}

}  // namespace
}  // namespace coulomb::contact
