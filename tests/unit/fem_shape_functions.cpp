// Shape functions and quadrature rules on the reference elements.
#include <gtest/gtest.h>

#include <cmath>

#include "coulomb/fem/Quadrature.hpp"
#include "coulomb/fem/ShapeFunctions.hpp"

namespace coulomb::fem {
namespace {

template <ReferenceShape S>
struct Shape {
  static constexpr ReferenceShape value = S;
};
using AllShapes = ::testing::Types<Shape<ReferenceShape::Line2>, Shape<ReferenceShape::Tri3>,
                                   Shape<ReferenceShape::Quad4>, Shape<ReferenceShape::Tet4>,
                                   Shape<ReferenceShape::Hex8>>;

template <typename T>
class FemShapeFunctions : public ::testing::Test {};
TYPED_TEST_SUITE(FemShapeFunctions, AllShapes);

// A fixed set of interior sample points of the reference element.
template <ReferenceShape S>
std::vector<std::array<double, ShapeTraits<S>::dim>> samplePoints() {
  constexpr int d = ShapeTraits<S>::dim;
  const bool simplex = S == ReferenceShape::Tri3 || S == ReferenceShape::Tet4;
  std::vector<std::array<double, d>> pts;
  for (int k = 0; k < 7; ++k) {
    std::array<double, d> xi{};
    for (int i = 0; i < d; ++i) {
      const double r = std::sin(1.3 * k + 2.1 * i + 0.4);  // in [-1, 1]
      xi[i] = simplex ? 0.2 * (r + 1.0) : 0.9 * r;         // simplex: sum of coordinates <= 0.4 d < 1.3
    }
    pts.push_back(xi);
  }
  return pts;
}

TYPED_TEST(FemShapeFunctions, PartitionOfUnityAndLinearCompleteness) {
  constexpr ReferenceShape S = TypeParam::value;
  constexpr int n = ShapeTraits<S>::nodes, d = ShapeTraits<S>::dim;
  for (const auto& xi : samplePoints<S>()) {
    std::array<double, n> N;
    std::array<double, n * d> dN;
    shapeValues<S>(xi, N);
    shapeGradients<S>(xi, dN);
    double sum = 0.0;
    std::array<double, d> x{}, gradSum{};
    for (int a = 0; a < n; ++a) {
      sum += N[a];
      const auto node = referenceNode<S>(a);
      for (int i = 0; i < d; ++i) {
        x[i] += N[a] * node[i];  // sum_a N_a xi_a = xi (linear completeness)
        gradSum[i] += dN[a * d + i];
      }
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int i = 0; i < d; ++i) {
      EXPECT_NEAR(x[i], xi[i], 1e-14);
      EXPECT_NEAR(gradSum[i], 0.0, 1e-14);
    }
  }
}

TYPED_TEST(FemShapeFunctions, KroneckerPropertyAtNodes) {
  constexpr ReferenceShape S = TypeParam::value;
  constexpr int n = ShapeTraits<S>::nodes;
  for (int b = 0; b < n; ++b) {
    std::array<double, n> N;
    shapeValues<S>(referenceNode<S>(b), N);
    for (int a = 0; a < n; ++a) EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-15) << "N_" << a << " at node " << b;
  }
}

TYPED_TEST(FemShapeFunctions, GradientsMatchCentralDifferences) {
  constexpr ReferenceShape S = TypeParam::value;
  constexpr int n = ShapeTraits<S>::nodes, d = ShapeTraits<S>::dim;
  const double h = 1e-6;
  for (const auto& xi : samplePoints<S>()) {
    std::array<double, n * d> dN;
    shapeGradients<S>(xi, dN);
    for (int i = 0; i < d; ++i) {
      auto xp = xi, xm = xi;
      xp[i] += h;
      xm[i] -= h;
      std::array<double, n> Np, Nm;
      shapeValues<S>(xp, Np);
      shapeValues<S>(xm, Nm);
      for (int a = 0; a < n; ++a) EXPECT_NEAR(dN[a * d + i], (Np[a] - Nm[a]) / (2 * h), 1e-9);
    }
  }
}

TEST(FemShapeFunctions, PhysicalGradientsOfAffineMapAreExact) {
  // X = M xi + c on the Hex8 and Tri3 reference elements: the interpolant sum_a X_a . k N_a of
  // the linear function f(X) = k . X has gradient k, and det J = det M.
  const double M[3][3] = {{2.0, 0.3, 0.1}, {-0.2, 1.5, 0.4}, {0.1, -0.3, 0.8}};
  const double detM = 2.0 * (1.5 * 0.8 + 0.4 * 0.3) - 0.3 * (-0.2 * 0.8 - 0.4 * 0.1) + 0.1 * (0.06 - 0.15);
  const double k[3] = {0.7, -1.1, 0.4};
  {
    constexpr ReferenceShape S = ReferenceShape::Hex8;
    std::array<double, 24> X, dNdxi, G;
    for (int a = 0; a < 8; ++a) {
      const auto xi = referenceNode<S>(a);
      for (int i = 0; i < 3; ++i) X[a * 3 + i] = M[i][0] * xi[0] + M[i][1] * xi[1] + M[i][2] * xi[2] + 0.5 * i;
    }
    shapeGradients<S>({0.3, -0.6, 0.2}, dNdxi);
    EXPECT_NEAR(physicalGradients<S>(X, dNdxi, G), detM, 1e-13);
    for (int i = 0; i < 3; ++i) {
      double g = 0.0;
      for (int a = 0; a < 8; ++a) g += (k[0] * X[a * 3] + k[1] * X[a * 3 + 1] + k[2] * X[a * 3 + 2]) * G[a * 3 + i];
      EXPECT_NEAR(g, k[i], 1e-13);
    }
  }
  {
    constexpr ReferenceShape S = ReferenceShape::Tri3;
    std::array<double, 6> X, dNdxi, G;
    for (int a = 0; a < 3; ++a) {
      const auto xi = referenceNode<S>(a);
      for (int i = 0; i < 2; ++i) X[a * 2 + i] = M[i][0] * xi[0] + M[i][1] * xi[1];
    }
    shapeGradients<S>({0.2, 0.3}, dNdxi);
    EXPECT_NEAR(physicalGradients<S>(X, dNdxi, G), M[0][0] * M[1][1] - M[0][1] * M[1][0], 1e-14);
    for (int i = 0; i < 2; ++i) {
      double g = 0.0;
      for (int a = 0; a < 3; ++a) g += (k[0] * X[a * 2] + k[1] * X[a * 2 + 1]) * G[a * 2 + i];
      EXPECT_NEAR(g, k[i], 1e-14);
    }
    std::swap(X[2], X[4]);  // swap nodes 1 and 2: orientation reverses
    std::swap(X[3], X[5]);
    EXPECT_LT(physicalGradients<S>(X, dNdxi, G), 0.0);
  }
}

// ---- quadrature -----------------------------------------------------------------------

double factorial(int k) { return k <= 1 ? 1.0 : k * factorial(k - 1); }
// \int_{-1}^{1} x^k dx
double lineMoment(int k) { return k % 2 ? 0.0 : 2.0 / (k + 1); }

template <ReferenceShape S>
double integrateMonomial(const std::array<int, 3>& p) {
  const auto& rule = quadratureRule<S>();
  double s = 0.0;
  for (int q = 0; q < rule.points; ++q) {
    double v = rule.weight[q];
    for (int i = 0; i < rule.dim; ++i) v *= std::pow(rule.xi[q][i], p[i]);
    s += v;
  }
  return s;
}

TEST(FemQuadrature, GaussRulesExactToDegreeThreePerVariable) {
  for (int i = 0; i <= 3; ++i) {
    EXPECT_NEAR(integrateMonomial<ReferenceShape::Line2>({i, 0, 0}), lineMoment(i), 1e-15);
    for (int j = 0; j <= 3; ++j) {
      EXPECT_NEAR(integrateMonomial<ReferenceShape::Quad4>({i, j, 0}), lineMoment(i) * lineMoment(j), 1e-15);
      for (int k = 0; k <= 3; ++k)
        EXPECT_NEAR(integrateMonomial<ReferenceShape::Hex8>({i, j, k}), lineMoment(i) * lineMoment(j) * lineMoment(k),
                    1e-14);
    }
  }
  // and not beyond: x^4 is not integrated exactly by 2-point Gauss (2/9 instead of 2/5)
  EXPECT_GT(std::abs(integrateMonomial<ReferenceShape::Line2>({4, 0, 0}) - lineMoment(4)), 0.1);
}

TEST(FemQuadrature, SimplexRulesExactToTotalDegreeTwo) {
  // \int_simplex x^i y^j [z^k] = i! j! [k!] / (i + j [+ k] + dim)!
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; i + j <= 2; ++j) {
      EXPECT_NEAR(integrateMonomial<ReferenceShape::Tri3>({i, j, 0}), factorial(i) * factorial(j) / factorial(i + j + 2),
                  1e-15);
      for (int k = 0; i + j + k <= 2; ++k)
        EXPECT_NEAR(integrateMonomial<ReferenceShape::Tet4>({i, j, k}),
                    factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3), 1e-15);
    }
}

TEST(FemQuadrature, TabulationMatchesShapeFunctions) {
  constexpr ReferenceShape S = ReferenceShape::Quad4;
  const auto& rule = quadratureRule<S>();
  const auto& tab = tabulatedShape<S>();
  ASSERT_EQ(tab.points, rule.points);
  for (int q = 0; q < rule.points; ++q) {
    std::array<double, 4> N;
    shapeValues<S>(rule.xi[q], N);
    EXPECT_EQ(tab.weight[q], rule.weight[q]);
    for (int a = 0; a < 4; ++a) EXPECT_EQ(tab.N[q][a], N[a]);
  }
}

}  // namespace
}  // namespace coulomb::fem
