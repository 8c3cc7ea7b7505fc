/// @file MortarSegment2D.cpp
/// @brief Segment-based mortar integration of a Line2 pair (see the header for the equations).
#include "coulomb/contact/mortar/MortarSegment2D.hpp"

#include "coulomb/contact/mortar/MortarScalarTypes.hpp"

#include <cmath>
#include <utility>

namespace coulomb::contact {
namespace {

using Fad12 = SegmentFad2D;
constexpr mesh::FaceType kLine = mesh::FaceType::Line2;
constexpr double kTwoPi = 6.283185307179586;

template <typename T>
double valueOf(const T& x) {
  return Sacado::ScalarValue<T>::eval(x);
}

/// a × b = a_x b_y - a_y b_x.
template <typename T>
T cross(const std::array<T, 2>& a, const std::array<T, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

/// 5-point Gauss–Legendre rule on [-1, 1].
struct GaussLegendre5 {
  std::array<double, 5> x{}, w{};
  GaussLegendre5() {
    const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
    const double wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    x = {-b, -a, 0.0, a, b};
    w = {wb, wa, 128.0 / 225.0, wa, wb};
  }
};

const GaussLegendre5& gaussLegendre5() {
  static const GaussLegendre5 rule;
  return rule;
}

/// Projection of the point p onto the slave segment along the normal field:
/// solves f(xi) = (p - c - xi d) × (a + xi b) = 0, where x^1(xi) = c + xi d and
/// n(xi) = a + xi b. Newton on the double values from the orthogonal projection,
/// then one Newton step in T at the converged point, which carries the exact
/// derivative dxi = -(df/dinputs)/f'(xi) (implicit function theorem).
template <typename T>
bool projectOntoSlave(const std::array<T, 2>& p, const std::array<T, 2>& c, const std::array<T, 2>& d,
                      const std::array<T, 2>& a, const std::array<T, 2>& b, T& xi) {
  const std::array<double, 2> pd{valueOf(p[0]), valueOf(p[1])}, cd{valueOf(c[0]), valueOf(c[1])},
      dd{valueOf(d[0]), valueOf(d[1])}, ad{valueOf(a[0]), valueOf(a[1])}, bd{valueOf(b[0]), valueOf(b[1])};
  auto fd = [&](double s) {
    const std::array<double, 2> r{pd[0] - cd[0] - s * dd[0], pd[1] - cd[1] - s * dd[1]};
    const std::array<double, 2> n{ad[0] + s * bd[0], ad[1] + s * bd[1]};
    return std::array<double, 2>{cross(r, n), cross(std::array<double, 2>{-dd[0], -dd[1]}, n) + cross(r, bd)};
  };
  const double dd2 = dd[0] * dd[0] + dd[1] * dd[1];
  double s = ((pd[0] - cd[0]) * dd[0] + (pd[1] - cd[1]) * dd[1]) / dd2;
  bool converged = false;
  for (int it = 0; it < 50 && !converged; ++it) {
    const std::array<double, 2> v = fd(s);
    if (!(std::abs(v[1]) > 1e-14 * dd2)) return false;  // normal field parallel to the line
    const double step = v[0] / v[1];
    s -= step;
    converged = projectionConverged(step, s);  // MortarSegment2D.hpp
  }
  if (!converged || !std::isfinite(s)) return false;
  const T sT = s;
  const std::array<T, 2> r{T(p[0] - c[0] - sT * d[0]), T(p[1] - c[1] - sT * d[1])};
  const std::array<T, 2> n{T(a[0] + sT * b[0]), T(a[1] + sT * b[1])};
  const std::array<T, 2> minusD{T(-d[0]), T(-d[1])};
  const T f = cross(r, n);
  const T df = cross(minusD, n) + cross(r, b);
  xi = sT - f / df;
  return true;
}

}  // namespace

template <typename T>
FaceMass<kLine, T> ringMass(const Line2Nodes<T>& xs) {
  using std::sqrt;
  const T r0 = xs[0][0], r1 = xs[1][0];
  const T dx = xs[1][0] - xs[0][0], dy = xs[1][1] - xs[0][1];
  const T scale = kTwoPi * sqrt(dx * dx + dy * dy) / 12.0;
  FaceMass<kLine, T> mass;
  mass.De = {T(scale * 2.0 * (2.0 * r0 + r1)), T(scale * 2.0 * (r0 + 2.0 * r1))};
  mass.Me[0] = {T(scale * (3.0 * r0 + r1)), T(scale * (r0 + r1))};
  mass.Me[1] = {T(scale * (r0 + r1)), T(scale * (r0 + 3.0 * r1))};
  return mass;
}

template <typename T>
NodalMatrix<kLine, T> axisymmetricDual(const Line2Nodes<T>& xs) {
  const FaceMass<kLine, T> m = ringMass<T>(xs);
  const T det = m.Me[0][0] * m.Me[1][1] - m.Me[0][1] * m.Me[1][0];
  NodalMatrix<kLine, T> A;  // A = D_e M_e^-1 (M_e symmetric)
  A[0] = {T(m.De[0] * m.Me[1][1] / det), T(-m.De[0] * m.Me[0][1] / det)};
  A[1] = {T(-m.De[1] * m.Me[1][0] / det), T(m.De[1] * m.Me[0][0] / det)};
  return A;
}

template <typename T>
MortarSegment2D<T> integrateSegment2D(const Line2Nodes<T>& xs, const Line2Nodes<T>& ns, const Line2Nodes<T>& xm,
                                      double relativeTolerance, bool axisymmetric) {
  using std::sqrt;
  MortarSegment2D<T> out;
  for (int j = 0; j < 2; ++j) {
    out.D[j] = 0.0;
    out.gap[j] = 0.0;
    out.M[j] = {T(0.0), T(0.0)};
  }
  out.length = 0.0;

  // Slave x^1(xi) = c + xi d, normal field n(xi) = a + xi b; master x^2(xi2) = cm + xi2 dm.
  const std::array<T, 2> c{T(0.5 * (xs[0][0] + xs[1][0])), T(0.5 * (xs[0][1] + xs[1][1]))};
  const std::array<T, 2> d{T(0.5 * (xs[1][0] - xs[0][0])), T(0.5 * (xs[1][1] - xs[0][1]))};
  const std::array<T, 2> a{T(0.5 * (ns[0][0] + ns[1][0])), T(0.5 * (ns[0][1] + ns[1][1]))};
  const std::array<T, 2> b{T(0.5 * (ns[1][0] - ns[0][0])), T(0.5 * (ns[1][1] - ns[0][1]))};
  const std::array<T, 2> cm{T(0.5 * (xm[0][0] + xm[1][0])), T(0.5 * (xm[0][1] + xm[1][1]))};
  const std::array<T, 2> dm{T(0.5 * (xm[1][0] - xm[0][0])), T(0.5 * (xm[1][1] - xm[0][1]))};

  // Overlap: projections of the master nodes onto the slave, cut to [-1, 1].
  std::array<T, 2> xiProj{};
  for (int l = 0; l < 2; ++l)
    if (!projectOntoSlave(xm[l], c, d, a, b, xiProj[l])) return out;
  T lo = xiProj[0], hi = xiProj[1];
  if (valueOf(lo) > valueOf(hi)) std::swap(lo, hi);
  if (valueOf(lo) < -1.0) lo = -1.0;
  if (valueOf(hi) > 1.0) hi = 1.0;
  if (!(valueOf(hi) - valueOf(lo) > 2.0 * relativeTolerance)) return out;
  out.contributes = true;
  out.slaveInterval = {valueOf(lo), valueOf(hi)};

  const NodalMatrix<kLine, T> A = axisymmetric ? axisymmetricDual<T>(xs) : dualCoefficients<kLine, T>(xs);
  const T J = sqrt(d[0] * d[0] + d[1] * d[1]);  // |dx^1/dxi|, constant on a straight segment
  const T half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  const GaussLegendre5& rule = gaussLegendre5();
  for (int g = 0; g < 5; ++g) {
    const FacePoint<kLine, T> xi{T(mid + half * rule.x[g])};
    const std::array<T, 2> x1{T(c[0] + xi[0] * d[0]), T(c[1] + xi[0] * d[1])};
    const T w = rule.w[g] * half * J * (axisymmetric ? T(kTwoPi * x1[0]) : T(1.0));
    const NodalValues<kLine, T> phi = dualShapeValues<kLine, T, T>(A, xi);
    const std::array<T, 2> n{T(a[0] + xi[0] * b[0]), T(a[1] + xi[0] * b[1])};
    // (cm + xi2 dm - x1) × n = 0.
    const std::array<T, 2> r{T(x1[0] - cm[0]), T(x1[1] - cm[1])};
    const FacePoint<kLine, T> xi2{T(cross(r, n) / cross(dm, n))};
    const NodalValues<kLine, T> N2 = faceShapeValues<kLine, T>(xi2);
    const std::array<T, 2> x2{T(cm[0] + xi2[0] * dm[0]), T(cm[1] + xi2[0] * dm[1])};
    const T gn = ((x2[0] - x1[0]) * n[0] + (x2[1] - x1[1]) * n[1]) / sqrt(n[0] * n[0] + n[1] * n[1]);
    for (int j = 0; j < 2; ++j) {
      const T pw = phi[j] * w;
      out.D[j] += pw;
      out.gap[j] += pw * gn;
      for (int l = 0; l < 2; ++l) out.M[j][l] += pw * N2[l];
    }
    out.length += w;
  }
  return out;
}

MortarSegment2DLinearization linearizeSegment2D(const Line2Nodes<double>& xs, const Line2Nodes<double>& ns,
                                                const Line2Nodes<double>& xm, double relativeTolerance,
                                                bool axisymmetric) {
  Line2Nodes<Fad12> fxs, fns, fxm;
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < 2; ++i) {
      fxs[a][i] = Fad12(kSegment2DInputs, 2 * a + i, xs[a][i]);
      fns[a][i] = Fad12(kSegment2DInputs, 4 + 2 * a + i, ns[a][i]);
      fxm[a][i] = Fad12(kSegment2DInputs, 8 + 2 * a + i, xm[a][i]);
    }
  const MortarSegment2D<Fad12> r = integrateSegment2D<Fad12>(fxs, fns, fxm, relativeTolerance, axisymmetric);
  MortarSegment2DLinearization lin;
  lin.value.contributes = r.contributes;
  lin.value.slaveInterval = r.slaveInterval;
  lin.value.length = r.length.val();
  for (int i = 0; i < kSegment2DInputs; ++i) lin.dLength[i] = r.length.dx(i);
  for (int j = 0; j < 2; ++j) {
    lin.value.D[j] = r.D[j].val();
    lin.value.gap[j] = r.gap[j].val();
    for (int i = 0; i < kSegment2DInputs; ++i) {
      lin.dD[j][i] = r.D[j].dx(i);
      lin.dGap[j][i] = r.gap[j].dx(i);
    }
    for (int l = 0; l < 2; ++l) {
      lin.value.M[j][l] = r.M[j][l].val();
      for (int i = 0; i < kSegment2DInputs; ++i) lin.dM[j][l][i] = r.M[j][l].dx(i);
    }
  }
  return lin;
}

template MortarSegment2D<double> integrateSegment2D<double>(const Line2Nodes<double>&, const Line2Nodes<double>&,
                                                            const Line2Nodes<double>&, double, bool);
template MortarSegment2D<Fad12> integrateSegment2D<Fad12>(const Line2Nodes<Fad12>&, const Line2Nodes<Fad12>&,
                                                          const Line2Nodes<Fad12>&, double, bool);
template NodalMatrix<kLine, double> axisymmetricDual<double>(const Line2Nodes<double>&);
template FaceMass<kLine, double> ringMass<double>(const Line2Nodes<double>&);

}  // namespace coulomb::contact
