// Exodus side numbering and surface-load integration.
#include <gtest/gtest.h>

#include <cmath>

#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/FaceKernel.hpp"
#include "coulomb/fem/FaceTopology.hpp"
#include "fem_test_support.hpp"

namespace coulomb::fem::test {
namespace {

// ---- topology -------------------------------------------------------------------------

TEST(FemFaceTopology, SideNodesFollowTheExodusConvention) {
  // Exodus II side-to-node tables, 1-based, as published with SEACAS.
  const std::vector<std::vector<int>> quad4 = {{1, 2}, {2, 3}, {3, 4}, {4, 1}};
  const std::vector<std::vector<int>> tri3 = {{1, 2}, {2, 3}, {3, 1}};
  const std::vector<std::vector<int>> hex8 = {{1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7},
                                              {4, 1, 5, 8}, {1, 4, 3, 2}, {5, 6, 7, 8}};
  const std::vector<std::vector<int>> tet4 = {{1, 2, 4}, {2, 3, 4}, {1, 4, 3}, {1, 3, 2}};
  const struct {
    CellType cell;
    const std::vector<std::vector<int>>& table;
    FaceType face;
  } cases[] = {{CellType::Quad4, quad4, FaceType::Line2},
               {CellType::Tri3, tri3, FaceType::Line2},
               {CellType::Hex8, hex8, FaceType::Quad4},
               {CellType::Tet4, tet4, FaceType::Tri3}};
  for (const auto& c : cases) {
    ASSERT_EQ(static_cast<int>(c.table.size()), mesh::numFaces(c.cell));
    for (int s = 0; s < mesh::numFaces(c.cell); ++s) {
      std::array<int, mesh::kMaxFaceNodes> nodes;
      const int count = faceLocalNodes(c.cell, s, nodes);
      ASSERT_EQ(count, static_cast<int>(c.table[s].size()));
      EXPECT_EQ(count, mesh::numNodes(faceType(c.cell, s)));
      EXPECT_EQ(faceType(c.cell, s), c.face);
      for (int k = 0; k < count; ++k)
        EXPECT_EQ(nodes[k], c.table[s][k] - 1) << mesh::toString(c.cell) << " side " << s + 1 << " node " << k;
      for (int k = count; k < 4; ++k) EXPECT_EQ(nodes[k], -1);
    }
  }
}

TEST(FemFaceTopology, QuadraticSidesFollowTheExodusConvention) {
  // HEX27 sides as published with SEACAS (Ioss), 1-based; side 4 starts at its
  // corner 4 like the HEX8 side above (the same cycle). HEX20: the first 8.
  const std::vector<std::vector<int>> hex27 = {
      {1, 2, 6, 5, 9, 14, 17, 13, 26},  {2, 3, 7, 6, 10, 15, 18, 14, 25}, {3, 4, 8, 7, 11, 16, 19, 15, 27},
      {4, 1, 5, 8, 12, 13, 20, 16, 24}, {1, 4, 3, 2, 12, 11, 10, 9, 22},  {5, 6, 7, 8, 17, 18, 19, 20, 23}};
  const std::vector<std::vector<int>> tet10 = {
      {1, 2, 4, 5, 9, 8}, {2, 3, 4, 6, 10, 9}, {1, 4, 3, 8, 10, 7}, {1, 3, 2, 7, 6, 5}};
  const std::vector<std::vector<int>> quad9 = {{1, 2, 5}, {2, 3, 6}, {3, 4, 7}, {4, 1, 8}};
  const std::vector<std::vector<int>> tri6 = {{1, 2, 4}, {2, 3, 5}, {3, 1, 6}};
  const struct {
    CellType cell;
    const std::vector<std::vector<int>>& table;
    int nodes;
    FaceType face;
  } cases[] = {{CellType::Hex27, hex27, 9, FaceType::Quad9}, {CellType::Hex20, hex27, 8, FaceType::Quad8},
               {CellType::Tet10, tet10, 6, FaceType::Tri6},  {CellType::Quad9, quad9, 3, FaceType::Line3},
               {CellType::Quad8, quad9, 3, FaceType::Line3}, {CellType::Tri6, tri6, 3, FaceType::Line3}};
  for (const auto& c : cases)
    for (int s = 0; s < mesh::numFaces(c.cell); ++s) {
      std::array<int, mesh::kMaxFaceNodes> nodes;
      ASSERT_EQ(faceLocalNodes(c.cell, s, nodes), c.nodes);
      EXPECT_EQ(faceType(c.cell, s), c.face);
      for (int k = 0; k < c.nodes; ++k)
        EXPECT_EQ(nodes[k], c.table[s][k] - 1) << mesh::toString(c.cell) << " side " << s + 1 << " node " << k;
    }
}

TEST(FemFaceTopology, BadSideThrows) {
  std::array<int, mesh::kMaxFaceNodes> nodes;
  for (CellType cell : {CellType::Quad4, CellType::Tri3, CellType::Hex8, CellType::Tet4, CellType::Quad8,
                        CellType::Hex27, CellType::Tet10}) {
    EXPECT_THROW(faceLocalNodes(cell, -1, nodes), coulomb::Error);
    EXPECT_THROW(faceLocalNodes(cell, mesh::numFaces(cell), nodes), coulomb::Error);
    EXPECT_THROW(faceType(cell, mesh::numFaces(cell)), coulomb::Error);
  }
}

template <typename C>
class FemFaceKernel : public ::testing::Test {};
TYPED_TEST_SUITE(FemFaceKernel, AllCells, CellNames);

template <FaceType F>
std::array<double, FaceTraits<F>::dim> areaVectorOfSide(const double* X, const std::array<int, mesh::kMaxFaceNodes>& nodes) {
  constexpr int d = FaceTraits<F>::dim;
  std::array<double, FaceTraits<F>::dofs> Xf{};
  for (int k = 0; k < FaceTraits<F>::nodes; ++k)
    for (int i = 0; i < d; ++i) Xf[k * d + i] = X[nodes[k] * d + i];
  return faceAreaVector<F>(Xf);
}

// The face normal from faceLocalNodes points out of the cell: its dot product with
// (face centroid - cell centroid) is positive, and on cells with planar faces (reference and
// projective geometry, both convex) every node off the face lies strictly on its inner side.
TYPED_TEST(FemFaceKernel, FaceNormalsPointOutOfTheCell) {
  using C = TypeParam;
  constexpr int d = C::dim;
  std::vector<int> all(C::nodes);
  for (int a = 0; a < C::nodes; ++a) all[a] = a;
  for (int geometry = 0; geometry < 3; ++geometry) {
    typename C::Vec X;
    if (geometry == 0) {
      X = referenceCoordinates<C::type>();
    } else if (geometry == 1) {
      X = distortedCoordinates<C::type>();
    } else {
      X = projectiveCoordinates<C::type>();
    }
    const auto cellCentroid = nodeAverage<d>(X, all.data(), C::nodes);
    for (int s = 0; s < mesh::numFaces(C::type); ++s) {
      std::array<int, mesh::kMaxFaceNodes> nodes;
      const int count = faceLocalNodes(C::type, s, nodes);
      const auto faceCentroid = nodeAverage<d>(X, nodes.data(), count);
      std::array<double, d> n{};
      visitFace<C::type>(s, [&](auto face) { n = areaVectorOfSide<decltype(face)::value>(X.data(), nodes); });
      double dot = 0.0;
      for (int i = 0; i < d; ++i) dot += n[i] * (faceCentroid[i] - cellCentroid[i]);
      EXPECT_GT(dot, 0.0) << mesh::toString(C::type) << " side " << s + 1 << " geometry " << geometry;
      if (geometry == 1) continue;
      for (int b = 0; b < C::nodes; ++b) {
        if (std::find(nodes.begin(), nodes.begin() + count, b) != nodes.begin() + count) continue;
        double side = 0.0;
        for (int i = 0; i < d; ++i) side += n[i] * (X[b * d + i] - faceCentroid[i]);
        EXPECT_LT(side, -1e-3) << mesh::toString(C::type) << " side " << s + 1 << " node " << b + 1;
      }
    }
  }
}

// ---- loads on single faces -------------------------------------------------------------

TEST(FemFaceKernel, Line2ForcesMatchClosedForm) {
  const std::array<double, 4> X = {1.0, 2.0, 4.0, 6.0};  // length 5, (dy, -dx) = (4, -3)
  const double thickness = 0.4, p = 3.0;
  EXPECT_NEAR(faceArea<FaceType::Line2>(X), 5.0, 1e-14);
  const auto av = faceAreaVector<FaceType::Line2>(X);
  EXPECT_NEAR(av[0], 4.0, 1e-14);
  EXPECT_NEAR(av[1], -3.0, 1e-14);
  std::array<double, 4> f;
  facePressureForces<FaceType::Line2>(X, p, thickness, f);
  for (int a = 0; a < 2; ++a) {  // -p n L t / 2 at each end
    EXPECT_NEAR(f[a * 2 + 0], -p * 4.0 * thickness / 2, 1e-14);
    EXPECT_NEAR(f[a * 2 + 1], -p * -3.0 * thickness / 2, 1e-14);
  }
  const std::array<double, 2> t = {1.5, -0.5};
  faceTractionForces<FaceType::Line2>(X, t, thickness, f);
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(f[a * 2 + i], t[i] * 5.0 * thickness / 2, 1e-14);
}

// Axisymmetric: the ring of a LINE2 face from r = 1 to r = 2 at z = 0.5, under
// a pressure p: the forces are p n 2 pi \int N_a r dr, i.e. 2 pi p (4/6, 5/6)
// on the ends (\int N_0 r = 2/3, \int N_1 r = 5/6), the thickness ignored.
// The LINE3 face of the same ring carries the same total force, 3 pi p.
TEST(FemFaceKernel, AxisymmetricFacesCarryTheRingsForce) {
  const double p = 2.0, twoPi = 2.0 * M_PI;
  const std::array<double, 4> X = {2.0, 0.5, 1.0, 0.5};  // outward normal (dy, -dx) = (0, 1)
  std::array<double, 4> f;
  facePressureForces<FaceType::Line2>(X, p, 123.0, f, true);
  EXPECT_NEAR(f[1], -p * twoPi * 5.0 / 6.0, 1e-13);  // node at r = 2
  EXPECT_NEAR(f[3], -p * twoPi * 2.0 / 3.0, 1e-13);  // node at r = 1
  EXPECT_NEAR(f[0], 0.0, 1e-14);
  const std::array<double, 6> X3 = {2.0, 0.5, 1.0, 0.5, 1.5, 0.5};
  std::array<double, 6> f3;
  facePressureForces<FaceType::Line3>(X3, p, 123.0, f3, true);
  EXPECT_NEAR(f3[1] + f3[3] + f3[5], -p * 3.0 * M_PI, 1e-13);
  const std::array<double, 2> t = {0.0, -p};
  faceTractionForces<FaceType::Line3>(X3, t, 123.0, f3, true);
  EXPECT_NEAR(f3[1] + f3[3] + f3[5], -p * 3.0 * M_PI, 1e-13);
}

TEST(FemFaceKernel, Tri3ForcesMatchClosedForm) {
  const std::array<double, 9> X = {0.1, 0.2, 0.3, 2.0, 0.5, -0.2, 0.4, 1.7, 0.9};
  // area vector = 1/2 (x1 - x0) x (x2 - x0)
  const double a[3] = {1.9, 0.3, -0.5}, b[3] = {0.3, 1.5, 0.6};
  const double A[3] = {0.5 * (a[1] * b[2] - a[2] * b[1]), 0.5 * (a[2] * b[0] - a[0] * b[2]),
                       0.5 * (a[0] * b[1] - a[1] * b[0])};
  const double area = std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]);
  EXPECT_NEAR(faceArea<FaceType::Tri3>(X), area, 1e-14);
  std::array<double, 9> f;
  const double p = -2.5;
  facePressureForces<FaceType::Tri3>(X, p, 123.0 /* ignored in 3D */, f);
  for (int n = 0; n < 3; ++n)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[n * 3 + i], -p * A[i] / 3, 1e-14);
  const std::array<double, 3> t = {0.3, -1.2, 2.0};
  faceTractionForces<FaceType::Tri3>(X, t, 123.0, f);
  for (int n = 0; n < 3; ++n)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[n * 3 + i], t[i] * area / 3, 1e-14);
}

TEST(FemFaceKernel, FlatQuad4ForcesSumToAreaTimesLoad) {
  // A planar, non-rectangular quad in a tilted plane: corners (u, v) mapped by
  // x = o + u e1 + v e2 with e1, e2 spanning the plane.
  const double o[3] = {0.5, -0.2, 1.0}, e1[3] = {1.0, 0.2, 0.3}, e2[3] = {-0.1, 0.8, 0.5};
  const double uv[4][2] = {{0, 0}, {2.0, 0.1}, {1.7, 1.4}, {0.2, 1.0}};
  std::array<double, 12> X;
  for (int n = 0; n < 4; ++n)
    for (int i = 0; i < 3; ++i) X[n * 3 + i] = o[i] + uv[n][0] * e1[i] + uv[n][1] * e2[i];
  // planar polygon area (shoelace in (u, v)) times |e1 x e2|, normal along e1 x e2
  double shoelace = 0.0;
  for (int n = 0; n < 4; ++n) shoelace += uv[n][0] * uv[(n + 1) % 4][1] - uv[(n + 1) % 4][0] * uv[n][1];
  const double c[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double cn = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double area = 0.5 * shoelace * cn;
  EXPECT_NEAR(faceArea<FaceType::Quad4>(X), area, 1e-13);
  const double p = 4.0;
  std::array<double, 12> f;
  facePressureForces<FaceType::Quad4>(X, p, 1.0, f);
  for (int i = 0; i < 3; ++i) {
    const double sum = f[i] + f[3 + i] + f[6 + i] + f[9 + i];
    EXPECT_NEAR(sum, -p * area * c[i] / cn, 1e-13);
  }
  const std::array<double, 3> t = {-1.0, 0.5, 2.0};
  faceTractionForces<FaceType::Quad4>(X, t, 1.0, f);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i] + f[3 + i] + f[6 + i] + f[9 + i], t[i] * area, 1e-13);
}

TEST(FemFaceKernel, WarpedQuad4AreaVectorIsHalfTheDiagonalCrossProduct) {
  // For any bilinear quad, \int n dA = 1/2 (x2 - x0) x (x3 - x1), while the true area is larger
  // than the norm of that vector when the face is warped.
  const std::array<double, 12> X = {0, 0, 0, 1, 0, 0.3, 1.2, 1.1, -0.2, -0.1, 0.9, 0.25};
  double d1[3], d2[3];
  for (int i = 0; i < 3; ++i) {
    d1[i] = X[6 + i] - X[i];
    d2[i] = X[9 + i] - X[3 + i];
  }
  const double A[3] = {0.5 * (d1[1] * d2[2] - d1[2] * d2[1]), 0.5 * (d1[2] * d2[0] - d1[0] * d2[2]),
                       0.5 * (d1[0] * d2[1] - d1[1] * d2[0])};
  const auto av = faceAreaVector<FaceType::Quad4>(X);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(av[i], A[i], 1e-14);
  std::array<double, 12> f;
  facePressureForces<FaceType::Quad4>(X, 1.0, 1.0, f);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i] + f[3 + i] + f[6 + i] + f[9 + i], -A[i], 1e-14);
  EXPECT_GT(faceArea<FaceType::Quad4>(X), std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2]) + 1e-3);
}

TYPED_TEST(FemFaceKernel, PressureOnClosedSurfaceSumsToZero) {
  // A uniform pressure on all faces of a closed cell is self-equilibrated: \oint n dA = 0.
  using C = TypeParam;
  const auto X = distortedCoordinates<C::type>();
  const auto f = boundaryForcesOfConstantStress<C::type>(X, sampleGradient(C::dim, 0.0 /* zero */), 1.0,
                                                         FaceIntegration::Pressure);
  EXPECT_EQ(maxAbs(f), 0.0);
  std::vector<double> identity(C::dim * C::dim, 0.0);
  for (int i = 0; i < C::dim; ++i) identity[i * C::dim + i] = 1.0;
  const auto g = boundaryForcesOfConstantStress<C::type>(X, identity, 1.0, FaceIntegration::Pressure);
  for (int i = 0; i < C::dim; ++i) {
    double sum = 0.0;
    for (int a = 0; a < C::nodes; ++a) sum += g[a * C::dim + i];
    EXPECT_NEAR(sum, 0.0, 1e-14);
  }
}

}  // namespace
}  // namespace coulomb::fem::test
