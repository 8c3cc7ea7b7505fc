/// @file PolygonClipping.cpp
/// @brief Sutherland–Hodgman clipping of convex polygons, generic in the scalar.
#include "coulomb/contact/PolygonClipping.hpp"

#include "coulomb/contact/MortarScalarTypes.hpp"

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
  return std::hypot(a[0] - b[0], a[1] - b[1]);
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
      if (qIn) output.push(q);
    }
    mergeCloseVertices(output, tolerance);
    current = output;
  }
  if (current.size < 3) return Polygon2<T>{};
  return current;
}

#define COULOMB_CONTACT_CLIP_INSTANTIATE(T)                         \
  template T signedArea<T>(const Polygon2<T>&);                     \
  template Point2<T> vertexAverage<T>(const Polygon2<T>&);          \
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
#undef COULOMB_CONTACT_CLIP_INSTANTIATE

}  // namespace coulomb::contact
