// Total-Lagrangian compressible neo-Hookean cell kernel, every cell type.
#include <gtest/gtest.h>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/ElementKernel.hpp"
#include "coulomb/fem/StressKernel.hpp"
#include "fem_test_support.hpp"

namespace coulomb::fem::test {
namespace {

constexpr double kE = 10.0, kNu = 0.35, kThickness = 0.6;

MaterialParameters neoHookeanMaterial() {
  MaterialParameters m;
  m.model = MaterialModel::NeoHookean;
  m.youngsModulus = kE;
  m.poissonRatio = kNu;
  m.thickness = kThickness;
  return m;
}

template <typename C>
class FemNeoHookeanKernel : public ::testing::Test {};
TYPED_TEST_SUITE(FemNeoHookeanKernel, AllCells, CellNames);

template <typename C>
typename C::Vec residualOf(const MaterialParameters& m, const typename C::Vec& X, const typename C::Vec& u) {
  typename C::Vec r;
  const std::array<double, C::dim> b{};
  EXPECT_EQ(cellResidualTangent<C::type>(m, X, u, b, r, nullptr), KernelStatus::Ok);
  return r;
}

/// Cauchy stress at node a recovered from cellNodalStress (constant fields: exact).
template <typename C>
std::array<std::array<double, 6>, C::nodes> nodalStress(const MaterialParameters& m, const typename C::Vec& X,
                                                        const typename C::Vec& u) {
  std::array<double, C::nodes * 6> ws;
  std::array<double, C::nodes> w;
  EXPECT_EQ(cellNodalStress<C::type>(m, X, u, ws, w), KernelStatus::Ok);
  std::array<std::array<double, 6>, C::nodes> s;
  for (int a = 0; a < C::nodes; ++a)
    for (int k = 0; k < 6; ++k) s[a][k] = ws[a * 6 + k] / w[a];
  return s;
}

/// Embed a d x d deformation gradient I + A as a 3x3 one (F_zz = 1 in 2D).
void embed(int d, const std::vector<double>& A, double F[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F[i][j] = (i == j ? 1.0 : 0.0) + (i < d && j < d ? A[i * d + j] : 0.0);
}

std::array<double, 6> voigt(const double s[3][3]) { return {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]}; }

TYPED_TEST(FemNeoHookeanKernel, TangentMatchesCentralDifferences) {
  using C = TypeParam;
  const MaterialParameters m = neoHookeanMaterial();
  const auto X = distortedCoordinates<C::type>();
  for (double amplitude : {0.0, 1.0}) {  // undeformed and finitely deformed (|grad u| ~ 0.3)
    auto u = linearField<C::type>(X, sampleGradient(C::dim, amplitude), {0.1, 0.0, -0.1});
    for (int k = 0; k < C::dofs; ++k) u[k] += 0.05 * amplitude * wiggle(k, 2, 5);
    const std::array<double, C::dim> b{};
    typename C::Vec r;
    typename C::Mat K;
    ASSERT_EQ(cellResidualTangent<C::type>(m, X, u, b, r, &K), KernelStatus::Ok);
    const auto r0 = residualOf<C>(m, X, u);  // the residual without tangent is the same
    for (int i = 0; i < C::dofs; ++i) EXPECT_NEAR(r[i], r0[i], 1e-14 * kE);
    const double err = tangentDifferenceError<C>(m, X, u, K);
    EXPECT_LT(err, 1e-6 * maxAbs(K)) << "amplitude " << amplitude;
    // hyperelastic with dead loads: the tangent is symmetric
    for (int i = 0; i < C::dofs; ++i)
      for (int j = 0; j < i; ++j) EXPECT_NEAR(K[i * C::dofs + j], K[j * C::dofs + i], 1e-12 * maxAbs(K));
  }
}

TYPED_TEST(FemNeoHookeanKernel, LargeRigidRotationIsStressFree) {
  using C = TypeParam;
  constexpr int d = C::dim;
  const MaterialParameters m = neoHookeanMaterial();
  const auto X = distortedCoordinates<C::type>();
  // Rotation by 60 degrees (3D: about the axis (1, 2, 2)/3, Rodrigues' formula).
  const double th = M_PI / 3.0, c = std::cos(th), s = std::sin(th);
  std::vector<double> A(d * d);  // u = (R - I) X + t
  if (d == 2) {
    A = {c - 1.0, -s, s, c - 1.0};
  } else {
    const double n[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
    const double K[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double K2 = 0.0;
        for (int k = 0; k < 3; ++k) K2 += K[i][k] * K[k][j];
        A[i * 3 + j] = s * K[i][j] + (1.0 - c) * K2;  // R - I
      }
  }
  const auto u = linearField<C::type>(X, A, {0.5, -1.0, 2.0});
  EXPECT_LT(maxAbs(residualOf<C>(m, X, u)), 1e-13 * kE);
  for (const auto& sigma : nodalStress<C>(m, X, u))
    for (double v : sigma) EXPECT_LT(std::abs(v), 1e-13 * kE);
}

TYPED_TEST(FemNeoHookeanKernel, SmallStrainsMatchLinearElasticityToSecondOrder) {
  using C = TypeParam;
  const MaterialParameters nh = neoHookeanMaterial();
  MaterialParameters le = nh;
  le.model = MaterialModel::LinearElastic;
  const auto X = distortedCoordinates<C::type>();
  double error[2];
  const double strain[2] = {1e-3, 1e-4};
  for (int k = 0; k < 2; ++k) {
    const auto u = linearField<C::type>(X, sampleGradient(C::dim, strain[k]), {0.0, 0.0, 0.0});
    const auto sNH = nodalStress<C>(nh, X, u), sLE = nodalStress<C>(le, X, u);
    error[k] = 0.0;
    for (int a = 0; a < C::nodes; ++a)
      for (int i = 0; i < 6; ++i) error[k] = std::max(error[k], std::abs(sNH[a][i] - sLE[a][i]));
    // residuals: the difference relative to the (first-order) residual is first order
    const auto rNH = residualOf<C>(nh, X, u), rLE = residualOf<C>(le, X, u);
    typename C::Vec diff;
    for (int i = 0; i < C::dofs; ++i) diff[i] = rNH[i] - rLE[i];
    EXPECT_LT(maxAbs(diff), 2.0 * strain[k] * maxAbs(rLE));
  }
  EXPECT_LT(error[0], 2.0 * kE * strain[0] * strain[0]);  // O(strain^2) with a modest constant
  EXPECT_GT(error[0] / error[1], 50.0);                    // ... and really second order
  EXPECT_LT(error[0] / error[1], 200.0);
}

TYPED_TEST(FemNeoHookeanKernel, HomogeneousDeformationResidualEqualsBoundaryTractions) {
  using C = TypeParam;
  constexpr int d = C::dim;
  const MaterialParameters m = neoHookeanMaterial();
  double mu, lambda;
  lame(kE, kNu, mu, lambda);
  const std::vector<double> A = sampleGradient(d, 1.0);
  double F[3][3], P[3][3], sigma[3][3];
  embed(d, A, F);
  neoHookean3(mu, lambda, F, P, sigma);
  std::vector<double> Pd(d * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) Pd[i * d + j] = P[i][j];
  // total Lagrangian: r_a = \oint_{dOmega_0} N_a P N dA_0 for a homogeneous F
  const struct {
    typename C::Vec X;
    FaceIntegration how;
  } cases[] = {{projectiveCoordinates<C::type>(), FaceIntegration::Traction},
               {distortedCoordinates<C::type>(), FaceIntegration::Pressure}};
  for (const auto& cs : cases) {
    const auto u = linearField<C::type>(cs.X, A, {0.2, 0.1, 0.0});
    const auto r = residualOf<C>(m, cs.X, u);
    const auto f = boundaryForcesOfConstantStress<C::type>(cs.X, Pd, kThickness, cs.how);
    for (int k = 0; k < C::dofs; ++k) EXPECT_NEAR(r[k], f[k], 1e-10 * maxAbs(f)) << "dof " << k;
    // and the Cauchy stress of the same state
    for (const auto& s : nodalStress<C>(m, cs.X, u)) {
      const auto expected = voigt(sigma);
      for (int k = 0; k < 6; ++k) EXPECT_NEAR(s[k], expected[k], 1e-12 * kE);
    }
  }
}

// Axisymmetric (2D cells moved to x >= 2): the tangent against central
// differences (finitely deformed, hoop stretch included), and a homogeneous
// finite expansion u_r = c r, u_z = e z (F = diag(1 + c, 1 + e), F_tt = 1 + c:
// P constant with P_rr = P_tt, in equilibrium) whose residual is the ring's
// boundary forces \oint N_a P N 2 pi R dS and whose Cauchy stress is the 3D
// law's, the hoop stress in the "zz" slot.
TYPED_TEST(FemNeoHookeanKernel, AxisymmetricTangentAndHomogeneousExpansion) {
  using C = TypeParam;
  if constexpr (C::dim == 2) {
    MaterialParameters m = neoHookeanMaterial();
    m.plane = PlaneAssumption::Axisymmetric;
    auto X = distortedCoordinates<C::type>();
    for (int a = 0; a < C::nodes; ++a) X[a * 2] += 2.0;
    auto u = linearField<C::type>(X, sampleGradient(2, 1.0), {0.1, -0.1, 0.0});
    for (int k = 0; k < C::dofs; ++k) u[k] += 0.05 * wiggle(k, 2, 5);
    const std::array<double, 2> b{};
    typename C::Vec r;
    typename C::Mat K;
    ASSERT_EQ(cellResidualTangent<C::type>(m, X, u, b, r, &K), KernelStatus::Ok);
    const double err = tangentDifferenceError<C>(m, X, u, K);
    EXPECT_LT(err, 1e-6 * maxAbs(K));

    const double c = 0.15, e = -0.1;
    const auto Xa = [] {
      auto x = distortedCoordinates<C::type>(0.0);
      for (int a = 0; a < C::nodes; ++a) x[a * 2] += 2.0;
      return x;
    }();
    typename C::Vec ua{};
    for (int a = 0; a < C::nodes; ++a) ua[a * 2] = c * Xa[a * 2], ua[a * 2 + 1] = e * Xa[a * 2 + 1];
    double mu, lambda;
    lame(kE, kNu, mu, lambda);
    double F[3][3] = {{1 + c, 0, 0}, {0, 1 + e, 0}, {0, 0, 1 + c}}, P[3][3], sigma[3][3];
    neoHookean3(mu, lambda, F, P, sigma);
    const std::vector<double> Pd = {P[0][0], 0.0, 0.0, P[1][1]};
    const auto ra = residualOf<C>(m, Xa, ua);
    const auto f = boundaryForcesOfConstantStress<C::type>(Xa, Pd, kThickness, FaceIntegration::Traction, true);
    for (int k = 0; k < C::dofs; ++k) EXPECT_NEAR(ra[k], f[k], 1e-10 * maxAbs(f)) << "dof " << k;
    for (const auto& st : nodalStress<C>(m, Xa, ua)) {
      EXPECT_NEAR(st[0], sigma[0][0], 1e-12 * kE);
      EXPECT_NEAR(st[1], sigma[1][1], 1e-12 * kE);
      EXPECT_NEAR(st[2], sigma[2][2], 1e-12 * kE);
    }
  }
}

TYPED_TEST(FemNeoHookeanKernel, UniaxialStressMatchesClosedForm) {
  using C = TypeParam;
  constexpr int d = C::dim;
  const MaterialParameters m = neoHookeanMaterial();
  double mu, lambda;
  lame(kE, kNu, mu, lambda);
  const auto X = distortedCoordinates<C::type>();
  for (double stretch : {1.5, 0.7}) {
    // F = diag(s, t[, t]) (2D: plane strain F_zz = 1). sigma_22 = 0 requires
    // g(t) = mu (t^2 - 1) + lambda ln J = 0 with J = s t^(d-1); solve by Newton.
    double t = 1.0;
    for (int it = 0; it < 50; ++it) {
      const double J = stretch * std::pow(t, d - 1);
      const double g = mu * (t * t - 1.0) + lambda * std::log(J);
      t -= g / (2.0 * mu * t + lambda * (d - 1) / t);
    }
    const double J = stretch * std::pow(t, d - 1);
    std::vector<double> A(d * d, 0.0);
    A[0] = stretch - 1.0;
    for (int i = 1; i < d; ++i) A[i * d + i] = t - 1.0;
    const auto u = linearField<C::type>(X, A, {0.0, 0.0, 0.0});
    const double sigma11 = (mu * (stretch * stretch - 1.0) + lambda * std::log(J)) / J;
    const double sigmaZZ = d == 2 ? lambda * std::log(J) / J : 0.0;
    for (const auto& s : nodalStress<C>(m, X, u)) {
      EXPECT_NEAR(s[0], sigma11, 1e-12 * kE);
      EXPECT_NEAR(s[1], 0.0, 1e-12 * kE);
      EXPECT_NEAR(s[2], sigmaZZ, 1e-12 * kE);
      for (int k = 3; k < 6; ++k) EXPECT_NEAR(s[k], 0.0, 1e-12 * kE);
    }
  }
}

TYPED_TEST(FemNeoHookeanKernel, InvertedDeformationIsReported) {
  using C = TypeParam;
  const auto X = distortedCoordinates<C::type>();
  std::vector<double> A(C::dim * C::dim, 0.0);
  A[0] = -2.0;  // F = diag(-1, 1[, 1]): det F = -1
  const auto u = linearField<C::type>(X, A, {0.0, 0.0, 0.0});
  const std::array<double, C::dim> b{};
  typename C::Vec r;
  typename C::Mat K;
  r.fill(1.0);
  EXPECT_EQ(cellResidualTangent<C::type>(neoHookeanMaterial(), X, u, b, r, &K), KernelStatus::InvertedCurrent);
  EXPECT_EQ(maxAbs(r), 0.0);
  EXPECT_EQ(maxAbs(K), 0.0);
  std::array<double, C::nodes * 6> ws;
  std::array<double, C::nodes> w;
  EXPECT_EQ(cellNodalStress<C::type>(neoHookeanMaterial(), X, u, ws, w), KernelStatus::InvertedCurrent);
  // the small-strain model has no notion of an inverted deformation
  MaterialParameters le = neoHookeanMaterial();
  le.model = MaterialModel::LinearElastic;
  EXPECT_EQ(cellResidualTangent<C::type>(le, X, u, b, r, &K), KernelStatus::Ok);
}

TEST(FemNeoHookeanKernel, PlaneStressIsRejected) {
  MaterialParameters m = neoHookeanMaterial();
  m.plane = PlaneAssumption::PlaneStress;
  const auto X = distortedCoordinates<CellType::Quad4>();
  const std::array<double, 8> u{};
  const std::array<double, 2> b{};
  std::array<double, 8> r;
  EXPECT_THROW(cellResidualTangent<CellType::Quad4>(m, X, u, b, r, nullptr), coulomb::Error);
  // 3D cells ignore the plane assumption
  const auto X3 = distortedCoordinates<CellType::Tet4>();
  const std::array<double, 12> u3{};
  const std::array<double, 3> b3{};
  std::array<double, 12> r3;
  EXPECT_EQ(cellResidualTangent<CellType::Tet4>(m, X3, u3, b3, r3, nullptr), KernelStatus::Ok);
}

}  // namespace
}  // namespace coulomb::fem::test
