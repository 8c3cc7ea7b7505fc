// Convergence: the thick-walled cylinder under internal pressure (Lamé),
// plane strain, on quarter-annulus meshes (h, h/2, h/4).
//  - QUAD4 (n = 4, 8, 16): the nodal RMS displacement error falls at the rate
//    of bilinear elements, 2.
//  - QUAD8, QUAD9, TRI6 (order-2 meshes, n = 2, 4, 8, mid-side nodes on the
//    arcs) and HEX20, HEX27 (a slice of the cylinder, one layer, u_z = 0 on
//    both faces: plane strain): the L2 displacement error, integrated over
//    the cells, falls at the rate of quadratic elements, 3; TET10 on
//    unstructured slices (n = 4, 8, 16: n = 2 is pre-asymptotic) as well.
//  - The same cylinder as an axisymmetric section (Plane Assumption =
//    Axisymmetric, x = r, y = z, u_z = 0 on the bottom and top: the same
//    plane-strain solution): QUAD4 at rate 2, QUAD8, QUAD9, TRI6 at rate 3
//    (n = 4, 8, 16).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

#include <Teuchos_CommHelpers.hpp>

#include "TestSupport.hpp"
#include "coulomb/fem/ElementKernel.hpp"
#include "coulomb/fem/Quadrature.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {
namespace {

constexpr double kE = 1000.0, kNu = 0.3, kPressure = 1.0, kInner = 1.0, kOuter = 2.0;

/// Plane-strain Lamé solution: sigma_rr = A - B/r^2, u_r = (1+nu)/E ((1-2nu) A r + B/r).
double exactRadialDisplacement(double r) {
  const double A = kPressure * kInner * kInner / (kOuter * kOuter - kInner * kInner);
  const double B = A * kOuter * kOuter;
  return (1 + kNu) / kE * ((1 - 2 * kNu) * A * r + B / r);
}

/// The exact displacement at X: on the quarter annulus u_r along (x, y) / r,
/// on the axisymmetric section (x = r) u_r along x.
std::array<double, 2> exactDisplacement(const double* X, bool axisymmetric) {
  if (axisymmetric) return {exactRadialDisplacement(X[0]), 0.0};
  const double r = std::hypot(X[0], X[1]);
  const double ur = exactRadialDisplacement(r);
  return {ur * X[0] / r, ur * X[1] / r};
}

/// Runs the Lamé problem on one mesh (3D: a slice held at u_z = 0 on both
/// faces; axisymmetric: the section held at u_z = 0 on its bottom and top).
std::unique_ptr<solver::Simulation> solveLame(const std::string& meshFile, const std::string& dir, int dimension = 2,
                                              bool axisymmetric = false) {
  std::string body = "<ParameterList name=\"Dirichlet Conditions\">";
  if (axisymmetric)
    body += dirichletXml("bottom z", "bottom", "y", 0.0) + dirichletXml("top z", "top", "y", 0.0);
  else
    body += dirichletXml("sym x", "symmetry_x", "x", 0.0) + dirichletXml("sym y", "symmetry_y", "y", 0.0);
  if (dimension == 3) body += dirichletXml("back z", "back", "z", 0.0) + dirichletXml("front z", "front", "z", 0.0);
  body +=
      "</ParameterList><ParameterList name=\"Neumann Conditions\"><ParameterList name=\"inner pressure\">"
      "<Parameter name=\"Side Set\" type=\"string\" value=\"inner\"/>"
      "<Parameter name=\"Value\" type=\"double\" value=\"1.0\"/></ParameterList></ParameterList>"
      "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-12\"/></ParameterList>";
  if (dimension == 2)
    body += std::string("<ParameterList name=\"Problem\"><Parameter name=\"Plane Assumption\" type=\"string\" value=\"") +
            (axisymmetric ? "Axisymmetric" : "Plane Strain") + "\"/></ParameterList>";
  const std::string material =
      "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"1000\"/>"
      "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.3\"/>";
  const std::string deck = dir + "/lame.xml";
  writeOnRoot(deck, deckXml(meshFile, material, body));
  auto simulation = std::make_unique<solver::Simulation>(deck, worldComm(), nullptr);
  simulation->run();
  return simulation;
}

/// Relative nodal RMS error of one mesh.
double solveAndMeasure(const std::string& meshFile, const std::string& dir, bool axisymmetric = false) {
  const auto simulation = solveLame(meshFile, dir, 2, axisymmetric);
  double error2 = 0, norm2 = 0;
  forOwnedNodes(*simulation, [&](long long, const double* X, const double* u) {
    const auto e = exactDisplacement(X, axisymmetric);
    error2 += (u[0] - e[0]) * (u[0] - e[0]) + (u[1] - e[1]) * (u[1] - e[1]);
    norm2 += e[0] * e[0] + e[1] * e[1];
  });
  return std::sqrt(globalSum(error2) / globalSum(norm2));
}

/// \int (u_h - u)^2 and \int u^2 over one cell, by the cell's own quadrature rule
/// on its isoparametric (curved) geometry; the exact u_z is 0. (Axisymmetric:
/// the section's integrals, without 2 pi r: the rate is the same.)
template <mesh::CellType T>
void addCellError(const mesh::ElementBlock& block, long long e, const std::vector<double>& coordinates,
                  const std::vector<double>& u, bool axisymmetric, double& error2, double& norm2) {
  using Traits = fem::CellTraits<T>;
  constexpr int D = Traits::dim;
  constexpr fem::ReferenceShape S = Traits::shape;
  const auto& tab = fem::tabulatedShape<S>();
  std::array<double, Traits::dofs> X{}, ue{}, G{};
  for (int a = 0; a < Traits::nodes; ++a) {
    const long long node = block.connectivity[e * Traits::nodes + a];
    for (int d = 0; d < D; ++d) X[a * D + d] = coordinates[node * D + d], ue[a * D + d] = u[node * D + d];
  }
  for (int q = 0; q < tab.points; ++q) {
    const double dV = tab.weight[q] * fem::physicalGradients<S>(X, tab.dNdxi[q], G);
    double x[D] = {}, uh[D] = {};
    for (int a = 0; a < Traits::nodes; ++a)
      for (int d = 0; d < D; ++d) x[d] += tab.N[q][a] * X[a * D + d], uh[d] += tab.N[q][a] * ue[a * D + d];
    const auto exact = exactDisplacement(x, axisymmetric);
    for (int d = 0; d < D; ++d) {
      const double ex = d < 2 ? exact[d] : 0.0;
      error2 += dV * (uh[d] - ex) * (uh[d] - ex);
      norm2 += dV * ex * ex;
    }
  }
}

/// Relative L2 displacement error of one mesh (cells split over the ranks).
double solveAndMeasureL2(const std::string& meshFile, const std::string& dir, int dimension, bool axisymmetric) {
  const auto simulation = solveLame(meshFile, dir, dimension, axisymmetric);
  const mesh::GlobalMesh& m = simulation->mesh().global();
  std::vector<double> mine(m.coordinates.size(), 0.0), u(m.coordinates.size(), 0.0);
  forOwnedNodes(*simulation, [&](long long node, const double*, const double* un) {
    for (int d = 0; d < dimension; ++d) mine[node * dimension + d] = un[d];
  });
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(), u.data());
  const int rank = worldComm()->getRank(), size = worldComm()->getSize();
  double error2 = 0, norm2 = 0;
  using mesh::CellType;
  for (const auto& block : m.blocks)
    for (long long e = rank; e < block.numElements(); e += size) {
      switch (block.cellType) {
        case CellType::Quad8: addCellError<CellType::Quad8>(block, e, m.coordinates, u, axisymmetric, error2, norm2); break;
        case CellType::Quad9: addCellError<CellType::Quad9>(block, e, m.coordinates, u, axisymmetric, error2, norm2); break;
        case CellType::Tri6: addCellError<CellType::Tri6>(block, e, m.coordinates, u, axisymmetric, error2, norm2); break;
        case CellType::Hex20: addCellError<CellType::Hex20>(block, e, m.coordinates, u, axisymmetric, error2, norm2); break;
        case CellType::Hex27: addCellError<CellType::Hex27>(block, e, m.coordinates, u, axisymmetric, error2, norm2); break;
        case CellType::Tet10: addCellError<CellType::Tet10>(block, e, m.coordinates, u, axisymmetric, error2, norm2); break;
        default: ADD_FAILURE() << "no L2 error for " << mesh::toString(block.cellType);
      }
    }
  return std::sqrt(globalSum(error2) / globalSum(norm2));
}

/// The nodal RMS error on <mesh>_n4.e, _n8.e, _n16.e (QUAD4) falls at rate 2.
void expectBilinearRate(const std::string& mesh, bool axisymmetric) {
  const std::string dir = scratchDirectory("lame_" + mesh);
  std::vector<double> errors;
  for (int n : {4, 8, 16})
    errors.push_back(solveAndMeasure(shippedMesh(mesh + "_n" + std::to_string(n) + ".e"), dir, axisymmetric));
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double rate = std::log2(errors[i] / errors[i + 1]);
    if (worldComm()->getRank() == 0)
      std::cout << "Lame " << mesh << ": error " << errors[i] << " -> " << errors[i + 1] << ", rate " << rate << "\n";
    EXPECT_GT(rate, 1.8) << mesh;
    EXPECT_LT(rate, 2.3) << mesh;
  }
  EXPECT_LT(errors.back(), 2e-3) << mesh;
}

TEST(LameCylinder, DisplacementErrorConvergesAtRateTwo) { expectBilinearRate("quarter_annulus2d", false); }

// The same for the axisymmetric section of the cylinder.
TEST(LameCylinder, AxisymmetricDisplacementErrorConvergesAtRateTwo) { expectBilinearRate("axisymmetric_cylinder", true); }

struct QuadraticLame {
  const char* mesh;  ///< <mesh>_n<n>.e
  int dimension;
  bool axisymmetric;
  int coarsest = 2;  ///< n of the coarsest mesh (then 2n, 4n)
};

class LameQuadratic : public ::testing::TestWithParam<QuadraticLame> {};

TEST_P(LameQuadratic, L2DisplacementErrorConvergesAtRateThree) {
  const QuadraticLame c = GetParam();
  const std::string type = c.mesh;
  const std::string dir = scratchDirectory("lame_" + type);
  std::vector<double> errors;
  for (int n : {c.coarsest, 2 * c.coarsest, 4 * c.coarsest})
    errors.push_back(solveAndMeasureL2(shippedMesh(type + "_n" + std::to_string(n) + ".e"), dir, c.dimension,
                                       c.axisymmetric));
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double rate = std::log2(errors[i] / errors[i + 1]);
    if (worldComm()->getRank() == 0)
      std::cout << "Lame " << type << ": L2 error " << errors[i] << " -> " << errors[i + 1] << ", rate " << rate << "\n";
    EXPECT_GE(rate, 2.7) << type;
  }
}

INSTANTIATE_TEST_SUITE_P(
    QuadraticCells, LameQuadratic,
    ::testing::Values(QuadraticLame{"quarter_annulus2d_quad8", 2, false}, QuadraticLame{"quarter_annulus2d_quad9", 2, false},
                      QuadraticLame{"quarter_annulus2d_tri6", 2, false}, QuadraticLame{"quarter_annulus3d_hex20", 3, false},
                      QuadraticLame{"quarter_annulus3d_hex27", 3, false},
                      QuadraticLame{"quarter_annulus3d_tet10", 3, false, 4},
                      // (The section is n/2 cells high: n = 2 is one cell, pre-asymptotic for TRI6.)
                      QuadraticLame{"axisymmetric_cylinder_quad8", 2, true, 4},
                      QuadraticLame{"axisymmetric_cylinder_quad9", 2, true, 4},
                      QuadraticLame{"axisymmetric_cylinder_tri6", 2, true, 4}),
    [](const auto& info) {
      const std::string mesh = info.param.mesh;
      return (info.param.axisymmetric ? "axisymmetric_" : "") + mesh.substr(mesh.rfind('_') + 1);
    });

}  // namespace
}  // namespace coulomb::test
