// Dual (biorthogonal) shape functions of slave faces: biorthogonality against an
// independent high-order quadrature, partition of unity, closed-form coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coulomb/contact/mortar/DualBasis.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;

// n-point Gauss–Legendre on [-1, 1] by Newton on the Legendre polynomial
// (independent of the rules used by the code).
struct Gauss {
  std::vector<double> x, w;
  explicit Gauss(int n) {
    for (int i = 0; i < n; ++i) {
      double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x.push_back(z);
      w.push_back(2.0 / ((1.0 - z * z) * dp * dp));
    }
  }
};

// Quadrature points (xi, weight) of a reference face, exact for high polynomial degree.
template <FaceType F>
std::vector<std::pair<FacePoint<F, double>, double>> referenceRule(int n = 8) {
  const Gauss g(n);
  std::vector<std::pair<FacePoint<F, double>, double>> rule;
  for (int i = 0; i < n; ++i) {
    if constexpr (F == FaceType::Line2) {
      rule.push_back({{g.x[i]}, g.w[i]});
    } else {
      for (int j = 0; j < n; ++j) {
        if constexpr (F == FaceType::Quad4) {
          rule.push_back({{g.x[i], g.x[j]}, g.w[i] * g.w[j]});
        } else {  // collapsed square -> unit triangle: xi = u, eta = v (1 - u)
          const double u = 0.5 * (1.0 + g.x[i]), v = 0.5 * (1.0 + g.x[j]);
          rule.push_back({{u, v * (1.0 - u)}, 0.25 * g.w[i] * g.w[j] * (1.0 - u)});
        }
      }
    }
  }
  return rule;
}

// Surface measure |dx/dxi| from the tangents of the face map.
template <FaceType F>
double measure(const FaceNodes<F, double>& x, const FacePoint<F, double>& xi) {
  const auto g = faceShapeGradients<F, double>(xi);
  constexpr int sd = FaceTraits<F>::spaceDim;
  std::array<std::array<double, 3>, 2> t{};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a)
    for (int i = 0; i < FaceTraits<F>::paramDim; ++i)
      for (int d = 0; d < sd; ++d) t[i][d] += g[a][i] * x[a][d];
  if constexpr (F == FaceType::Line2) return std::hypot(t[0][0], t[0][1]);
  const double c0 = t[0][1] * t[1][2] - t[0][2] * t[1][1];
  const double c1 = t[0][2] * t[1][0] - t[0][0] * t[1][2];
  const double c2 = t[0][0] * t[1][1] - t[0][1] * t[1][0];
  return std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
}

// Distorted faces (plane for Tri3/Quad4, arbitrarily oriented in space).
FaceNodes<FaceType::Line2, double> line() { return {{{0.3, -0.2}, {1.9, 0.7}}}; }
FaceNodes<FaceType::Tri3, double> tri() { return {{{0.1, 0.2, -0.3}, {1.4, 0.5, 0.2}, {0.3, 1.1, 0.6}}}; }
// A plane, non-parallelogram quadrilateral: corners of a distorted quad in the
// plane spanned by u and v through o.
FaceNodes<FaceType::Quad4, double> quad() {
  const std::array<double, 3> o{0.2, -0.1, 0.4}, u{0.8, 0.36, 0.48}, v{-0.36, 0.928, -0.096};
  const double c[4][2] = {{0.0, 0.0}, {1.3, -0.2}, {1.6, 0.9}, {0.1, 1.2}};
  FaceNodes<FaceType::Quad4, double> x{};
  for (int a = 0; a < 4; ++a)
    for (int d = 0; d < 3; ++d) x[a][d] = o[d] + c[a][0] * u[d] + c[a][1] * v[d];
  return x;
}

template <FaceType F>
FaceNodes<F, double> distortedFace() {
  if constexpr (F == FaceType::Line2) return line();
  else if constexpr (F == FaceType::Tri3) return tri();
  else return quad();
}

template <FaceType F>
struct Face {
  static constexpr FaceType value = F;
};
using AllFaces = ::testing::Types<Face<FaceType::Line2>, Face<FaceType::Tri3>, Face<FaceType::Quad4>>;

template <typename T>
class DualBasisTyped : public ::testing::Test {};
TYPED_TEST_SUITE(DualBasisTyped, AllFaces);

TYPED_TEST(DualBasisTyped, BiorthogonalOnDistortedFace) {
  constexpr FaceType F = TypeParam::value;
  constexpr int n = FaceTraits<F>::nodes;
  const FaceNodes<F, double> x = distortedFace<F>();
  const NodalMatrix<F, double> A = dualCoefficients<F, double>(x);
  // int Phi_j N_k dA and int N_k dA by the independent rule.
  double B[4][4] = {}, Nint[4] = {}, area = 0.0;
  for (const auto& [xi, w] : referenceRule<F>()) {
    const double dA = w * measure<F>(x, xi);
    const auto N = faceShapeValues<F, double>(xi);
    const auto phi = dualShapeValues<F, double, double>(A, xi);
    area += dA;
    for (int k = 0; k < n; ++k) {
      Nint[k] += N[k] * dA;
      for (int j = 0; j < n; ++j) B[j][k] += phi[j] * N[k] * dA;
    }
  }
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) EXPECT_NEAR(B[j][k], j == k ? Nint[k] : 0.0, 1e-13 * area) << j << "," << k;
}

TYPED_TEST(DualBasisTyped, PartitionOfUnity) {
  constexpr FaceType F = TypeParam::value;
  const FaceNodes<F, double> x = distortedFace<F>();
  const NodalMatrix<F, double> A = dualCoefficients<F, double>(x);
  for (const auto& [xi, w] : referenceRule<F>(3)) {
    (void)w;
    const auto phi = dualShapeValues<F, double, double>(A, xi);
    double sum = 0.0;
    for (double p : phi) sum += p;
    EXPECT_NEAR(sum, 1.0, 1e-13);
  }
}

TYPED_TEST(DualBasisTyped, LumpedMassIsRowSumOfConsistentMass) {
  constexpr FaceType F = TypeParam::value;
  constexpr int n = FaceTraits<F>::nodes;
  const FaceNodes<F, double> x = distortedFace<F>();
  const FaceMass<F, double> mass = faceMass<F, double>(x);
  double Nint[4] = {}, area = 0.0;
  for (const auto& [xi, w] : referenceRule<F>()) {
    const double dA = w * measure<F>(x, xi);
    const auto N = faceShapeValues<F, double>(xi);
    area += dA;
    for (int k = 0; k < n; ++k) Nint[k] += N[k] * dA;
  }
  for (int j = 0; j < n; ++j) {
    double rowSum = 0.0;
    for (int k = 0; k < n; ++k) {
      rowSum += mass.Me[j][k];
      EXPECT_DOUBLE_EQ(mass.Me[j][k], mass.Me[k][j]);
    }
    EXPECT_NEAR(mass.De[j], rowSum, 1e-14 * area);
    EXPECT_NEAR(mass.De[j], Nint[j], 1e-14 * area);
  }
}

TEST(DualBasis, ConstantCoefficientsOfSimplices) {
  // Line2: A = [[2,-1],[-1,2]]: Phi_1 = (1 - 3 xi)/2, Phi_2 = (1 + 3 xi)/2.
  const auto A2 = dualCoefficients<FaceType::Line2, double>(line());
  const double e2[2][2] = {{2.0, -1.0}, {-1.0, 2.0}};
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(A2[j][k], e2[j][k], 1e-14);
  // Tri3: A = 4 I - 1 1^T (Phi_j = 3 N_j - sum_{k != j} N_k).
  const auto A3 = dualCoefficients<FaceType::Tri3, double>(tri());
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(A3[j][k], j == k ? 3.0 : -1.0, 1e-13);
}

TEST(DualBasis, ParallelogramQuadIsTensorProductOfLineDuals) {
  // On a parallelogram the measure is constant, M_e and D_e are tensor products of
  // the 1D ones, so Phi_(a,b)(xi, eta) = phi_a(xi) phi_b(eta), phi = (1 -/+ 3 s)/2.
  FaceNodes<FaceType::Quad4, double> x{{{0.0, 0.0, 0.0}, {2.0, 0.5, 0.3}, {2.4, 1.7, 0.1}, {0.4, 1.2, -0.2}}};
  const auto A = dualCoefficients<FaceType::Quad4, double>(x);
  const int sign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (double xi : {-0.7, 0.1, 0.8})
    for (double eta : {-0.4, 0.3, 0.95}) {
      const auto phi = dualShapeValues<FaceType::Quad4, double, double>(A, {xi, eta});
      for (int j = 0; j < 4; ++j) {
        const double expected = 0.25 * (1.0 + 3.0 * sign[j][0] * xi) * (1.0 + 3.0 * sign[j][1] * eta);
        EXPECT_NEAR(phi[j], expected, 1e-13);
      }
    }
}

TEST(DualBasis, WarpedQuadKeepsPartitionOfUnity) {
  FaceNodes<FaceType::Quad4, double> x{{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.15}, {1.1, 1.0, -0.1}, {0.0, 0.9, 0.2}}};
  const auto A = dualCoefficients<FaceType::Quad4, double>(x);
  for (double xi : {-0.9, 0.2, 0.7}) {
    const auto phi = dualShapeValues<FaceType::Quad4, double, double>(A, {xi, -0.3 * xi + 0.1});
    EXPECT_NEAR(phi[0] + phi[1] + phi[2] + phi[3], 1.0, 1e-13);
  }
}

TEST(DualBasis, DegenerateFaceThrows) {
  FaceNodes<FaceType::Tri3, double> x{{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {2.0, 2.0, 2.0}}};
  EXPECT_THROW(dualCoefficients<FaceType::Tri3>(x), Error);
}

}  // namespace
}  // namespace coulomb::contact
