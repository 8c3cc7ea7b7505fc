// Nodal stress recovery (lumped L2 projection weights) and von Mises stress.
#include <gtest/gtest.h>

#include "coulomb/fem/StressKernel.hpp"
#include "fem_test_support.hpp"

namespace coulomb::fem::test {
namespace {

constexpr double kE = 70.0, kNu = 0.25, kThickness = 2.5;

MaterialParameters elastic(PlaneAssumption plane) {
  MaterialParameters m;
  m.youngsModulus = kE;
  m.poissonRatio = kNu;
  m.plane = plane;
  m.thickness = kThickness;
  return m;
}

template <typename C>
class FemStressKernel : public ::testing::Test {};
TYPED_TEST_SUITE(FemStressKernel, AllCells, CellNames);

// Closed-form small-strain stress of the displacement gradient A (3D, or 2D with the
// plane assumption), Voigt xx yy zz xy yz xz.
std::array<double, 6> hookeStress(int d, const std::vector<double>& A, PlaneAssumption plane) {
  double e[3][3] = {};
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) e[i][j] = 0.5 * (A[i * d + j] + A[j * d + i]);
  const double G = kE / (2 * (1 + kNu));
  if (d == 2 && plane == PlaneAssumption::PlaneStress) {
    const double f = kE / (1 - kNu * kNu);
    return {f * (e[0][0] + kNu * e[1][1]), f * (e[1][1] + kNu * e[0][0]), 0.0, 2 * G * e[0][1], 0.0, 0.0};
  }
  // Hooke's law in compliance form inverted: sigma = E/((1+nu)(1-2nu)) [(1-nu) e_ii + nu (sum of others)]
  const double f = kE / ((1 + kNu) * (1 - 2 * kNu));
  std::array<double, 6> s{};
  for (int i = 0; i < 3; ++i) s[i] = f * ((1 - kNu) * e[i][i] + kNu * (e[0][0] + e[1][1] + e[2][2] - e[i][i]));
  s[3] = 2 * G * e[0][1];
  s[4] = 2 * G * e[1][2];
  s[5] = 2 * G * e[0][2];
  return s;
}

TYPED_TEST(FemStressKernel, ConstantStressIsRecoveredAtEveryNode) {
  using C = TypeParam;
  const auto X = distortedCoordinates<C::type>();
  const std::vector<double> A = sampleGradient(C::dim, 1e-3);
  const auto u = linearField<C::type>(X, A, {1.0, 2.0, 3.0});
  for (PlaneAssumption plane : {PlaneAssumption::PlaneStrain, PlaneAssumption::PlaneStress}) {
    std::array<double, C::nodes * 6> ws;
    std::array<double, C::nodes> w;
    ASSERT_EQ(cellNodalStress<C::type>(elastic(plane), X, u, ws, w), KernelStatus::Ok);
    const auto expected = hookeStress(C::dim, A, plane);
    for (int a = 0; a < C::nodes; ++a) {
      ASSERT_GT(w[a], 0.0);
      for (int k = 0; k < 6; ++k) EXPECT_NEAR(ws[a * 6 + k] / w[a], expected[k], 1e-12 * kE) << "node " << a << " k " << k;
      if (C::dim == 2 && plane == PlaneAssumption::PlaneStrain) {  // sigma_zz = nu (sigma_xx + sigma_yy)
        EXPECT_NEAR(ws[a * 6 + 2] / w[a], kNu * (ws[a * 6] + ws[a * 6 + 1]) / w[a], 1e-12 * kE);
      }
      if (C::dim == 2 && plane == PlaneAssumption::PlaneStress) {
        EXPECT_EQ(ws[a * 6 + 2], 0.0);
      }
    }
  }
}

TYPED_TEST(FemStressKernel, WeightsAreShapeFunctionIntegrals) {
  using C = TypeParam;
  // Affine cell: linear cells weigh by \int N_a dV = det M \int_ref N_a (2D: x thickness).
  // Quadratic cells by \int N_a^2 dV: positive at every node; for QUAD9 and HEX27 the
  // product of the 1D integrals of the squared quadratic Lagrange functions, 4/15 (ends)
  // and 16/15 (middle).
  const auto X = distortedCoordinates<C::type>(0.0);
  const double M[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.15}, {-0.05, 0.1, 1.1}};
  const double detM = C::dim == 2 ? (M[0][0] * M[1][1] - M[0][1] * M[1][0]) * kThickness : det3(M);
  const typename C::Vec u{};
  std::array<double, C::nodes * 6> ws;
  std::array<double, C::nodes> w;
  ASSERT_EQ(cellNodalStress<C::type>(elastic(PlaneAssumption::PlaneStrain), X, u, ws, w), KernelStatus::Ok);
  for (int a = 0; a < C::nodes; ++a) {
    if (!mesh::isQuadratic(C::type)) {
      EXPECT_NEAR(w[a], detM * referenceShapeIntegral(C::type, a), 1e-14);
    } else if (C::type == CellType::Quad9 || C::type == CellType::Hex27) {
      const mesh::NodeCorners c = mesh::nodeCorners(C::type, a);
      const int middle = c.count == 1 ? 0 : c.count == 2 ? 1 : c.count == 4 ? 2 : 3;
      double expected = detM;
      for (int i = 0; i < C::dim; ++i) expected *= i < middle ? 16.0 / 15.0 : 4.0 / 15.0;
      EXPECT_NEAR(w[a], expected, 1e-13) << "node " << a;
    } else {
      EXPECT_GT(w[a], 0.0) << "node " << a;
    }
  }
  EXPECT_EQ(maxAbs(ws), 0.0);
}

TYPED_TEST(FemStressKernel, InvertedReferenceCellIsReported) {
  using C = TypeParam;
  auto X = distortedCoordinates<C::type>();
  // mirror the cell: x -> -x reverses the orientation of every cell type
  for (int a = 0; a < C::nodes; ++a) X[a * C::dim] = -X[a * C::dim];
  const typename C::Vec u{};
  std::array<double, C::nodes * 6> ws;
  std::array<double, C::nodes> w;
  w.fill(1.0);
  EXPECT_EQ(cellNodalStress<C::type>(elastic(PlaneAssumption::PlaneStrain), X, u, ws, w),
            KernelStatus::InvertedReference);
  EXPECT_EQ(maxAbs(w), 0.0);
}

TEST(FemStressKernel, VonMisesOfElementaryStates) {
  for (double s : {250.0, -40.0}) {
    for (int i = 0; i < 3; ++i) {  // uniaxial along each axis
      std::array<double, 6> v{};
      v[i] = s;
      EXPECT_NEAR(vonMises(v), std::abs(s), 1e-12 * std::abs(s));
    }
    for (int i = 3; i < 6; ++i) {  // pure shear in each plane
      std::array<double, 6> v{};
      v[i] = s;
      EXPECT_NEAR(vonMises(v), std::sqrt(3.0) * std::abs(s), 1e-12 * std::abs(s));
    }
    // hydrostatic pressure has no deviator; adding it changes nothing
    EXPECT_NEAR(vonMises({s, s, s, 0, 0, 0}), 0.0, 1e-12 * std::abs(s));
    EXPECT_NEAR(vonMises({s + 7.0, 7.0, 7.0, 0, 0, 0}), std::abs(s), 1e-12 * std::abs(s));
  }
  // uniaxial stress sigma along the unit vector n: sigma_ij = sigma n_i n_j -> |sigma|
  const double n[3] = {2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0};
  const double s = 13.0;
  EXPECT_NEAR(vonMises({s * n[0] * n[0], s * n[1] * n[1], s * n[2] * n[2], s * n[0] * n[1], s * n[1] * n[2],
                        s * n[0] * n[2]}),
              s, 1e-12 * s);
}

}  // namespace
}  // namespace coulomb::fem::test
