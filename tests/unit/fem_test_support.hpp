#pragma once
// Shared helpers of the fem_*.cpp unit tests: test geometries, closed-form
// continuum mechanics written independently of the kernels, small dense linear algebra.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "coulomb/fem/ElementKernel.hpp"
#include "coulomb/fem/FaceKernel.hpp"
#include "coulomb/fem/FaceTopology.hpp"
#include "coulomb/fem/ShapeFunctions.hpp"
#include "coulomb/mesh/CellType.hpp"

namespace coulomb::fem::test {

using mesh::CellType;
using mesh::FaceType;

/// Type tag so the cell types can drive GoogleTest typed tests.
template <CellType T>
struct Cell {
  static constexpr CellType type = T;
  static constexpr int nodes = CellTraits<T>::nodes, dim = CellTraits<T>::dim, dofs = CellTraits<T>::dofs;
  using Vec = std::array<double, dofs>;
  using Mat = std::array<double, dofs * dofs>;
};
using AllCells = ::testing::Types<Cell<CellType::Quad4>, Cell<CellType::Tri3>, Cell<CellType::Hex8>, Cell<CellType::Tet4>,
                                  Cell<CellType::Quad8>, Cell<CellType::Quad9>, Cell<CellType::Tri6>,
                                  Cell<CellType::Hex20>, Cell<CellType::Hex27>, Cell<CellType::Tet10>>;

/// Calls visit(std::integral_constant<FaceType, F>) with the face type of side `side` of a T cell.
template <CellType T, typename Visit>
void visitFace(int side, Visit&& visit) {
  switch (faceType(T, side)) {
    case FaceType::Line2: if constexpr (CellTraits<T>::dim == 2) visit(std::integral_constant<FaceType, FaceType::Line2>{}); break;
    case FaceType::Line3: if constexpr (CellTraits<T>::dim == 2) visit(std::integral_constant<FaceType, FaceType::Line3>{}); break;
    case FaceType::Tri3: if constexpr (CellTraits<T>::dim == 3) visit(std::integral_constant<FaceType, FaceType::Tri3>{}); break;
    case FaceType::Quad4: if constexpr (CellTraits<T>::dim == 3) visit(std::integral_constant<FaceType, FaceType::Quad4>{}); break;
    case FaceType::Tri6: if constexpr (CellTraits<T>::dim == 3) visit(std::integral_constant<FaceType, FaceType::Tri6>{}); break;
    case FaceType::Quad8: if constexpr (CellTraits<T>::dim == 3) visit(std::integral_constant<FaceType, FaceType::Quad8>{}); break;
    case FaceType::Quad9: if constexpr (CellTraits<T>::dim == 3) visit(std::integral_constant<FaceType, FaceType::Quad9>{}); break;
  }
}

struct CellNames {
  template <typename C>
  static std::string GetName(int) {
    return mesh::toString(C::type);
  }
};

/// Reference-element node coordinates (Exodus order).
template <CellType T>
std::array<double, CellTraits<T>::dofs> referenceCoordinates() {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim;
  std::array<double, CellTraits<T>::dofs> X{};
  for (int a = 0; a < n; ++a) {
    const auto xi = referenceNode<CellTraits<T>::shape>(a);
    for (int i = 0; i < d; ++i) X[a * d + i] = xi[i];
  }
  return X;
}

/// \int N_a over the reference element, in closed form (not from the kernels' quadrature):
/// linear cells measure/nodes; QUAD9/HEX27 products of the 1D integrals 1/3 (ends) and 4/3
/// (middle); QUAD8 corners -1/3, edges 4/3; HEX20 corners -1, edges 4/3; TRI6 corners 0,
/// edges 1/6; TET10 corners -1/120, edges 1/30.
inline double referenceShapeIntegral(CellType t, int a) {
  const bool corner = a < mesh::numCorners(t);
  switch (t) {
    case CellType::Quad4: return 1.0;
    case CellType::Tri3: return 1.0 / 6.0;
    case CellType::Hex8: return 1.0;
    case CellType::Tet4: return 1.0 / 24.0;
    case CellType::Quad8: return corner ? -1.0 / 3.0 : 4.0 / 3.0;
    case CellType::Hex20: return corner ? -1.0 : 4.0 / 3.0;
    case CellType::Tri6: return corner ? 0.0 : 1.0 / 6.0;
    case CellType::Tet10: return corner ? -1.0 / 120.0 : 1.0 / 30.0;
    case CellType::Quad9:
    case CellType::Hex27: {
      double v = 1.0;
      const int d = mesh::spatialDimension(t);
      const mesh::NodeCorners c = mesh::nodeCorners(t, a);
      // a node between 2^k corners has k coordinates at 0 (middle), d - k at the ends
      const int middle = c.count == 1 ? 0 : c.count == 2 ? 1 : c.count == 4 ? 2 : 3;
      for (int i = 0; i < d; ++i) v *= i < middle ? 4.0 / 3.0 : 1.0 / 3.0;
      return v;
    }
  }
  return 0.0;
}

/// Deterministic pseudo-random number in [-1, 1] (no global state).
inline double wiggle(int a, int i, int seed = 0) { return std::sin(1.7 * a + 2.9 * i + 0.37 * seed + 0.5); }

/// Reference element, affinely stretched and sheared, then every node perturbed by up to
/// `amount` (relative to the element size): a genuinely distorted cell with det J > 0.
/// For the simplices any node perturbation is still affine.
template <CellType T>
std::array<double, CellTraits<T>::dofs> distortedCoordinates(double amount = 0.12, int seed = 0) {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim;
  const double M[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.15}, {-0.05, 0.1, 1.1}};
  const double shift[3] = {0.4, -0.3, 0.25};
  const auto R = referenceCoordinates<T>();
  std::array<double, CellTraits<T>::dofs> X{};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < d; ++i) {
      double v = shift[i] + amount * wiggle(a, i, seed);
      for (int j = 0; j < d; ++j) v += M[i][j] * R[a * d + j];
      X[a * d + i] = v;
    }
  return X;
}

/// Non-affine cell whose faces are all planar: the reference element under the projective
/// map x -> (M xi + s) / (1 + c . xi). Projective maps keep planes planar.
template <CellType T>
std::array<double, CellTraits<T>::dofs> projectiveCoordinates() {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim;
  const double M[3][3] = {{1.2, 0.15, -0.1}, {-0.1, 0.95, 0.2}, {0.05, -0.1, 1.05}};
  const double s[3] = {0.3, -0.2, 0.1};
  const double c[3] = {0.12, -0.08, 0.1};
  const auto R = referenceCoordinates<T>();
  std::array<double, CellTraits<T>::dofs> X{};
  for (int a = 0; a < n; ++a) {
    double den = 1.0;
    for (int j = 0; j < d; ++j) den += c[j] * R[a * d + j];
    for (int i = 0; i < d; ++i) {
      double v = s[i];
      for (int j = 0; j < d; ++j) v += M[i][j] * R[a * d + j];
      X[a * d + i] = v / den;
    }
  }
  return X;
}

/// Nodal values of the linear field u = A X + c (A row-major d x d).
template <CellType T>
std::array<double, CellTraits<T>::dofs> linearField(const std::array<double, CellTraits<T>::dofs>& X,
                                                     const std::vector<double>& A, const std::vector<double>& c) {
  constexpr int n = CellTraits<T>::nodes, d = CellTraits<T>::dim;
  std::array<double, CellTraits<T>::dofs> u{};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < d; ++i) {
      double v = c[i];
      for (int j = 0; j < d; ++j) v += A[i * d + j] * X[a * d + j];
      u[a * d + i] = v;
    }
  return u;
}

/// A fixed, full (non-symmetric) displacement gradient of size d x d, scaled by s.
inline std::vector<double> sampleGradient(int d, double s) {
  if (d == 2) return {0.3 * s, -0.2 * s, 0.15 * s, -0.1 * s};
  return {0.3 * s, -0.2 * s, 0.1 * s, 0.15 * s, -0.1 * s, 0.05 * s, -0.12 * s, 0.08 * s, 0.2 * s};
}

// ---- small dense linear algebra (row-major) -------------------------------------------

inline double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// Inverse of a 3x3 matrix by Gauss-Jordan elimination with partial pivoting.
inline void inverse3(const double m[3][3], double inv[3][3]) {
  double a[3][6];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = m[i][j];
      a[i][j + 3] = i == j ? 1.0 : 0.0;
    }
  for (int c = 0; c < 3; ++c) {
    int p = c;
    for (int r = c + 1; r < 3; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    for (int j = 0; j < 6; ++j) std::swap(a[c][j], a[p][j]);
    const double piv = a[c][c];
    for (int j = 0; j < 6; ++j) a[c][j] /= piv;
    for (int r = 0; r < 3; ++r)
      if (r != c) {
        const double f = a[r][c];
        for (int j = 0; j < 6; ++j) a[r][j] -= f * a[c][j];
      }
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inv[i][j] = a[i][j + 3];
}

/// Lame parameters, written out independently of the library.
inline void lame(double E, double nu, double& mu, double& lambda) {
  mu = E / (2.0 * (1.0 + nu));
  lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

/// Closed-form neo-Hookean first Piola and Cauchy stress of a 3x3 deformation gradient
/// (2D plane strain: embed with F_zz = 1): P = mu (F - F^{-T}) + lambda ln J F^{-T}.
inline void neoHookean3(double mu, double lambda, const double F[3][3], double P[3][3], double sigma[3][3]) {
  double Finv[3][3];
  inverse3(F, Finv);
  const double J = det3(F);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P[i][j] = mu * (F[i][j] - Finv[j][i]) + lambda * std::log(J) * Finv[j][i];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int k = 0; k < 3; ++k) s += P[i][k] * F[j][k];
      sigma[i][j] = s / J;
    }
}

/// Eigenvalues of a symmetric n x n matrix (cyclic Jacobi rotations).
inline std::vector<double> symmetricEigenvalues(std::vector<double> a, int n) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0, total = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) (i == j ? total : off) += a[i * n + j] * a[i * n + j];
    if (off <= 1e-30 * (total + off)) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (apq == 0.0) continue;
        const double theta = (a[q * n + q] - a[p * n + p]) / (2.0 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < n; ++k) {  // columns p, q
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = c * akp - s * akq;
          a[k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // rows p, q
          const double apk = a[p * n + k], aqk = a[q * n + k];
          a[p * n + k] = c * apk - s * aqk;
          a[q * n + k] = s * apk + c * aqk;
        }
      }
  }
  std::vector<double> ev(n);
  for (int i = 0; i < n; ++i) ev[i] = a[i * n + i];
  std::sort(ev.begin(), ev.end());
  return ev;
}

template <std::size_t N>
double maxAbs(const std::array<double, N>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// Geometric centroid of a set of nodes (average of node coordinates).
template <int D, std::size_t N>
std::array<double, D> nodeAverage(const std::array<double, N>& X, const int* nodes, int count) {
  std::array<double, D> c{};
  for (int k = 0; k < count; ++k)
    for (int i = 0; i < D; ++i) c[i] += X[nodes[k] * D + i] / count;
  return c;
}

/// The largest |K_ik - (r_i(u + h e_k) - r_i(u - h e_k)) / 2h| of a cell's
/// tangent K at u against central differences of its residual (h = 1e-6).
template <typename C>
double tangentDifferenceError(const MaterialParameters& m, const typename C::Vec& X, const typename C::Vec& u,
                              const typename C::Mat& K) {
  const double h = 1e-6;
  const std::array<double, C::dim> b{};
  double err = 0.0;
  for (int k = 0; k < C::dofs; ++k) {
    auto up = u, um = u;
    up[k] += h;
    um[k] -= h;
    typename C::Vec rp, rm;
    EXPECT_EQ(cellResidualTangent<C::type>(m, X, up, b, rp, nullptr), KernelStatus::Ok);
    EXPECT_EQ(cellResidualTangent<C::type>(m, X, um, b, rm, nullptr), KernelStatus::Ok);
    for (int i = 0; i < C::dofs; ++i) err = std::max(err, std::abs(K[i * C::dofs + k] - (rp[i] - rm[i]) / (2 * h)));
  }
  return err;
}

/// How boundaryForcesOfConstantStress integrates sigma n over a face.
enum class FaceIntegration {
  Traction,  ///< faceTractionForces with t = sigma n, n from the face nodes (planar faces only)
  Pressure   ///< sigma \int N_a n dA via facePressureForces(p = -1) (exact on warped faces too)
};

/// Unit normal of a planar face from its nodes, right-hand rule (2D: (dy, -dx)/L).
template <int D, std::size_t N>
std::array<double, D> planarUnitNormal(const std::array<double, N>& Xf, int m) {
  std::array<double, D> n{};
  if constexpr (D == 2) {
    n = {Xf[3] - Xf[1], -(Xf[2] - Xf[0])};
  } else {
    // triangle: (x1-x0) x (x2-x0); quad: diagonals (x2-x0) x (x3-x1) (corners lead quadratic faces)
    const bool tri = m == 3 || m == 6;
    const int p0 = 0, p1 = tri ? 1 : 2, q0 = tri ? 0 : 1, q1 = tri ? 2 : 3;
    double a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = Xf[p1 * 3 + i] - Xf[p0 * 3 + i];
      b[i] = Xf[q1 * 3 + i] - Xf[q0 * 3 + i];
    }
    n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  double len = 0.0;
  for (double x : n) len += x * x;
  len = std::sqrt(len);
  for (double& x : n) x /= len;
  return n;
}

template <FaceType F, CellType T>
void addFaceForces(const std::array<double, CellTraits<T>::dofs>& X, const std::array<int, mesh::kMaxFaceNodes>& nodes,
                   const std::vector<double>& sigma, double thickness, FaceIntegration how,
                   std::array<double, CellTraits<T>::dofs>& f, bool axisymmetric) {
  constexpr int d = CellTraits<T>::dim, m = FaceTraits<F>::nodes;
  std::array<double, FaceTraits<F>::dofs> Xf{}, g{};
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < d; ++i) Xf[k * d + i] = X[nodes[k] * d + i];
  if (how == FaceIntegration::Traction) {
    const std::array<double, d> n = planarUnitNormal<d>(Xf, m);
    std::array<double, d> t{};
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) t[i] += sigma[i * d + j] * n[j];
    faceTractionForces<F>(Xf, t, thickness, g, axisymmetric);
    for (int k = 0; k < m * d; ++k) f[nodes[k / d] * d + k % d] += g[k];
  } else {
    facePressureForces<F>(Xf, -1.0, thickness, g, axisymmetric);
    for (int k = 0; k < m; ++k)
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) f[nodes[k] * d + i] += sigma[i * d + j] * g[k * d + j];
  }
}

/// Sum over the cell's faces of the consistent nodal forces of the traction sigma n of a
/// constant d x d stress sigma, scattered to the cell's nodes (2D: x thickness, or
/// x 2 pi r when `axisymmetric`).
template <CellType T>
std::array<double, CellTraits<T>::dofs> boundaryForcesOfConstantStress(const std::array<double, CellTraits<T>::dofs>& X,
                                                                       const std::vector<double>& sigma,
                                                                       double thickness, FaceIntegration how,
                                                                       bool axisymmetric = false) {
  std::array<double, CellTraits<T>::dofs> f{};
  for (int s = 0; s < mesh::numFaces(T); ++s) {
    std::array<int, mesh::kMaxFaceNodes> nodes;
    faceLocalNodes(T, s, nodes);
    visitFace<T>(s, [&](auto face) { addFaceForces<decltype(face)::value, T>(X, nodes, sigma, thickness, how, f, axisymmetric); });
  }
  return f;
}

}  // namespace coulomb::fem::test
