// The corner level of quadratic meshes (fem/VertexCoarsening.hpp, the
// P-Multigrid preconditioner's prolongator): on straight-sided meshes of
// every quadratic cell, P reproduces any linear field from its corner
// values (the linear element's interpolation at the mid-side, face and cell
// centre nodes), so P times the corner rigid-body modes is the fine
// rigid-body modes (fem::rigidBodyModes); every row of P sums to one, also on
// curved cells; a linear mesh has no corner level. np = 1, 2, 3.
//
// "Reproduces" to kMeshPlacement: gmsh puts a straight edge's mid-side node
// within about 1e-12 of the mean of its ends (1.03e-12 on block3d_hex20.e,
// 6.3e-13 on tube3d_tet10.e, measured from the files), and the fields here
// change by at most about 3 per unit length; a wrong weight or corner shows
// as an error of order 0.1.
#include <gtest/gtest.h>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

#include "TestSupport.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/fem/RigidBodyModes.hpp"
#include "coulomb/fem/VertexCoarsening.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {
namespace {

constexpr double kMeshPlacement = 1e-10;

struct Level {
  std::shared_ptr<const mesh::GlobalMesh> global;
  std::unique_ptr<mesh::Mesh> mesh;
  std::unique_ptr<fem::DofMap> dofs;
  fem::VertexCoarsening coarse;
};

Level levelOf(const std::string& file) {
  Level l;
  l.global = std::make_shared<const mesh::GlobalMesh>(io::readExodus(shippedMesh(file)));
  l.mesh = std::make_unique<mesh::Mesh>(l.global, worldComm());
  l.dofs = std::make_unique<fem::DofMap>(*l.mesh);
  l.coarse = fem::vertexCoarsening(*l.mesh, *l.dofs);
  return l;
}

/// The largest |P c - f| over the owned DoFs and the columns.
double largestDifference(const CrsMatrix& P, const MultiVector& coarse, const MultiVector& fine) {
  MultiVector prolongated(fine.getMap(), fine.getNumVectors());
  P.apply(coarse, prolongated);
  prolongated.update(-1.0, fine, 1.0);
  std::vector<double> norms(fine.getNumVectors());
  prolongated.normInf(norms);
  return *std::max_element(norms.begin(), norms.end());
}

class StraightQuadraticMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(StraightQuadraticMesh, ProlongatorReproducesLinearFieldsAndRigidBodyModes) {
  const Level l = levelOf(GetParam());
  ASSERT_FALSE(l.coarse.prolongator.is_null());
  const int dim = l.mesh->dimension();
  const long long corners = fem::cornerNodeCount(*l.global);
  EXPECT_EQ(static_cast<long long>(l.coarse.prolongator->getDomainMap()->getGlobalNumElements()), dim * corners);
  EXPECT_LT(corners, l.global->numNodes());  // there are nodes to interpolate

  // Rigid-body modes (rotations about the origin: linear fields).
  const auto fineModes = fem::rigidBodyModes(*l.mesh, *l.dofs);
  EXPECT_LT(largestDifference(*l.coarse.prolongator, *l.coarse.nullspace, *fineModes), kMeshPlacement);

  // A general linear field u_c = sum_d A_cd x_d + b_c.
  auto field = [&](const double* x, int c) {
    double u = 0.1 * (c + 1);
    for (int d = 0; d < dim; ++d) u += (0.3 + c - 0.7 * d + 0.2 * c * d) * x[d];
    return u;
  };
  MultiVector coarse(l.coarse.prolongator->getDomainMap(), 1), fine(l.dofs->ownedMap(), 1);
  {
    auto x = l.coarse.coordinates->get2dView();
    auto u = coarse.get1dViewNonConst();
    for (std::size_t i = 0; i < l.coarse.coordinates->getLocalLength(); ++i) {
      double X[3] = {0.0, 0.0, 0.0};
      for (int d = 0; d < dim; ++d) X[d] = x[d][i];
      for (int c = 0; c < dim; ++c) u[i * dim + c] = field(X, c);
    }
    auto f = fine.get1dViewNonConst();
    for (int i = 0; i < l.mesh->numOwnedNodes(); ++i) {
      const double* X = &l.global->coordinates[l.mesh->localNodes()[i] * dim];
      for (int c = 0; c < dim; ++c) f[i * dim + c] = field(X, c);
    }
  }
  EXPECT_LT(largestDifference(*l.coarse.prolongator, coarse, fine), kMeshPlacement);
}

INSTANTIATE_TEST_SUITE_P(Cells, StraightQuadraticMesh,
                         ::testing::Values("block3d_hex20.e", "block3d_hex27.e", "block3d_tet10.e", "block2d_quad8.e",
                                           "block2d_quad9.e", "block2d_tri6.e", "tube3d_tet10.e"));

TEST(VertexCoarsening, RowsSumToOneOnCurvedCells) {
  for (const char* file : {"quarter_annulus3d_hex20_n4.e", "quarter_annulus2d_tri6_n4.e"}) {
    const Level l = levelOf(file);
    ASSERT_FALSE(l.coarse.prolongator.is_null()) << file;
    MultiVector ones(l.coarse.prolongator->getDomainMap(), 1), sums(l.dofs->ownedMap(), 1), expected(l.dofs->ownedMap(), 1);
    ones.putScalar(1.0);
    expected.putScalar(1.0);
    EXPECT_LT(largestDifference(*l.coarse.prolongator, ones, expected), 1e-14) << file;
  }
}

TEST(VertexCoarsening, LinearMeshHasNoCornerLevel) {
  const Level l = levelOf("block3d.e");
  EXPECT_TRUE(l.coarse.prolongator.is_null());
  EXPECT_EQ(fem::cornerNodeCount(*l.global), 0);
}

}  // namespace
}  // namespace coulomb::test
