#pragma once
/// @file AuxiliaryPlane.hpp
/// @brief The geometry helpers of the auxiliary-plane mortar kernels
/// (MortarSegment3D.cpp, MortarSegmentQuadratic3D.cpp): 3-vectors, the
/// 7-point triangle rule, the inverse of a face map projected onto the
/// plane, the convexity test of a projected quadrilateral, and the Sacado
/// linearization of a kernel. Includes
/// Sacado: for .cpp files only.
#include <Sacado.hpp>

#include <array>
#include <cmath>
#include <type_traits>

#include "coulomb/contact/mortar/DualBasis.hpp"
#include "coulomb/contact/mortar/MortarScalarTypes.hpp"
#include "coulomb/contact/mortar/MortarSegment3D.hpp"
#include "coulomb/contact/mortar/PolygonClipping.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact::plane {

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

inline const TriangleRule7& triangleRule7() {
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
    const double size = planeNorm(nd[2][0] - nd[0][0], nd[2][1] - nd[0][1]) +
                        planeNorm(nd[3][0] - nd[1][0], nd[3][1] - nd[1][1]);
    // Damped Newton from the centre: a step is at most 0.5 in xi and is
    // halved until |F| decreases, so an iterate never jumps far outside the
    // face where the bilinear map folds. Points are inside the (convex)
    // projected face, where the map is invertible.
    FacePoint<F, double> xi{0.0, 0.0};
    std::array<double, 2> Fd{};
    std::array<std::array<double, 2>, 2> Jd{};
    residual(nd, pd, xi, Fd, Jd);
    double norm = planeNorm(Fd[0], Fd[1]);
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
      double trialNorm = planeNorm(Fd[0], Fd[1]);
      for (int halving = 0; halving < 20 && !converged && !(trialNorm < norm); ++halving) {
        d0 *= 0.5, d1 *= 0.5;
        trial = {xi[0] - d0, xi[1] - d1};
        residual(nd, pd, trial, Fd, Jd);
        trialNorm = planeNorm(Fd[0], Fd[1]);
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


/// x_xi × x_eta of the face with nodes `x` at the point of shape gradients `grad`.
template <FaceType F, typename T>
Vec3<T> tangentNormal(const std::array<std::array<T, 2>, FaceTraits<F>::nodes>& grad, const FaceNodes<F, T>& x) {
  Vec3<T> tx{T(0.0), T(0.0), T(0.0)}, ty{T(0.0), T(0.0), T(0.0)};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a)
    for (int i = 0; i < 3; ++i) {
      tx[i] += grad[a][0] * x[a][i];
      ty[i] += grad[a][1] * x[a][i];
    }
  return cross(tx, ty);
}

/// One Gauss point of a segment: D_j += Phi_j dA, g~_j += Phi_j g_n dA,
/// M_jl += Phi_j N^2_l dA, the overlap area += dA.
template <FaceType S, FaceType Mf, typename T>
void addGaussPoint(MortarSegment3D<S, Mf, T>& out, const NodalValues<S, T>& phi, const NodalValues<Mf, T>& N2,
                   const T& gn, const T& dA) {
  for (int j = 0; j < FaceTraits<S>::nodes; ++j) {
    const T pw = phi[j] * dA;
    out.D[j] += pw;
    out.gap[j] += pw * gn;
    for (int l = 0; l < FaceTraits<Mf>::nodes; ++l) out.M[j][l] += pw * N2[l];
  }
  out.area += dA;
}

/// Values and derivatives of a 3D segment kernel: `integrate(xs, ns, xm)`
/// called on Sacado SFad scalars seeded with the inputs in the order of
/// MortarSegment3DLinearization (slave coordinates, slave normals, master
/// coordinates), the values and derivatives read off.
template <FaceType S, FaceType Mf, class Integrate>
MortarSegment3DLinearization<S, Mf> linearize3D(const FaceNodes<S, double>& xs, const FaceNodes<S, double>& ns,
                                                const FaceNodes<Mf, double>& xm, Integrate&& integrate) {
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
  const MortarSegment3D<S, Mf, Fad> r = integrate(fxs, fns, fxm);
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

}  // namespace coulomb::contact::plane
