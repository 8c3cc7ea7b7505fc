/// @file PolygonClipping.cpp
/// @brief Sutherland–Hodgman clipping of convex polygons, generic in the scalar.
#include "coulomb/contact/mortar/PolygonClipping.hpp"

#include "coulomb/contact/mortar/MortarScalarTypes.hpp"

#include <cmath>
#include <utility>

namespace coulomb::contact {
namespace {

template <typename T>
double valueOf(const T& x) {
  return Sacado::ScalarValue<T>::eval(x);
}

/// cross(b - a, p - a): twice the signed area of (a, b, p), positive when p is left of a->b.
template <typename T>
T edgeCross(const Point2<T>& a, const Point2<T>& b, const Point2<T>& p) {
  return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

double distance(const Point2<double>& a, const Point2<double>& b) {
  return planeNorm(a[0] - b[0], a[1] - b[1]);
}

template <typename T>
Point2<double> values(const Point2<T>& p) {
  return {valueOf(p[0]), valueOf(p[1])};
}

/// Drops vertices closer than tol to their (kept) predecessor, cyclically.
template <typename T>
void mergeCloseVertices(Polygon2<T>& polygon, double tol) {
  if (polygon.size == 0) return;
  Polygon2<T> merged;
  merged.push(polygon.vertex[0]);
  for (int i = 1; i < polygon.size; ++i)
    if (distance(values(polygon.vertex[i]), values(merged.vertex[merged.size - 1])) >= tol)
      merged.push(polygon.vertex[i]);
  while (merged.size > 1 && distance(values(merged.vertex[merged.size - 1]), values(merged.vertex[0])) < tol)
    --merged.size;
  polygon = merged;
}

/// Vertices that an edge's clip leaves closer than this many tolerances
/// are merged: duplicates from intersections at a vertex. Far below the
/// input merge: dropping a vertex changes the area by up to half its
/// distance times the edge, a jump in the operators, and the snapped edges
/// put vertices at that distance often (at 1 tolerance the tangent next to
/// a prescribed face differed from central differences by 1e-5).
constexpr double kMergeAfterClipFactor = 1e-3;

/// 1 for r <= 1, 0 for r >= 2, and 1 - smootherstep(r - 1) between: C2 in r.
template <typename T>
T fade(const T& r) {
  if (valueOf(r) <= 1.0) return T(1.0);
  if (valueOf(r) >= 2.0) return T(0.0);
  const T t = r - 1.0;
  return T(1.0 - t * t * t * (t * (6.0 * t - 15.0) + 10.0));
}

/// Moves the vertices of `polygon` that lie within 2 `snap` of the clip
/// edge a->b (of the segment, not of its line's extension) towards its
/// line: within `snap` of the segment onto the line, between `snap` and
/// 2 `snap` by a fraction that fades smoothly (C2 in the vertex, the edge's
/// own position and direction as scalars too). Why: a subject edge nearly
/// collinear with a clip edge (two meshes' boundaries that coincide up to
/// 1e-6, as the rims of two coaxial cylinders of one radius) cuts off a
/// sliver whose apex runs along the edge like d1 / (d1 - d2) (d1, d2 the
/// ends' distances to the line): the overlap area and the mortar operators
/// are C1 but curve on the length scale of d, far below any Newton
/// increment, and the objective slip (dM times a length) and its stick rows
/// then follow no linearisation (tests/zoo/pressed_torsion_3d stalled there).
/// Snapped, the two edges coincide (no sliver) and the operators are smooth
/// functions of the nodes; the overlap changes by less than 2 snap times
/// the edge length, and not at all where the edges coincide exactly.
template <typename T>
void snapToEdgeLine(Polygon2<T>& polygon, const Point2<T>& a, const Point2<T>& b, double orientation) {
  using std::sqrt;
  const T dx = b[0] - a[0], dy = b[1] - a[1];
  const T length = sqrt(dx * dx + dy * dy);
  // The zone's width follows the edge (a scalar of the configuration, so
  // that the derivative sees it: a width from a double tolerance made the
  // tangent miss d(fraction)/d(width)).
  const T snapT = kSnapRelative * length;
  const double snap = valueOf(snapT);
  // Unit normal towards the inner side of the edge, unit tangent a -> b.
  const T nx = -orientation * dy / length, ny = orientation * dx / length;
  const T tx = dx / length, ty = dy / length;
  for (int i = 0; i < polygon.size; ++i) {
    Point2<T>& p = polygon.vertex[i];
    const T d = (p[0] - a[0]) * nx + (p[1] - a[1]) * ny;  // signed distance, > 0 inside
    const T along = (p[0] - a[0]) * tx + (p[1] - a[1]) * ty;
    const double distance = std::abs(valueOf(d)), beyond = std::max(-valueOf(along), valueOf(along) - valueOf(length));
    if (distance >= 2.0 * snap || beyond >= snap) continue;
    const T absD = valueOf(d) < 0.0 ? T(-d) : d;
    const T across = fade<T>(T(absD / snapT));
    const T outside = valueOf(along) < 0.0 ? T(-along) : T(along - length);
    const T lengthwise = beyond <= 0.0 ? T(1.0) : fade<T>(T(1.0 + outside / snapT));
    const T fraction = across * lengthwise;
    if (valueOf(fraction) == 0.0) continue;
    p[0] -= fraction * d * nx;
    p[1] -= fraction * d * ny;
  }
}

}  // namespace

template <typename T>
T signedArea(const Polygon2<T>& polygon) {
  T twice = 0.0;
  for (int i = 0; i < polygon.size; ++i) {
    const Point2<T>& a = polygon.vertex[i];
    const Point2<T>& b = polygon.vertex[(i + 1) % polygon.size];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  return 0.5 * twice;
}

template <typename T>
Point2<T> vertexAverage(const Polygon2<T>& polygon) {
  Point2<T> c{T(0.0), T(0.0)};
  for (int i = 0; i < polygon.size; ++i) {
    c[0] += polygon.vertex[i][0];
    c[1] += polygon.vertex[i][1];
  }
  if (polygon.size > 0) {
    c[0] /= double(polygon.size);
    c[1] /= double(polygon.size);
  }
  return c;
}

template <typename T>
Point2<T> areaCentroid(const Polygon2<T>& polygon) {
  T twice = 0.0, cx = 0.0, cy = 0.0;
  for (int i = 0; i < polygon.size; ++i) {
    const Point2<T>& a = polygon.vertex[i];
    const Point2<T>& b = polygon.vertex[(i + 1) % polygon.size];
    const T cross = a[0] * b[1] - a[1] * b[0];
    twice += cross;
    cx += (a[0] + b[0]) * cross;
    cy += (a[1] + b[1]) * cross;
  }
  if (valueOf(twice) == 0.0) return vertexAverage(polygon);
  return {T(cx / (3.0 * twice)), T(cy / (3.0 * twice))};
}

template <typename T>
void makeCounterClockwise(Polygon2<T>& polygon) {
  if (valueOf(signedArea(polygon)) >= 0.0) return;
  for (int i = 0, j = polygon.size - 1; i < j; ++i, --j) std::swap(polygon.vertex[i], polygon.vertex[j]);
}

template <typename T>
Polygon2<T> clipConvexPolygon(const Polygon2<T>& subject, const Polygon2<T>& clip, double tolerance) {
  Polygon2<T> current = subject;
  mergeCloseVertices(current, tolerance);
  Polygon2<T> clipPolygon = clip;
  mergeCloseVertices(clipPolygon, tolerance);
  if (current.size < 3 || clipPolygon.size < 3) return Polygon2<T>{};
  // Inner side of a clip edge: left for a counter-clockwise clip polygon.
  const double orientation = valueOf(signedArea(clipPolygon)) >= 0.0 ? 1.0 : -1.0;

  for (int e = 0; e < clipPolygon.size && current.size > 0; ++e) {
    const Point2<T>& a = clipPolygon.vertex[e];
    const Point2<T>& b = clipPolygon.vertex[(e + 1) % clipPolygon.size];
    const double edgeLength = distance(values(a), values(b));
    if (edgeLength > 0.0) snapToEdgeLine(current, a, b, orientation);
    // Signed distance to the edge line, positive inside (on the double values);
    // the on-edge band outside is kOnEdgeFactor tolerances wide (see the header).
    auto inside = [&](const T& cross) { return orientation * valueOf(cross) >= -kOnEdgeFactor * tolerance * edgeLength; };

    Polygon2<T> output;
    for (int i = 0; i < current.size; ++i) {
      const Point2<T>& p = current.vertex[(i + current.size - 1) % current.size];
      const Point2<T>& q = current.vertex[i];
      const T cp = edgeCross(a, b, p);
      const T cq = edgeCross(a, b, q);
      const bool pIn = inside(cp), qIn = inside(cq);
      if (pIn != qIn) {
        // Intersection p + t (q - p) with the edge line, cross(.) linear along pq.
        T t = cp / (cp - cq);
        // A vertex inside only by the tolerance can put t outside [0,1]: clamp
        // (the duplicate is merged below).
        if (valueOf(t) < 0.0) t = 0.0;
        if (valueOf(t) > 1.0) t = 1.0;
        output.push({T(p[0] + t * (q[0] - p[0])), T(p[1] + t * (q[1] - p[1]))});
      }
      if (qIn) {
        // A vertex outside by less than the band goes onto the edge's line,
        // so that leaving the band (cut off by the intersections, which lie
        // on the line) changes the polygon by O(band^2), not O(band x edge).
        if (orientation * valueOf(cq) < 0.0) {
          const T ex = b[0] - a[0], ey = b[1] - a[1];
          const T s = cq / (ex * ex + ey * ey);
          output.push({T(q[0] + s * ey), T(q[1] - s * ex)});
        } else {
          output.push(q);
        }
      }
    }
    mergeCloseVertices(output, kMergeAfterClipFactor * tolerance);
    current = output;
  }
  if (current.size < 3) return Polygon2<T>{};
  return current;
}

#define COULOMB_CONTACT_CLIP_INSTANTIATE(T)                         \
  template T signedArea<T>(const Polygon2<T>&);                     \
  template Point2<T> vertexAverage<T>(const Polygon2<T>&);          \
  template Point2<T> areaCentroid<T>(const Polygon2<T>&);           \
  template void makeCounterClockwise<T>(Polygon2<T>&);              \
  template Polygon2<T> clipConvexPolygon<T>(const Polygon2<T>&, const Polygon2<T>&, double);

// The scalar types of the 3D mortar kernels (MortarScalarTypes.hpp).
using mesh::FaceType;
using Fad3DTriTri = SegmentFad3D<FaceType::Tri3, FaceType::Tri3>;
using Fad3DTriQuad = SegmentFad3D<FaceType::Tri3, FaceType::Quad4>;
using Fad3DQuadTri = SegmentFad3D<FaceType::Quad4, FaceType::Tri3>;
using Fad3DQuadQuad = SegmentFad3D<FaceType::Quad4, FaceType::Quad4>;
COULOMB_CONTACT_CLIP_INSTANTIATE(double)
COULOMB_CONTACT_CLIP_INSTANTIATE(Fad3DTriTri)
COULOMB_CONTACT_CLIP_INSTANTIATE(Fad3DTriQuad)
COULOMB_CONTACT_CLIP_INSTANTIATE(Fad3DQuadTri)
COULOMB_CONTACT_CLIP_INSTANTIATE(Fad3DQuadQuad)
// MortarSegmentQuadratic3D (SubFacetFad3D: 3 x the nodes of both faces),
// the counts not above (27 to 36): Quad9/Quad9 54, Quad9/Quad8 and
// Quad8/Quad9 51, Quad8/Quad8 48, Quad9/Tri6 and Tri6/Quad9 45, Quad8/Tri6
// and Tri6/Quad8 42, Quad9/Quad4 and Quad4/Quad9 39.
using FadInputs54 = Sacado::Fad::SFad<double, 54>;
COULOMB_CONTACT_CLIP_INSTANTIATE(FadInputs54)
using FadInputs51 = Sacado::Fad::SFad<double, 51>;
COULOMB_CONTACT_CLIP_INSTANTIATE(FadInputs51)
using FadInputs48 = Sacado::Fad::SFad<double, 48>;
COULOMB_CONTACT_CLIP_INSTANTIATE(FadInputs48)
using FadInputs42 = Sacado::Fad::SFad<double, 42>;
COULOMB_CONTACT_CLIP_INSTANTIATE(FadInputs42)
using FadInputs45 = Sacado::Fad::SFad<double, 45>;
COULOMB_CONTACT_CLIP_INSTANTIATE(FadInputs45)
using FadInputs39 = Sacado::Fad::SFad<double, 39>;
COULOMB_CONTACT_CLIP_INSTANTIATE(FadInputs39)
#undef COULOMB_CONTACT_CLIP_INSTANTIATE

}  // namespace coulomb::contact
