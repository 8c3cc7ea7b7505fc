#pragma once
/// @file PolygonClipping.hpp
/// @brief Intersection of two convex polygons in a plane (Sutherland–Hodgman),
/// on fixed-capacity polygons, usable with automatic-differentiation scalars.
///
/// With a Sacado Fad scalar every decision (inside/outside of an edge, whether
/// two vertices coincide, orientation) is made on the double values, and the
/// arithmetic (intersection points, areas) on the scalars: the result is the
/// derivative of the polygon for a fixed topology. At configurations where the
/// topology changes (a vertex crossing an edge of the other polygon) the
/// intersection is continuous but not differentiable; derivatives there are
/// one-sided.
///
/// Scalar types: explicitly instantiated in PolygonClipping.cpp for double and
/// Sacado::Fad::SFad<double, N>, N = 27, 30, 33, 36 (the 3D mortar kernels);
/// only the double instantiations are declared `extern` here (no Sacado in headers).
#include <array>
#include <cmath>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

/// A point of the plane.
template <typename T>
using Point2 = std::array<T, 2>;

/// |(x, y)| of plane lengths and residuals: sqrt(x^2 + y^2), several times
/// cheaper than std::hypot (which guards against overflow that lengths of a
/// mesh never reach; it was 1 % of a HEX20 contact run).
inline double planeNorm(double x, double y) { return std::sqrt(x * x + y * y); }

/// Capacity of a polygon: the intersection of two convex polygons with p and q
/// vertices has at most p + q vertices (8 for two quadrilaterals).
inline constexpr int kMaxPolygonVertices = 16;

/// @brief A polygon of at most kMaxPolygonVertices vertices (no allocation).
template <typename T>
struct Polygon2 {
  std::array<Point2<T>, kMaxPolygonVertices> vertex{};
  int size = 0;

  void push(const Point2<T>& p) {
    COULOMB_REQUIRE(size < kMaxPolygonVertices, "polygon clipping: more than " << kMaxPolygonVertices
                                                                               << " vertices (non-convex input?)");
    vertex[size++] = p;
  }
};

/// @brief Signed area by the shoelace formula, positive for counter-clockwise order.
template <typename T>
T signedArea(const Polygon2<T>& polygon);

/// @brief Average of the vertices (inside a convex polygon; used as the fan centre).
template <typename T>
Point2<T> vertexAverage(const Polygon2<T>& polygon);

/// @brief Area centroid of a polygon (the vertex average if its area is 0):
/// continuous in the vertices, also where a vertex splits in two or two
/// merge (the vertex average jumps there): the fan centre of the mortar cells.
template <typename T>
Point2<T> areaCentroid(const Polygon2<T>& polygon);

/// @brief Reverses the vertex order if the polygon is clockwise (decided on the double values).
template <typename T>
void makeCounterClockwise(Polygon2<T>& polygon);

/// @brief Width of the band outside a clip edge in which a vertex counts as on
/// the edge, in units of the merge tolerance: 10 (1e-9 of the face) lies
/// outside the scatter of Newton iterates about coincident edges of
/// matching meshes (at 1, the 3D stick patch cycled) and below the jump at
/// the band's outer edge that a sliding sphere met at 100 (docs/architecture.md,
/// "Matching meshes" and "Nearly coincident boundaries").
constexpr double kOnEdgeFactor = 10.0;

/// @brief Width of the zone about a clip edge in which subject vertices are
/// moved onto its line, as a fraction of that edge's length: fully within
/// one width of the segment, by a C2 fading fraction in the next
/// (PolygonClipping.cpp, snapToEdgeLine: nearly collinear edges of two
/// meshes are taken as one).
constexpr double kSnapRelative = 1e-4;

/// @brief subject ∩ clip by Sutherland–Hodgman.
///
/// `clip` must be convex (either orientation); `subject` should be convex (a
/// non-convex subject gives the correct area but may carry degenerate edges).
/// The result keeps the orientation of `subject`. Subject vertices within
/// 2 kSnapRelative clip-edge lengths of a clip edge (the segment) are first
/// moved towards its line (snapToEdgeLine in the .cpp); a vertex outside an
/// edge by less than the band goes onto its line. A vertex within
/// kOnEdgeFactor × `tolerance` (a length) of the inner side of a clip edge
/// counts as inside; consecutive vertices closer than `tolerance` are merged. A result with fewer than three
/// vertices (disjoint, or touching along an edge or at a point) is returned
/// with size 0; a result of (near) zero area but three or more vertices is left
/// to the caller's area test.
template <typename T>
Polygon2<T> clipConvexPolygon(const Polygon2<T>& subject, const Polygon2<T>& clip, double tolerance);

extern template double signedArea<double>(const Polygon2<double>&);
extern template Point2<double> vertexAverage<double>(const Polygon2<double>&);
extern template Point2<double> areaCentroid<double>(const Polygon2<double>&);
extern template void makeCounterClockwise<double>(Polygon2<double>&);
extern template Polygon2<double> clipConvexPolygon<double>(const Polygon2<double>&, const Polygon2<double>&,
                                                           double);

}  // namespace coulomb::contact
