/// @file MortarSegment3D.cpp
/// @brief Auxiliary-plane mortar integration of a 3D face pair (equations in the header).
#include "coulomb/contact/mortar/MortarSegment3D.hpp"

#include "coulomb/contact/mortar/MortarScalarTypes.hpp"

#include <cmath>
#include <type_traits>

#include "coulomb/contact/mortar/AuxiliaryPlane.hpp"
#include "coulomb/contact/mortar/PolygonClipping.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using namespace plane;

}  // namespace

template <FaceType S, FaceType Mf, typename T>
MortarSegment3D<S, Mf, T> integrateSegment3D(const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns,
                                             const FaceNodes<Mf, T>& xm, double relativeTolerance) {
  static_assert(S != FaceType::Line2 && Mf != FaceType::Line2, "3D kernel: Tri3 and Quad4 faces only");
  using std::sqrt;
  constexpr int nS = FaceTraits<S>::nodes;
  constexpr int nM = FaceTraits<Mf>::nodes;
  MortarSegment3D<S, Mf, T> out;
  for (int j = 0; j < nS; ++j) {
    out.D[j] = 0.0;
    out.gap[j] = 0.0;
    for (int l = 0; l < nM; ++l) out.M[j][l] = 0.0;
  }
  out.area = 0.0;

  // 1. Auxiliary plane: centre x0, unit normal n0, in-plane basis e1, e2 (e1 × e2 = n0).
  Vec3<T> x0{T(0.0), T(0.0), T(0.0)};
  for (int a = 0; a < nS; ++a)
    for (int i = 0; i < 3; ++i) x0[i] += xs[a][i] / double(nS);
  Vec3<T> v;
  if constexpr (S == FaceType::Tri3)
    v = cross(sub(xs[1], xs[0]), sub(xs[2], xs[0]));
  else
    v = cross(sub(xs[2], xs[0]), sub(xs[3], xs[1]));
  const T vNorm = sqrt(dot(v, v));
  if (!(valueOf(vNorm) > 0.0)) return out;  // degenerate slave face
  const Vec3<T> n0{T(v[0] / vNorm), T(v[1] / vNorm), T(v[2] / vNorm)};
  const Vec3<T> t = sub(xs[1], xs[0]);
  const T tn = dot(t, n0);
  Vec3<T> e1{T(t[0] - tn * n0[0]), T(t[1] - tn * n0[1]), T(t[2] - tn * n0[2])};
  const T e1Norm = sqrt(dot(e1, e1));
  for (int i = 0; i < 3; ++i) e1[i] /= e1Norm;
  const Vec3<T> e2 = cross(n0, e1);
  auto toPlane = [&](const std::array<T, 3>& x) {
    const Vec3<T> r = sub(x, x0);
    return Point2<T>{dot(r, e1), dot(r, e2)};
  };

  // 2. Projected faces. The slave polygon is counter-clockwise by the choice of n0.
  PlaneNodes<S, T> ps;
  PlaneNodes<Mf, T> pm;
  Polygon2<T> slavePolygon, masterPolygon;
  for (int a = 0; a < nS; ++a) {
    ps[a] = toPlane(xs[a]);
    slavePolygon.push(ps[a]);
  }
  for (int a = 0; a < nM; ++a) {
    pm[a] = toPlane(xm[a]);
    masterPolygon.push(pm[a]);
  }
  const double slaveArea = valueOf(signedArea(slavePolygon));
  if (!(slaveArea > 0.0)) return out;
  if (!(std::abs(valueOf(signedArea(masterPolygon))) > relativeTolerance * slaveArea)) return out;

  if constexpr (S == FaceType::Quad4)
    COULOMB_REQUIRE(reflexVertex(ps, relativeTolerance * slaveArea) == -1,
                    "mortar integration: a slave Quad4 face is not convex on its auxiliary plane (distorted element)");

  // Master pieces: the face itself, or — a Quad4 whose projection is not
  // convex (seen edge-on or badly distorted after a large predictor) — the
  // two triangles either side of the diagonal through its reflex vertex,
  // each integrated with the linear interpolation of its three nodes. The
  // clip needs convex pieces, and points of a non-convex bilinear face have
  // no inverse map there (the map folds).
  struct Piece {
    int count;
    std::array<int, 4> node;
  };
  std::array<Piece, 2> pieces{};
  int numPieces = 1;
  pieces[0] = {nM, {0, 1, 2, 3}};
  if constexpr (Mf == FaceType::Quad4) {
    const int reflex = reflexVertex(pm, relativeTolerance * slaveArea);
    if (reflex == -2) {
      // A bow-tie that does not reach the slave face is no contact; one that
      // does is a geometry failure of this iterate (the step is cut back).
      bool overlaps = false;
      for (int first : {0, 2}) {
        Polygon2<T> half;
        for (int a = 0; a < 3; ++a) half.push(pm[(first + a) % 4]);
        if (!(std::abs(valueOf(signedArea(half))) > relativeTolerance * slaveArea)) continue;
        makeCounterClockwise(half);
        const Polygon2<T> part = clipConvexPolygon(half, slavePolygon, relativeTolerance * std::sqrt(slaveArea));
        overlaps = overlaps || (part.size >= 3 && valueOf(signedArea(part)) > relativeTolerance * slaveArea);
      }
      if (!overlaps) return out;
      COULOMB_REQUIRE(false, "mortar integration: a master Quad4 face is twisted over itself when projected onto a "
                             "slave face's auxiliary plane (a bow-tie)");
    }
    if (reflex >= 0) {
      numPieces = 2;
      pieces[0] = {3, {reflex, (reflex + 1) % 4, (reflex + 2) % 4, -1}};
      pieces[1] = {3, {(reflex + 2) % 4, (reflex + 3) % 4, reflex, -1}};
    }
  }

  const NodalMatrix<S, T> A = dualCoefficients<S, T>(xs);
  const TriangleRule7& rule = triangleRule7();
  const double tolerance = relativeTolerance * std::sqrt(slaveArea);
  for (int k = 0; k < numPieces; ++k) {
    const Piece& piece = pieces[k];
    Polygon2<T> piecePolygon;
    for (int a = 0; a < piece.count; ++a) piecePolygon.push(pm[piece.node[a]]);
    if (!(std::abs(valueOf(signedArea(piecePolygon))) > relativeTolerance * slaveArea)) continue;
    makeCounterClockwise(piecePolygon);

    // 3. Clip polygon.
    const Polygon2<T> clip = clipConvexPolygon(piecePolygon, slavePolygon, tolerance);
    if (clip.size < 3 || !(valueOf(signedArea(clip)) > relativeTolerance * slaveArea)) continue;
    out.contributes = true;
    out.polygonVertices += clip.size;

    // Master shape values at a plane point: the face map's inverse, or the
    // barycentric coordinates of a triangle piece.
    auto masterShape = [&](const Point2<T>& p) {
      NodalValues<Mf, T> N2;
      for (int l = 0; l < nM; ++l) N2[l] = 0.0;
      if (numPieces == 1) return faceShapeValues<Mf, T>(invertPlaneMap<Mf, T>(pm, p));
      PlaneNodes<FaceType::Tri3, T> tri{pm[piece.node[0]], pm[piece.node[1]], pm[piece.node[2]]};
      const FacePoint<FaceType::Tri3, T> xi = invertPlaneMap<FaceType::Tri3, T>(tri, p);
      N2[piece.node[0]] = 1.0 - xi[0] - xi[1];
      N2[piece.node[1]] = xi[0];
      N2[piece.node[2]] = xi[1];
      return N2;
    };

    // 4.-6. Cells, Gauss points, back-projection, integration.
    // The fan from the area centroid, triangles too: the cells change
    // continuously where a vertex of the clip polygon splits in two or two
    // merge (a fan from the vertex average jumps there, and with it the
    // quadrature error of a non-affine Quad4 integrand).
    const Point2<T> centre = areaCentroid(clip);
    const int cells = clip.size;
    for (int c = 0; c < cells; ++c) {
      const Point2<T>& q0 = centre;
      const Point2<T>& q1 = clip.vertex[c];
      const Point2<T>& q2 = clip.vertex[(c + 1) % clip.size];
      const T cellArea = 0.5 * ((q1[0] - q0[0]) * (q2[1] - q0[1]) - (q1[1] - q0[1]) * (q2[0] - q0[0]));
      for (int g = 0; g < 7; ++g) {
        const std::array<double, 3>& L = rule.L[g];
        const Point2<T> p{T(L[0] * q0[0] + L[1] * q1[0] + L[2] * q2[0]),
                          T(L[0] * q0[1] + L[1] * q1[1] + L[2] * q2[1])};
        const FacePoint<S, T> xi1 = invertPlaneMap<S, T>(ps, p);
        const NodalValues<S, T> N1 = faceShapeValues<S, T>(xi1);
        const NodalValues<S, T> phi = dualShapeValues<S, T, T>(A, xi1);
        const NodalValues<Mf, T> N2 = masterShape(p);
        const Vec3<T> x1 = facePoint<S, T, T>(xs, xi1);
        Vec3<T> x2{T(0.0), T(0.0), T(0.0)};
        for (int l = 0; l < nM; ++l)
          for (int i = 0; i < 3; ++i) x2[i] += N2[l] * xm[l][i];
        Vec3<T> n{T(0.0), T(0.0), T(0.0)};
        for (int a = 0; a < nS; ++a)
          for (int i = 0; i < 3; ++i) n[i] += N1[a] * ns[a][i];
        const T gn = dot(sub(x2, x1), n) / sqrt(dot(n, n));
        T dA = rule.w[g] * cellArea;
        if constexpr (S == FaceType::Quad4) {
          // Slave surface measure over plane measure: |x_xi × x_eta| / ((x_xi × x_eta).n0).
          const Vec3<T> nx = tangentNormal<S, T>(faceShapeGradients<S, T>(xi1), xs);
          dA *= sqrt(dot(nx, nx)) / dot(nx, n0);
        }
        addGaussPoint(out, phi, N2, gn, dA);
      }
    }
  }
  return out;
}

template <FaceType S, FaceType Mf>
MortarSegment3DLinearization<S, Mf> linearizeSegment3D(const FaceNodes<S, double>& xs,
                                                       const FaceNodes<S, double>& ns,
                                                       const FaceNodes<Mf, double>& xm, double relativeTolerance) {
  return linearize3D<S, Mf>(xs, ns, xm, [&](const auto& fxs, const auto& fns, const auto& fxm) {
    return integrateSegment3D<S, Mf, SegmentFad3D<S, Mf>>(fxs, fns, fxm, relativeTolerance);
  });
}

#define COULOMB_CONTACT_SEGMENT3D_INSTANTIATE(S, Mf)                                                      \
  template MortarSegment3D<S, Mf, double> integrateSegment3D<S, Mf, double>(                            \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double);    \
  template MortarSegment3D<S, Mf, SegmentFad3D<S, Mf>>                   \
  integrateSegment3D<S, Mf, SegmentFad3D<S, Mf>>(                         \
      const FaceNodes<S, SegmentFad3D<S, Mf>>&,                           \
      const FaceNodes<S, SegmentFad3D<S, Mf>>&,                           \
      const FaceNodes<Mf, SegmentFad3D<S, Mf>>&, double);                 \
  template MortarSegment3DLinearization<S, Mf> linearizeSegment3D<S, Mf>(                                 \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double);
COULOMB_CONTACT_SEGMENT3D_INSTANTIATE(FaceType::Tri3, FaceType::Tri3)
COULOMB_CONTACT_SEGMENT3D_INSTANTIATE(FaceType::Tri3, FaceType::Quad4)
COULOMB_CONTACT_SEGMENT3D_INSTANTIATE(FaceType::Quad4, FaceType::Tri3)
COULOMB_CONTACT_SEGMENT3D_INSTANTIATE(FaceType::Quad4, FaceType::Quad4)
#undef COULOMB_CONTACT_SEGMENT3D_INSTANTIATE

}  // namespace coulomb::contact
