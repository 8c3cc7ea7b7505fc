/// @file MortarSegment3D.cpp
/// @brief Auxiliary-plane mortar integration of a 3D face pair (equations in the header).
#include "coulomb/contact/mortar/MortarSegment3D.hpp"

#include "coulomb/contact/mortar/MortarScalarTypes.hpp"

#include <cmath>
#include <type_traits>

#include "coulomb/contact/mortar/PolygonClipping.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
template <typename T>
using Vec3 = std::array<T, 3>;

template <typename T>
double valueOf(const T& x) {
  return Sacado::ScalarValue<T>::eval(x);
}

template <typename T>
Vec3<T> sub(const Vec3<T>& a, const Vec3<T>& b) {
  return {T(a[0] - b[0]), T(a[1] - b[1]), T(a[2] - b[2])};
}
template <typename T>
T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <typename T>
Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {T(a[1] * b[2] - a[2] * b[1]), T(a[2] * b[0] - a[0] * b[2]), T(a[0] * b[1] - a[1] * b[0])};
}

/// Radon's 7-point rule on a triangle, barycentric coordinates, weights summing to 1
/// (exact for total degree 5).
struct TriangleRule7 {
  std::array<std::array<double, 3>, 7> L{};
  std::array<double, 7> w{};
  TriangleRule7() {
    const double s15 = std::sqrt(15.0);
    const double a1 = (6.0 - s15) / 21.0, b1 = 1.0 - 2.0 * a1, w1 = (155.0 - s15) / 1200.0;
    const double a2 = (6.0 + s15) / 21.0, b2 = 1.0 - 2.0 * a2, w2 = (155.0 + s15) / 1200.0;
    L = {{{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0},
          {a1, a1, b1},
          {a1, b1, a1},
          {b1, a1, a1},
          {a2, a2, b2},
          {a2, b2, a2},
          {b2, a2, a2}}};
    w = {9.0 / 40.0, w1, w1, w1, w2, w2, w2};
  }
};

const TriangleRule7& triangleRule7() {
  static const TriangleRule7 rule;
  return rule;
}

/// Nodes of a face projected onto the auxiliary plane (2D plane coordinates).
template <FaceType F, typename T>
using PlaneNodes = std::array<Point2<T>, FaceTraits<F>::nodes>;

/// xi with sum_a N_a(xi) p_a = p for the projected face map (the projection of
/// the plane point p onto the face along n0).
/// Tri3: the affine map, solved directly. Quad4: Newton on the double values
/// from the centre, then one Newton step in T at the converged point, which
/// gives the exact derivative dxi = -J^{-1} dF (implicit function theorem).
template <FaceType F, typename T>
FacePoint<F, T> invertPlaneMap(const PlaneNodes<F, T>& pn, const Point2<T>& p) {
  if constexpr (F == FaceType::Tri3) {
    const T a00 = pn[1][0] - pn[0][0], a01 = pn[2][0] - pn[0][0];
    const T a10 = pn[1][1] - pn[0][1], a11 = pn[2][1] - pn[0][1];
    const T r0 = p[0] - pn[0][0], r1 = p[1] - pn[0][1];
    const T det = a00 * a11 - a01 * a10;
    return {T((a11 * r0 - a01 * r1) / det), T((a00 * r1 - a10 * r0) / det)};
  } else {
    auto residual = [&](const auto& nodes, const auto& point, const auto& xi, auto& F0, auto& J) {
      using S = std::decay_t<decltype(xi[0])>;
      const auto N = faceShapeValues<FaceType::Quad4, S>(xi);
      const auto g = faceShapeGradients<FaceType::Quad4, S>(xi);
      for (int i = 0; i < 2; ++i) {
        F0[i] = -point[i];
        J[i][0] = 0.0;
        J[i][1] = 0.0;
        for (int a = 0; a < 4; ++a) {
          F0[i] += N[a] * nodes[a][i];
          J[i][0] += g[a][0] * nodes[a][i];
          J[i][1] += g[a][1] * nodes[a][i];
        }
      }
    };
    PlaneNodes<F, double> nd;
    for (int a = 0; a < 4; ++a) nd[a] = {valueOf(pn[a][0]), valueOf(pn[a][1])};
    const Point2<double> pd{valueOf(p[0]), valueOf(p[1])};
    const double size = std::hypot(nd[2][0] - nd[0][0], nd[2][1] - nd[0][1]) +
                        std::hypot(nd[3][0] - nd[1][0], nd[3][1] - nd[1][1]);
    // Damped Newton from the centre: a step is at most 0.5 in xi and is
    // halved until |F| decreases, so an iterate never jumps far outside the
    // face where the bilinear map folds. Points are inside the (convex)
    // projected face, where the map is invertible.
    FacePoint<F, double> xi{0.0, 0.0};
    std::array<double, 2> Fd{};
    std::array<std::array<double, 2>, 2> Jd{};
    residual(nd, pd, xi, Fd, Jd);
    double norm = std::hypot(Fd[0], Fd[1]);
    bool converged = false;
    for (int it = 0; it < 50 && !converged; ++it) {
      const double det = Jd[0][0] * Jd[1][1] - Jd[0][1] * Jd[1][0];
      COULOMB_REQUIRE(std::abs(det) > 1e-14 * size * size,
                      "mortar integration: degenerate or folded Quad4 face projection");
      double d0 = (Jd[1][1] * Fd[0] - Jd[0][1] * Fd[1]) / det;
      double d1 = (Jd[0][0] * Fd[1] - Jd[1][0] * Fd[0]) / det;
      const double length = std::max(std::abs(d0), std::abs(d1));
      if (length > 0.5) d0 *= 0.5 / length, d1 *= 0.5 / length;
      converged = std::abs(d0) + std::abs(d1) <= 1e-14 * (1.0 + std::abs(xi[0]) + std::abs(xi[1]));
      FacePoint<F, double> trial{xi[0] - d0, xi[1] - d1};
      residual(nd, pd, trial, Fd, Jd);
      double trialNorm = std::hypot(Fd[0], Fd[1]);
      for (int halving = 0; halving < 20 && !converged && !(trialNorm < norm); ++halving) {
        d0 *= 0.5, d1 *= 0.5;
        trial = {xi[0] - d0, xi[1] - d1};
        residual(nd, pd, trial, Fd, Jd);
        trialNorm = std::hypot(Fd[0], Fd[1]);
      }
      xi = trial;
      norm = trialNorm;
      converged = converged || norm <= 1e-15 * size;
    }
    const FacePoint<F, T> xiT{T(xi[0]), T(xi[1])};
    std::array<T, 2> F0{};
    std::array<std::array<T, 2>, 2> J{};
    residual(pn, p, xiT, F0, J);
    const T det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    return {T(xiT[0] - (J[1][1] * F0[0] - J[0][1] * F0[1]) / det),
            T(xiT[1] - (J[0][0] * F0[1] - J[1][0] * F0[0]) / det)};
  }
}

/// Index of the vertex of a projected quadrilateral where it is not convex
/// (the turn there has the other sign than the polygon's orientation), -1
/// when it is convex, -2 when it intersects itself (a bow-tie: two turns of
/// each sign; the face is twisted so far that part of it faces away from the
/// plane, and no split into triangles covers it once). Turns smaller than
/// `areaTolerance` count as straight.
template <typename T>
int reflexVertex(const PlaneNodes<FaceType::Quad4, T>& p, double areaTolerance) {
  std::array<double, 4> turn{};
  double area = 0.0;
  for (int k = 0; k < 4; ++k) {
    const auto& a = p[k];
    const auto& b = p[(k + 1) % 4];
    const auto& c = p[(k + 2) % 4];
    turn[(k + 1) % 4] = valueOf(T((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])));
    area += valueOf(T(a[0] * b[1] - b[0] * a[1]));
  }
  const double sign = area >= 0 ? 1.0 : -1.0;
  int against = 0, first = -1;
  for (int k = 0; k < 4; ++k)
    if (sign * turn[k] < -areaTolerance) {
      ++against;
      if (first < 0) first = k;
    }
  if (against == 0) return -1;
  return against == 1 ? first : -2;
}

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
          const auto grad = faceShapeGradients<S, T>(xi1);
          Vec3<T> tx{T(0.0), T(0.0), T(0.0)}, ty{T(0.0), T(0.0), T(0.0)};
          for (int a = 0; a < nS; ++a)
            for (int i = 0; i < 3; ++i) {
              tx[i] += grad[a][0] * xs[a][i];
              ty[i] += grad[a][1] * xs[a][i];
            }
          const Vec3<T> nx = cross(tx, ty);
          dA *= sqrt(dot(nx, nx)) / dot(nx, n0);
        }
        for (int j = 0; j < nS; ++j) {
          const T pw = phi[j] * dA;
          out.D[j] += pw;
          out.gap[j] += pw * gn;
          for (int l = 0; l < nM; ++l) out.M[j][l] += pw * N2[l];
        }
        out.area += dA;
      }
    }
  }
  return out;
}

template <FaceType S, FaceType Mf>
MortarSegment3DLinearization<S, Mf> linearizeSegment3D(const FaceNodes<S, double>& xs,
                                                       const FaceNodes<S, double>& ns,
                                                       const FaceNodes<Mf, double>& xm, double relativeTolerance) {
  constexpr int nS = FaceTraits<S>::nodes;
  constexpr int nM = FaceTraits<Mf>::nodes;
  constexpr int nI = segment3DInputs<S, Mf>;
  using Fad = SegmentFad3D<S, Mf>;
  FaceNodes<S, Fad> fxs, fns;
  FaceNodes<Mf, Fad> fxm;
  for (int a = 0; a < nS; ++a)
    for (int i = 0; i < 3; ++i) {
      fxs[a][i] = Fad(nI, 3 * a + i, xs[a][i]);
      fns[a][i] = Fad(nI, 3 * nS + 3 * a + i, ns[a][i]);
    }
  for (int a = 0; a < nM; ++a)
    for (int i = 0; i < 3; ++i) fxm[a][i] = Fad(nI, 6 * nS + 3 * a + i, xm[a][i]);
  const MortarSegment3D<S, Mf, Fad> r = integrateSegment3D<S, Mf, Fad>(fxs, fns, fxm, relativeTolerance);

  MortarSegment3DLinearization<S, Mf> lin;
  lin.value.contributes = r.contributes;
  lin.value.polygonVertices = r.polygonVertices;
  lin.value.area = r.area.val();
  for (int i = 0; i < nI; ++i) lin.dArea[i] = r.area.dx(i);
  for (int j = 0; j < nS; ++j) {
    lin.value.D[j] = r.D[j].val();
    lin.value.gap[j] = r.gap[j].val();
    for (int i = 0; i < nI; ++i) {
      lin.dD[j][i] = r.D[j].dx(i);
      lin.dGap[j][i] = r.gap[j].dx(i);
    }
    for (int l = 0; l < nM; ++l) {
      lin.value.M[j][l] = r.M[j][l].val();
      for (int i = 0; i < nI; ++i) lin.dM[j][l][i] = r.M[j][l].dx(i);
    }
  }
  return lin;
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
