// Sutherland–Hodgman clipping of convex polygons against closed-form intersection
// areas, and its derivative with a Sacado scalar.
#include <gtest/gtest.h>

#include <Sacado.hpp>
#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "coulomb/contact/PolygonClipping.hpp"

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

// A subject corner just outside a clip edge: inside the on-edge band
// (kOnEdgeFactor merge tolerances) it stays a vertex of the result, the
// polygon keeps its four corners and its derivative is that of the subject
// alone (the matching-mesh case: iterates scatter about coincident edges and
// must not switch the polygon's form); beyond the band it is cut off by the
// intersection, which lies on the clip line.
TEST(MortarClipping, VertexInTheOnEdgeBandStaysAVertex) {
  const double tol = 1e-10;
  for (double outside : {0.5 * kOnEdgeFactor * tol, 2.0 * kOnEdgeFactor * tol}) {
    // The unit square with its corner (1, 1) moved outside the clip's edge x = 1.
    const Polygon2<double> subject = polygon({{0.0, 0.0}, {1.0, 0.0}, {1.0 + outside, 1.0}, {0.0, 1.0}});
    const Polygon2<double> c = clipConvexPolygon(subject, kUnitSquare, tol);
    const bool inBand = outside < kOnEdgeFactor * tol;
    EXPECT_EQ(c.size, 4) << outside;
    double maxX = 0.0;
    for (int k = 0; k < c.size; ++k) maxX = std::max(maxX, c.vertex[k][0]);
    EXPECT_DOUBLE_EQ(maxX, inBand ? 1.0 + outside : 1.0) << outside;
  }
  // The band's width itself: 5 merge tolerances outside is still on the edge
  // (with a band of one tolerance, the old one, the 3D stick patch on a
  // matching mesh did not converge).
  const Polygon2<double> c = clipConvexPolygon(polygon({{0.0, 0.0}, {1.0, 0.0}, {1.0 + 5 * tol, 1.0}, {0.0, 1.0}}),
                                               kUnitSquare, tol);
  double maxX = 0.0;
  for (int k = 0; k < c.size; ++k) maxX = std::max(maxX, c.vertex[k][0]);
  EXPECT_DOUBLE_EQ(maxX, 1.0 + 5 * tol);
}

}  // namespace
}  // namespace coulomb::contact
