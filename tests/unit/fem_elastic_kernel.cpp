// Small-strain linear elastic cell kernel, every cell type on distorted geometry.
#include <gtest/gtest.h>

#include "coulomb/fem/ElementKernel.hpp"
#include "coulomb/fem/StressKernel.hpp"
#include "fem_test_support.hpp"

namespace coulomb::fem::test {
namespace {

constexpr double kE = 210.0, kNu = 0.3, kThickness = 0.7;

MaterialParameters elastic(PlaneAssumption plane = PlaneAssumption::PlaneStrain) {
  MaterialParameters m;
  m.model = MaterialModel::LinearElastic;
  m.youngsModulus = kE;
  m.poissonRatio = kNu;
  m.plane = plane;
  m.thickness = kThickness;
  return m;
}

template <typename C>
class FemElasticKernel : public ::testing::Test {};
TYPED_TEST_SUITE(FemElasticKernel, AllCells, CellNames);

template <typename C>
typename C::Vec residualOf(const MaterialParameters& m, const typename C::Vec& X, const typename C::Vec& u,
                           const std::array<double, C::dim>& b = {}) {
  typename C::Vec r;
  EXPECT_EQ(cellResidualTangent<C::type>(m, X, u, b, r, nullptr), KernelStatus::Ok);
  return r;
}

TYPED_TEST(FemElasticKernel, RigidTranslationGivesZeroResidual) {
  using C = TypeParam;
  const auto X = distortedCoordinates<C::type>();
  const auto u = linearField<C::type>(X, std::vector<double>(C::dim * C::dim, 0.0), {0.3, -0.7, 0.2});
  const auto r = residualOf<C>(elastic(), X, u);
  EXPECT_LT(maxAbs(r), 1e-13 * kE);
}

// For u = A X + c the stress is constant, so by the divergence theorem
// \int B_a^T sigma dV = \oint N_a sigma n dA exactly (also on the distorted cells).
template <typename C>
void checkPatch(const MaterialParameters& m, const typename C::Vec& X, FaceIntegration how) {
  constexpr int d = C::dim;
  const std::vector<double> A = sampleGradient(d, 1e-3);
  const auto u = linearField<C::type>(X, A, {0.1, 0.2, 0.3});
  double mu, lambda;
  lame(kE, kNu, mu, lambda);
  if (d == 2 && m.plane == PlaneAssumption::PlaneStress) lambda = 2 * lambda * mu / (lambda + 2 * mu);
  double tr = 0.0;
  for (int i = 0; i < d; ++i) tr += A[i * d + i];
  std::vector<double> sigma(d * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) sigma[i * d + j] = mu * (A[i * d + j] + A[j * d + i]) + (i == j ? lambda * tr : 0.0);
  const auto r = residualOf<C>(m, X, u);
  const auto f = boundaryForcesOfConstantStress<C::type>(X, sigma, kThickness, how);
  const double scale = maxAbs(f);
  ASSERT_GT(scale, 0.0);
  for (int k = 0; k < C::dofs; ++k) EXPECT_NEAR(r[k], f[k], 1e-10 * scale) << "dof " << k;
}

/// The cell moved to x >= 2 (an axisymmetric cell away from the axis; 3D cells too, harmlessly).
template <typename C>
typename C::Vec offAxis(typename C::Vec X) {
  for (int a = 0; a < C::nodes; ++a) X[a * C::dim] += 2.0;
  return X;
}

// Axisymmetric (2D cells): u_r = c r, u_z = e z + g has the constant strains
// eps_rr = eps_tt = c, eps_zz = e, a constant stress with sigma_rr = sigma_tt,
// which is in equilibrium in cylindrical coordinates (d sigma_rr / dr +
// (sigma_rr - sigma_tt) / r = 0): the residual is the ring's boundary
// forces, \oint N_a sigma n 2 pi r ds, on affine cells to round-off.
TYPED_TEST(FemElasticKernel, AxisymmetricUniformExpansionIsInEquilibrium) {
  using C = TypeParam;
  if constexpr (C::dim == 2) {
    const double c = 2e-3, e = -1e-3;
    const auto X = offAxis<C>(distortedCoordinates<C::type>(0.0));
    typename C::Vec u{};
    for (int a = 0; a < C::nodes; ++a) u[a * 2] = c * X[a * 2], u[a * 2 + 1] = e * X[a * 2 + 1] + 0.3;
    double mu, lambda;
    lame(kE, kNu, mu, lambda);
    const double tr = 2 * c + e;
    const std::vector<double> sigma = {lambda * tr + 2 * mu * c, 0.0, 0.0, lambda * tr + 2 * mu * e};
    const auto r = residualOf<C>(elastic(PlaneAssumption::Axisymmetric), X, u);
    const auto f = boundaryForcesOfConstantStress<C::type>(X, sigma, kThickness, FaceIntegration::Traction, true);
    const double scale = maxAbs(f);
    ASSERT_GT(scale, 0.0);
    for (int k = 0; k < C::dofs; ++k) EXPECT_NEAR(r[k], f[k], 1e-10 * scale) << "dof " << k;
    // The recovered stress: sigma_rr, sigma_zz in plane, the hoop stress in the "zz" slot.
    std::array<double, C::nodes * 6> weighted{};
    std::array<double, C::nodes> weight{};
    ASSERT_EQ(cellNodalStress<C::type>(elastic(PlaneAssumption::Axisymmetric), X, u, weighted, weight),
              KernelStatus::Ok);
    for (int a = 0; a < C::nodes; ++a) {
      EXPECT_NEAR(weighted[a * 6 + 0] / weight[a], sigma[0], 1e-12 * kE) << "node " << a;
      EXPECT_NEAR(weighted[a * 6 + 1] / weight[a], sigma[3], 1e-12 * kE) << "node " << a;
      EXPECT_NEAR(weighted[a * 6 + 2] / weight[a], sigma[0], 1e-12 * kE) << "node " << a;  // sigma_tt = sigma_rr
    }
    // Without the hoop terms (plane strain with the ring's weight) it is not.
    auto noHoop = elastic(PlaneAssumption::PlaneStrain);
    const auto plane = residualOf<C>(noHoop, X, u);
    double differs = 0;
    for (int k = 0; k < C::dofs; ++k) differs = std::max(differs, std::abs(plane[k] - r[k]));
    EXPECT_GT(differs, 1e-3 * scale);
  }
}

TYPED_TEST(FemElasticKernel, LinearFieldResidualEqualsBoundaryTractionForces) {
  using C = TypeParam;
  // Planar faces (projective map, non-affine for QUAD4/HEX8): faceTractionForces with t = sigma n.
  checkPatch<C>(elastic(), projectiveCoordinates<C::type>(), FaceIntegration::Traction);
  if (C::dim == 2) checkPatch<C>(elastic(PlaneAssumption::PlaneStress), projectiveCoordinates<C::type>(),
                                 FaceIntegration::Traction);
  // Randomly perturbed nodes (warped HEX8 faces): sigma \int N_a n dA.
  checkPatch<C>(elastic(), distortedCoordinates<C::type>(), FaceIntegration::Pressure);
}

TYPED_TEST(FemElasticKernel, BodyForceIsDistributedByShapeFunctionIntegrals) {
  using C = TypeParam;
  // Affine cell (no perturbation): \int N_a dV = det M \int_ref N_a (referenceShapeIntegral),
  // r_a = -b \int N_a dV (2D: x thickness).
  const auto X = distortedCoordinates<C::type>(0.0);
  const double M[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.15}, {-0.05, 0.1, 1.1}};
  const double detM = C::dim == 2 ? (M[0][0] * M[1][1] - M[0][1] * M[1][0]) * kThickness : det3(M);
  const std::array<double, C::dim> b = [] {
    std::array<double, C::dim> v{};
    for (int i = 0; i < C::dim; ++i) v[i] = 1.5 - i;
    return v;
  }();
  const typename C::Vec zero{};
  const auto r = residualOf<C>(elastic(), X, zero, b);
  for (int a = 0; a < C::nodes; ++a)
    for (int i = 0; i < C::dim; ++i)
      EXPECT_NEAR(r[a * C::dim + i], -b[i] * detM * referenceShapeIntegral(C::type, a), 1e-13) << "node " << a;
}

TYPED_TEST(FemElasticKernel, TangentMatchesCentralDifferences) {
  using C = TypeParam;
  for (PlaneAssumption plane :
       {PlaneAssumption::PlaneStrain, PlaneAssumption::PlaneStress, PlaneAssumption::Axisymmetric}) {
    const MaterialParameters m = elastic(plane);
    const auto X = offAxis<C>(distortedCoordinates<C::type>());
    typename C::Vec u;
    for (int k = 0; k < C::dofs; ++k) u[k] = 0.01 * wiggle(k, 1, 3);
    const std::array<double, C::dim> b{};
    typename C::Vec r;
    typename C::Mat K;
    ASSERT_EQ(cellResidualTangent<C::type>(m, X, u, b, r, &K), KernelStatus::Ok);
    const double err = tangentDifferenceError<C>(m, X, u, K);
    EXPECT_LT(err, 1e-6 * maxAbs(K));
    // residual is linear: r(u) = K u
    for (int i = 0; i < C::dofs; ++i) {
      double Ku = 0.0;
      for (int k = 0; k < C::dofs; ++k) Ku += K[i * C::dofs + k] * u[k];
      EXPECT_NEAR(r[i], Ku, 1e-12 * maxAbs(K));
    }
  }
}

TYPED_TEST(FemElasticKernel, TangentIsSymmetricWithRigidBodyNullSpace) {
  using C = TypeParam;
  const auto X = distortedCoordinates<C::type>();
  const typename C::Vec u{};
  const std::array<double, C::dim> b{};
  typename C::Vec r;
  typename C::Mat K;
  ASSERT_EQ(cellResidualTangent<C::type>(elastic(), X, u, b, r, &K), KernelStatus::Ok);
  const double scale = maxAbs(K);
  for (int i = 0; i < C::dofs; ++i)
    for (int j = 0; j < i; ++j) EXPECT_NEAR(K[i * C::dofs + j], K[j * C::dofs + i], 1e-13 * scale);
  const auto ev = symmetricEigenvalues(std::vector<double>(K.begin(), K.end()), C::dofs);
  int zero = 0;
  for (double e : ev) {
    EXPECT_GT(e, -1e-10 * ev.back());  // positive semi-definite
    if (std::abs(e) < 1e-10 * ev.back()) ++zero;
  }
  EXPECT_EQ(zero, C::dim == 2 ? 3 : 6);
}

TYPED_TEST(FemElasticKernel, InvertedReferenceCellIsReported) {
  using C = TypeParam;
  auto X = distortedCoordinates<C::type>();
  // Mirror the cell: x -> -x reverses the orientation of every cell type.
  for (int a = 0; a < C::nodes; ++a) X[a * C::dim] = -X[a * C::dim];
  const typename C::Vec u{};
  const std::array<double, C::dim> b{};
  typename C::Vec r;
  typename C::Mat K;
  r.fill(1.0);
  EXPECT_EQ(cellResidualTangent<C::type>(elastic(), X, u, b, r, &K), KernelStatus::InvertedReference);
  EXPECT_EQ(maxAbs(r), 0.0);
  EXPECT_EQ(maxAbs(K), 0.0);
}

TEST(FemElasticKernel, PlaneStressTangentMatchesClosedFormConstitutiveMatrix) {
  // One TRI3 (constant strain): K = t A B^T D B with D = E/(1-nu^2) [1 nu 0; nu 1 0; 0 0 (1-nu)/2].
  const std::array<double, 6> X = {0.0, 0.0, 2.0, 0.2, 0.3, 1.5};
  const double area = 0.5 * (2.0 * 1.5 - 0.2 * 0.3);
  // dN/dx = (y_b - y_c) / 2A, dN/dy = (x_c - x_b) / 2A for the cyclic (a, b, c)
  double gx[3], gy[3];
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    gx[a] = (X[b * 2 + 1] - X[c * 2 + 1]) / (2 * area);
    gy[a] = (X[c * 2] - X[b * 2]) / (2 * area);
  }
  const double f = kE / (1 - kNu * kNu);
  const double D[3][3] = {{f, f * kNu, 0}, {f * kNu, f, 0}, {0, 0, f * (1 - kNu) / 2}};
  double B[3][6] = {};
  for (int a = 0; a < 3; ++a) {
    B[0][2 * a] = gx[a];
    B[1][2 * a + 1] = gy[a];
    B[2][2 * a] = gy[a];
    B[2][2 * a + 1] = gx[a];
  }
  const std::array<double, 6> u{};
  const std::array<double, 2> b{};
  std::array<double, 6> r;
  std::array<double, 36> K;
  ASSERT_EQ(cellResidualTangent<CellType::Tri3>(elastic(PlaneAssumption::PlaneStress), X, u, b, r, &K),
            KernelStatus::Ok);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double k = 0.0;
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) k += B[p][i] * D[p][q] * B[q][j];
      EXPECT_NEAR(K[i * 6 + j], kThickness * area * k, 1e-12 * kE);
    }
}

}  // namespace
}  // namespace coulomb::fem::test
