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
                                   Shape<ReferenceShape::Hex8>, Shape<ReferenceShape::Line3>,
                                   Shape<ReferenceShape::Tri6>, Shape<ReferenceShape::Quad8>,
                                   Shape<ReferenceShape::Quad9>, Shape<ReferenceShape::Tet10>,
                                   Shape<ReferenceShape::Hex20>, Shape<ReferenceShape::Hex27>>;

template <typename T>
class FemShapeFunctions : public ::testing::Test {};
TYPED_TEST_SUITE(FemShapeFunctions, AllShapes);

// A fixed set of interior sample points of the reference element.
template <ReferenceShape S>
std::vector<std::array<double, ShapeTraits<S>::dim>> samplePoints() {
  constexpr int d = ShapeTraits<S>::dim;
  const bool simplex = isSimplex(S);
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

// The quadratic shapes (all of them hold the complete quadratics) interpolate
// any quadratic polynomial exactly: sum_a N_a p(xi_a) = p(xi), and likewise its gradient.
template <typename T>
class FemQuadraticShapes : public ::testing::Test {};
using QuadraticShapes = ::testing::Types<Shape<ReferenceShape::Line3>, Shape<ReferenceShape::Tri6>,
                                         Shape<ReferenceShape::Quad8>, Shape<ReferenceShape::Quad9>,
                                         Shape<ReferenceShape::Tet10>, Shape<ReferenceShape::Hex20>,
                                         Shape<ReferenceShape::Hex27>>;
TYPED_TEST_SUITE(FemQuadraticShapes, QuadraticShapes);

TYPED_TEST(FemQuadraticShapes, QuadraticCompleteness) {
  constexpr ReferenceShape S = TypeParam::value;
  constexpr int n = ShapeTraits<S>::nodes, d = ShapeTraits<S>::dim;
  // p(x) = 0.3 + sum_i c_i x_i + sum_{i<=j} q_ij x_i x_j with fixed, unrelated coefficients
  auto p = [](const std::array<double, d>& x) {
    double v = 0.3;
    for (int i = 0; i < d; ++i) {
      v += (0.7 - 0.4 * i) * x[i];
      for (int j = i; j < d; ++j) v += (0.5 + 0.3 * i - 0.8 * j) * x[i] * x[j];
    }
    return v;
  };
  auto gradP = [](const std::array<double, d>& x, int k) {
    double g = 0.7 - 0.4 * k;
    for (int i = 0; i < d; ++i)
      for (int j = i; j < d; ++j) {
        const double q = 0.5 + 0.3 * i - 0.8 * j;
        if (i == k) g += q * x[j];
        if (j == k) g += q * x[i];
      }
    return g;
  };
  for (const auto& xi : samplePoints<S>()) {
    std::array<double, n> N;
    std::array<double, n * d> dN;
    shapeValues<S>(xi, N);
    shapeGradients<S>(xi, dN);
    double v = 0.0;
    std::array<double, d> g{};
    for (int a = 0; a < n; ++a) {
      const double pa = p(referenceNode<S>(a));
      v += N[a] * pa;
      for (int k = 0; k < d; ++k) g[k] += dN[a * d + k] * pa;
    }
    EXPECT_NEAR(v, p(xi), 1e-14);
    for (int k = 0; k < d; ++k) EXPECT_NEAR(g[k], gradP(xi, k), 1e-13);
  }
}

// Where the shape functions put the quadratic nodes agrees with where the mesh
// layer says they are (mesh::nodeCorners, from which readers derive orders):
// each node sits at the mean of its corners.
template <mesh::CellType T>
void expectNodesAtCornerMeans() {
  constexpr ReferenceShape S = referenceShape(T);
  constexpr int d = ShapeTraits<S>::dim;
  for (int a = 0; a < ShapeTraits<S>::nodes; ++a) {
    const mesh::NodeCorners c = mesh::nodeCorners(T, a);
    std::array<double, d> mean{};
    for (int k = 0; k < c.count; ++k)
      for (int i = 0; i < d; ++i) mean[i] += referenceNode<S>(c.corners[k])[i] / c.count;
    for (int i = 0; i < d; ++i) EXPECT_EQ(referenceNode<S>(a)[i], mean[i]) << mesh::toString(T) << " node " << a;
  }
}

TEST(FemShapeFunctions, QuadraticNodesSitAtTheirCornerMeans) {
  expectNodesAtCornerMeans<mesh::CellType::Quad8>();
  expectNodesAtCornerMeans<mesh::CellType::Quad9>();
  expectNodesAtCornerMeans<mesh::CellType::Tri6>();
  expectNodesAtCornerMeans<mesh::CellType::Hex20>();
  expectNodesAtCornerMeans<mesh::CellType::Hex27>();
  expectNodesAtCornerMeans<mesh::CellType::Tet10>();
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

TEST(FemQuadrature, ThreePointGaussRulesExactToDegreeFivePerVariable) {
  for (int i = 0; i <= 5; ++i) {
    EXPECT_NEAR(integrateMonomial<ReferenceShape::Line3>({i, 0, 0}), lineMoment(i), 1e-15);
    for (int j = 0; j <= 5; ++j) {
      EXPECT_NEAR(integrateMonomial<ReferenceShape::Quad8>({i, j, 0}), lineMoment(i) * lineMoment(j), 1e-15);
      EXPECT_NEAR(integrateMonomial<ReferenceShape::Quad9>({i, j, 0}), lineMoment(i) * lineMoment(j), 1e-15);
      for (int k = 0; k <= 5; ++k) {
        const double exact = lineMoment(i) * lineMoment(j) * lineMoment(k);
        EXPECT_NEAR(integrateMonomial<ReferenceShape::Hex20>({i, j, k}), exact, 1e-14);
        EXPECT_NEAR(integrateMonomial<ReferenceShape::Hex27>({i, j, k}), exact, 1e-14);
      }
    }
  }
  // and not beyond: x^6 by 3-point Gauss is 6/25 instead of 2/7
  EXPECT_GT(std::abs(integrateMonomial<ReferenceShape::Line3>({6, 0, 0}) - lineMoment(6)), 0.04);
}

TEST(FemQuadrature, Tri6RuleExactToTotalDegreeFour) {
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j)
      EXPECT_NEAR(integrateMonomial<ReferenceShape::Tri6>({i, j, 0}), factorial(i) * factorial(j) / factorial(i + j + 2),
                  1e-14)
          << "x^" << i << " y^" << j;
  // not degree 5 (x^5: 1/42 exactly)
  EXPECT_GT(std::abs(integrateMonomial<ReferenceShape::Tri6>({5, 0, 0}) - 1.0 / 42.0), 1e-6);
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

TEST(FemQuadrature, Tet10RuleExactToTotalDegreeThree) {
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j)
      for (int k = 0; i + j + k <= 3; ++k)
        EXPECT_NEAR(integrateMonomial<ReferenceShape::Tet10>({i, j, k}),
                    factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3), 1e-15)
            << "x^" << i << " y^" << j << " z^" << k;
  // not degree 4 (x^4: 4!/7! = 1/210)
  EXPECT_GT(std::abs(integrateMonomial<ReferenceShape::Tet10>({4, 0, 0}) - 1.0 / 210.0), 1e-6);
  for (double w : quadratureRule<ReferenceShape::Tet10>().weight) EXPECT_GT(w, 0.0);
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
