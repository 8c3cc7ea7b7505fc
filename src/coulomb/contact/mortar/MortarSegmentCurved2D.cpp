/// @file MortarSegmentCurved2D.cpp
/// @brief Segment-based mortar integration of 2D pairs with a Line3 face (see the header).
#include "coulomb/contact/mortar/MortarSegmentCurved2D.hpp"
#include "coulomb/contact/mortar/MortarSegment2D.hpp"

#include <Sacado.hpp>

#include <cmath>
#include <utility>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
constexpr double kTwoPi = 6.283185307179586;

template <typename T>
double valueOf(const T& x) {
  return Sacado::ScalarValue<T>::eval(x);
}

template <typename T>
T cross(const std::array<T, 2>& a, const std::array<T, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

struct Gauss5 {
  std::array<double, 5> x{}, w{};
  Gauss5() {
    const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    x = {-b, -a, 0.0, a, b};
    w = {wb, wa, 128.0 / 225.0, wa, wb};
  }
};

const Gauss5& gauss5() {
  static const Gauss5 rule;
  return rule;
}

/// sum_a f[a] v[a] for nodal 2-vectors v.
template <FaceType F, typename T, typename W>
std::array<T, 2> combine(const W& f, const FaceNodes<F, T>& v) {
  std::array<T, 2> out{T(0.0), T(0.0)};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a)
    for (int i = 0; i < 2; ++i) out[i] += f[a] * v[a][i];
  return out;
}

/// Nodal values in doubles.
template <FaceType F, typename T>
FaceNodes<F, double> values(const FaceNodes<F, T>& v) {
  FaceNodes<F, double> out{};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a)
    for (int i = 0; i < 2; ++i) out[a][i] = valueOf(v[a][i]);
  return out;
}

/// xi with (p - x^1(xi)) × n(xi) = 0 on the slave (Newton in doubles from the
/// chord projection, then one step in T). False when it does not converge.
template <FaceType S, typename T>
bool projectOntoSlave(const std::array<T, 2>& p, const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns, T& xi) {
  const FaceNodes<S, double> xd = values<S>(xs), nd = values<S>(ns);
  const std::array<double, 2> pd{valueOf(p[0]), valueOf(p[1])};
  auto residual = [&](double s, double& f, double& df) {
    const FacePoint<S, double> at{s};
    const auto N = faceShapeValues<S, double>(at);
    const auto G = faceShapeGradients<S, double>(at);
    NodalValues<S, double> dN{};
    for (int a = 0; a < FaceTraits<S>::nodes; ++a) dN[a] = G[a][0];
    const auto x = combine<S, double>(N, xd), dx = combine<S, double>(dN, xd);
    const auto n = combine<S, double>(N, nd), dn = combine<S, double>(dN, nd);
    const std::array<double, 2> r{pd[0] - x[0], pd[1] - x[1]};
    f = cross(r, n);
    df = cross(std::array<double, 2>{-dx[0], -dx[1]}, n) + cross(r, dn);
  };
  const std::array<double, 2> chord{xd[1][0] - xd[0][0], xd[1][1] - xd[0][1]};
  const double c2 = chord[0] * chord[0] + chord[1] * chord[1];
  double s = 2.0 * ((pd[0] - xd[0][0]) * chord[0] + (pd[1] - xd[0][1]) * chord[1]) / c2 - 1.0;
  bool converged = false;
  for (int it = 0; it < 50 && !converged; ++it) {
    double f = 0, df = 0;
    residual(s, f, df);
    if (!(std::abs(df) > 1e-14 * c2)) return false;
    const double step = f / df;
    s -= step;
    converged = projectionConverged(step, s);  // MortarSegment2D.hpp
  }
  if (!converged || !std::isfinite(s)) return false;
  const FacePoint<S, T> at{T(s)};
  const auto N = faceShapeValues<S, T>(at);
  const auto G = faceShapeGradients<S, T>(at);
  NodalValues<S, T> dN{};
  for (int a = 0; a < FaceTraits<S>::nodes; ++a) dN[a] = G[a][0];
  const auto x = combine<S, T>(N, xs), dx = combine<S, T>(dN, xs);
  const auto n = combine<S, T>(N, ns), dn = combine<S, T>(dN, ns);
  const std::array<T, 2> r{T(p[0] - x[0]), T(p[1] - x[1])};
  const T f = cross(r, n);
  const T df = cross(std::array<T, 2>{T(-dx[0]), T(-dx[1])}, n) + cross(r, dn);
  xi = T(s) - f / df;
  return true;
}

/// eta with (x^2(eta) - x1) × n = 0 on the master (Newton in doubles from
/// the chord, then one step in T).
template <FaceType Mf, typename T>
bool projectOntoMaster(const std::array<T, 2>& x1, const std::array<T, 2>& n, const FaceNodes<Mf, T>& xm, T& eta) {
  const FaceNodes<Mf, double> xd = values<Mf>(xm);
  const std::array<double, 2> pd{valueOf(x1[0]), valueOf(x1[1])}, nd{valueOf(n[0]), valueOf(n[1])};
  auto residual = [&](double s, double& f, double& df) {
    const FacePoint<Mf, double> at{s};
    const auto N = faceShapeValues<Mf, double>(at);
    const auto G = faceShapeGradients<Mf, double>(at);
    NodalValues<Mf, double> dN{};
    for (int a = 0; a < FaceTraits<Mf>::nodes; ++a) dN[a] = G[a][0];
    const auto x = combine<Mf, double>(N, xd), dx = combine<Mf, double>(dN, xd);
    f = cross(std::array<double, 2>{x[0] - pd[0], x[1] - pd[1]}, nd);
    df = cross(dx, nd);
  };
  double s = 0.0, f = 0.0, df = 0.0;
  bool converged = false;
  for (int it = 0; it < 50 && !converged; ++it) {
    residual(s, f, df);
    if (!(std::abs(df) > 0.0)) return false;
    const double step = f / df;
    s -= step;
    converged = projectionConverged(step, s);  // MortarSegment2D.hpp
  }
  if (!converged || !std::isfinite(s)) return false;
  const FacePoint<Mf, T> at{T(s)};
  const auto N = faceShapeValues<Mf, T>(at);
  const auto G = faceShapeGradients<Mf, T>(at);
  NodalValues<Mf, T> dN{};
  for (int a = 0; a < FaceTraits<Mf>::nodes; ++a) dN[a] = G[a][0];
  const auto x = combine<Mf, T>(N, xm), dx = combine<Mf, T>(dN, xm);
  const T fT = cross(std::array<T, 2>{T(x[0] - x1[0]), T(x[1] - x1[1])}, n);
  eta = T(s) - fT / cross(dx, n);
  return true;
}

/// A = D_e M_e^-1 by Gauss-Jordan on the (at most 3 x 3) symmetric M_e.
template <FaceType S, typename T>
NodalMatrix<S, T> dualOf(const FaceMass<S, T>& mass) {
  constexpr int n = FaceTraits<S>::nodes;
  NodalMatrix<S, T> M = mass.Me, inverse{};
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) inverse[j][k] = j == k ? 1.0 : 0.0;
  for (int c = 0; c < n; ++c) {
    COULOMB_REQUIRE(valueOf(M[c][c]) > 0.0, "dual basis: degenerate slave face (element mass matrix singular)");
    const T pivot = M[c][c];
    for (int k = 0; k < n; ++k) {
      M[c][k] /= pivot;
      inverse[c][k] /= pivot;
    }
    for (int r = 0; r < n; ++r) {
      if (r == c) continue;
      const T factor = M[r][c];
      for (int k = 0; k < n; ++k) {
        M[r][k] -= factor * M[c][k];
        inverse[r][k] -= factor * inverse[c][k];
      }
    }
  }
  NodalMatrix<S, T> A{};
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) A[j][k] = mass.De[j] * inverse[j][k];
  return A;
}

}  // namespace

template <FaceType S, typename T>
FaceMass<S, T> lineMass(const FaceNodes<S, T>& xs, bool axisymmetric) {
  using std::sqrt;
  constexpr int n = FaceTraits<S>::nodes;
  FaceMass<S, T> mass;
  for (int j = 0; j < n; ++j) {
    mass.De[j] = 0.0;
    for (int k = 0; k < n; ++k) mass.Me[j][k] = 0.0;
  }
  const Gauss5& rule = gauss5();
  for (int q = 0; q < 5; ++q) {
    const FacePoint<S, double> at{rule.x[q]};
    const auto N = faceShapeValues<S, double>(at);
    const auto G = faceShapeGradients<S, double>(at);
    NodalValues<S, double> dN{};
    for (int a = 0; a < n; ++a) dN[a] = G[a][0];
    const auto dx = combine<S, T>(dN, xs);
    T dA = rule.w[q] * sqrt(dx[0] * dx[0] + dx[1] * dx[1]);
    if (axisymmetric) dA *= kTwoPi * combine<S, T>(N, xs)[0];
    for (int j = 0; j < n; ++j) {
      mass.De[j] += N[j] * dA;
      for (int k = 0; k < n; ++k) mass.Me[j][k] += N[j] * N[k] * dA;
    }
  }
  return mass;
}

template <FaceType S, FaceType Mf, typename T>
MortarSegmentCurved2D<S, Mf, T> integrateCurvedSegment2D(const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns,
                                                         const FaceNodes<Mf, T>& xm, double relativeTolerance,
                                                         bool axisymmetric) {
  using std::sqrt;
  using Out = MortarSegmentCurved2D<S, Mf, T>;
  Out out;
  for (int j = 0; j < Out::nS; ++j) {
    out.D[j] = 0.0;
    out.gap[j] = 0.0;
    for (int l = 0; l < Out::nM; ++l) out.M[j][l] = 0.0;
  }
  out.length = 0.0;
  // Overlap: the projections of the master's corners (nodes 0 and 1).
  std::array<T, 2> xiProj{};
  for (int l = 0; l < 2; ++l)
    if (!projectOntoSlave<S, T>(xm[l], xs, ns, xiProj[l])) return out;
  T lo = xiProj[0], hi = xiProj[1];
  if (valueOf(lo) > valueOf(hi)) std::swap(lo, hi);
  if (valueOf(lo) < -1.0) lo = -1.0;
  if (valueOf(hi) > 1.0) hi = 1.0;
  if (!(valueOf(hi) - valueOf(lo) > 2.0 * relativeTolerance)) return out;

  const NodalMatrix<S, T> A = dualOf<S, T>(lineMass<S, T>(xs, axisymmetric));
  const T half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  const Gauss5& rule = gauss5();
  Out sum = out;
  for (int g = 0; g < 5; ++g) {
    const FacePoint<S, T> xi{T(mid + half * rule.x[g])};
    const auto N = faceShapeValues<S, T>(xi);
    const auto G = faceShapeGradients<S, T>(xi);
    NodalValues<S, T> dN{};
    for (int a = 0; a < Out::nS; ++a) dN[a] = G[a][0];
    const auto x1 = combine<S, T>(N, xs), dx1 = combine<S, T>(dN, xs), n = combine<S, T>(N, ns);
    T w = rule.w[g] * half * sqrt(dx1[0] * dx1[0] + dx1[1] * dx1[1]);
    if (axisymmetric) w *= kTwoPi * x1[0];
    T eta{};
    if (!projectOntoMaster<Mf, T>(x1, n, xm, eta)) return out;
    const auto N2 = faceShapeValues<Mf, T>(FacePoint<Mf, T>{eta});
    const auto x2 = combine<Mf, T>(N2, xm);
    const T gn = ((x2[0] - x1[0]) * n[0] + (x2[1] - x1[1]) * n[1]) / sqrt(n[0] * n[0] + n[1] * n[1]);
    const NodalValues<S, T> phi = dualShapeValues<S, T, T>(A, xi);
    for (int j = 0; j < Out::nS; ++j) {
      const T pw = phi[j] * w;
      sum.D[j] += pw;
      sum.gap[j] += pw * gn;
      for (int l = 0; l < Out::nM; ++l) sum.M[j][l] += pw * N2[l];
    }
    sum.length += w;
  }
  sum.contributes = true;
  sum.slaveInterval = {valueOf(lo), valueOf(hi)};
  return sum;
}

template <FaceType S, FaceType Mf>
MortarSegmentCurved2DLinearization<S, Mf> linearizeCurvedSegment2D(const FaceNodes<S, double>& xs,
                                                                   const FaceNodes<S, double>& ns,
                                                                   const FaceNodes<Mf, double>& xm,
                                                                   double relativeTolerance, bool axisymmetric) {
  using Lin = MortarSegmentCurved2DLinearization<S, Mf>;
  using Fad = Sacado::Fad::SFad<double, Lin::N>;
  constexpr int nS = Lin::nS, nM = Lin::nM;
  FaceNodes<S, Fad> fxs, fns;
  FaceNodes<Mf, Fad> fxm;
  for (int a = 0; a < nS; ++a)
    for (int i = 0; i < 2; ++i) {
      fxs[a][i] = Fad(Lin::N, 2 * a + i, xs[a][i]);
      fns[a][i] = Fad(Lin::N, 2 * nS + 2 * a + i, ns[a][i]);
    }
  for (int l = 0; l < nM; ++l)
    for (int i = 0; i < 2; ++i) fxm[l][i] = Fad(Lin::N, 4 * nS + 2 * l + i, xm[l][i]);
  const auto r = integrateCurvedSegment2D<S, Mf, Fad>(fxs, fns, fxm, relativeTolerance, axisymmetric);
  Lin lin;
  lin.value.contributes = r.contributes;
  lin.value.slaveInterval = r.slaveInterval;
  lin.value.length = r.length.val();
  for (int i = 0; i < Lin::N; ++i) lin.dLength[i] = r.length.dx(i);
  for (int j = 0; j < nS; ++j) {
    lin.value.D[j] = r.D[j].val();
    lin.value.gap[j] = r.gap[j].val();
    for (int i = 0; i < Lin::N; ++i) {
      lin.dD[j][i] = r.D[j].dx(i);
      lin.dGap[j][i] = r.gap[j].dx(i);
    }
    for (int l = 0; l < nM; ++l) {
      lin.value.M[j][l] = r.M[j][l].val();
      for (int i = 0; i < Lin::N; ++i) lin.dM[j][l][i] = r.M[j][l].dx(i);
    }
  }
  return lin;
}

#define COULOMB_CURVED_2D_INSTANTIATE(S, Mf)                                                                       \
  template MortarSegmentCurved2D<S, Mf, double> integrateCurvedSegment2D<S, Mf, double>(                          \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double, bool);      \
  template MortarSegmentCurved2DLinearization<S, Mf> linearizeCurvedSegment2D<S, Mf>(                             \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double, bool);
COULOMB_CURVED_2D_INSTANTIATE(FaceType::Line2, FaceType::Line2)
COULOMB_CURVED_2D_INSTANTIATE(FaceType::Line2, FaceType::Line3)
COULOMB_CURVED_2D_INSTANTIATE(FaceType::Line3, FaceType::Line2)
COULOMB_CURVED_2D_INSTANTIATE(FaceType::Line3, FaceType::Line3)
#undef COULOMB_CURVED_2D_INSTANTIATE
template FaceMass<FaceType::Line2, double> lineMass<FaceType::Line2, double>(const FaceNodes<FaceType::Line2, double>&, bool);
template FaceMass<FaceType::Line3, double> lineMass<FaceType::Line3, double>(const FaceNodes<FaceType::Line3, double>&, bool);

}  // namespace coulomb::contact
