// Patch tests of the quadratic cells (QUAD8, QUAD9, TRI6, HEX20, HEX27, TET10):
//  - a linear displacement field prescribed on the whole boundary of a
//    distorted mesh (interior corner AND mid-side nodes moved: curved edges)
//    is reproduced inside to round-off;
//  - a quadratic field, the column under its own weight (u_z = g/(lambda+2mu)
//    (z^2/2 - H z), rollers on the sides, free top), is reproduced at every
//    node where the element holds it: on the undistorted meshes (affine cells)
//    for every type, and on distorted straight-sided meshes for TRI6/TET10
//    (straight simplices are affine; a distorted quadrilateral is not, and its
//    isoparametric space holds no quadratic in x, y).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

constexpr double kE = 1000.0, kNu = 0.3;

struct QuadraticCase {
  const char* mesh;
  int dimension;
};

std::string name(const ::testing::TestParamInfo<QuadraticCase>& info) {
  std::string n = info.param.mesh;
  return n.substr(0, n.find('.'));
}

const std::string kMaterial =
    "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"1000\"/>"
    "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.3\"/>";
const std::string kTight =
    "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-14\"/>"
    "<Parameter name=\"Absolute Tolerance\" type=\"double\" value=\"1e-14\"/></ParameterList>";

std::vector<std::string> boundarySets(int dimension) {
  return dimension == 2 ? std::vector<std::string>{"left", "right", "bottom", "top"}
                        : std::vector<std::string>{"left", "right", "bottom", "top", "front", "back"};
}

class QuadraticPatch : public ::testing::TestWithParam<QuadraticCase> {};

TEST_P(QuadraticPatch, LinearFieldIsReproducedOnCurvedDistortedMesh) {
  const QuadraticCase c = GetParam();
  const std::string dir = scratchDirectory(std::string("quadratic_patch_") + c.mesh);
  const std::string meshFile = dir + "/distorted.e";
  writeDistortedCopy(shippedMesh(c.mesh), meshFile, 0.25);

  // u = A X + b, a general linear field (stretch, shear and rotation parts).
  const double A[3][3] = {{1e-3, 4e-4, -2e-4}, {-3e-4, 2e-3, 5e-4}, {1e-4, -6e-4, -1e-3}};
  const double b[3] = {1e-3, -2e-3, 5e-4};
  const char* axes[] = {"x", "y", "z"};
  std::string conditions = "<ParameterList name=\"Dirichlet Conditions\">";
  for (const auto& set : boundarySets(c.dimension))
    for (int i = 0; i < c.dimension; ++i)
      conditions += dirichletXml(set + "_" + axes[i], set, axes[i], b[i],
                                 std::vector<double>(A[i], A[i] + c.dimension), "constant");
  conditions += "</ParameterList>" + kTight;
  const std::string deck = dir + "/patch.xml";
  writeOnRoot(deck, deckXml(meshFile, kMaterial, conditions));

  solver::Simulation simulation(deck, worldComm(), nullptr);
  const auto summary = simulation.run();
  EXPECT_EQ(summary.steps, 1);

  const auto [maxError, maxValue] = linearFieldError(simulation, A, b);
  if (worldComm()->getRank() == 0)
    std::cout << c.mesh << ": linear field on a curved distorted mesh, max nodal error " << maxError << " (max |u| "
              << maxValue << ")\n";
  EXPECT_LT(maxError, 1e-10 * maxValue) << "patch test failed on " << c.mesh;
}

/// The column under its own weight along the last axis (y in 2D plane strain,
/// z in 3D): u_last = g / (lambda + 2 mu) (s^2 / 2 - H s), s the last
/// coordinate, H the height (1), the other components zero. Returns the max
/// nodal error relative to max |u|.
double columnUnderGravity(const std::string& meshFile, const std::string& dir, int dimension) {
  const double g = 10.0;
  const int last = dimension - 1;
  std::string body = "<ParameterList name=\"Dirichlet Conditions\">";
  // rollers: the sides hold their normal component; the bottom holds everything
  body += dirichletXml("left_x", "left", "x", 0.0, {}, "constant") + dirichletXml("right_x", "right", "x", 0.0, {}, "constant");
  if (dimension == 3)
    body += dirichletXml("front_y", "front", "y", 0.0, {}, "constant") + dirichletXml("back_y", "back", "y", 0.0, {}, "constant");
  body += dirichletXml("bottom_all", "bottom", "all", 0.0, {}, "constant");
  body += "</ParameterList><ParameterList name=\"Body Forces\"><ParameterList name=\"weight\">"
          "<Parameter name=\"Force\" type=\"Array(double)\" value=\"{";
  for (int i = 0; i < dimension; ++i) body += std::string(i ? ", " : "") + (i == last ? "-10" : "0");
  body += "}\"/><Parameter name=\"Function\" type=\"string\" value=\"constant\"/></ParameterList></ParameterList>";
  if (dimension == 2)
    body += "<ParameterList name=\"Problem\"><Parameter name=\"Plane Assumption\" type=\"string\" "
            "value=\"Plane Strain\"/></ParameterList>";
  body += kTight;
  const std::string deck = dir + "/column.xml";
  writeOnRoot(deck, deckXml(meshFile, kMaterial, body));
  solver::Simulation simulation(deck, worldComm(), nullptr);
  simulation.run();

  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double H = 1.0;
  double maxError = 0, maxValue = 0;
  forOwnedNodes(simulation, [&](long long, const double* X, const double* u) {
    const double s = X[last];
    for (int i = 0; i < dimension; ++i) {
      const double exact = i == last ? g / (lambda + 2 * mu) * (s * s / 2 - H * s) : 0.0;
      maxError = std::max(maxError, std::abs(u[i] - exact));
      maxValue = std::max(maxValue, std::abs(exact));
    }
  });
  return globalMax(maxError) / globalMax(maxValue);
}

TEST_P(QuadraticPatch, QuadraticFieldIsReproducedOnAffineCells) {
  const QuadraticCase c = GetParam();
  const std::string dir = scratchDirectory(std::string("quadratic_column_") + c.mesh);
  const double error = columnUnderGravity(shippedMesh(c.mesh), dir, c.dimension);
  if (worldComm()->getRank() == 0)
    std::cout << c.mesh << ": quadratic field (column under gravity), max relative nodal error " << error << "\n";
  EXPECT_LT(error, 1e-10) << c.mesh;
}

INSTANTIATE_TEST_SUITE_P(QuadraticCells, QuadraticPatch,
                         ::testing::Values(QuadraticCase{"block2d_quad8.e", 2}, QuadraticCase{"block2d_quad9.e", 2},
                                           QuadraticCase{"block2d_tri6.e", 2}, QuadraticCase{"block3d_hex20.e", 3},
                                           QuadraticCase{"block3d_hex27.e", 3}, QuadraticCase{"block3d_tet10.e", 3}),
                         name);

class QuadraticSimplexPatch : public ::testing::TestWithParam<QuadraticCase> {};

TEST_P(QuadraticSimplexPatch, QuadraticFieldIsReproducedOnDistortedStraightSimplices) {
  const QuadraticCase c = GetParam();
  const std::string dir = scratchDirectory(std::string("quadratic_column_distorted_") + c.mesh);
  const std::string meshFile = dir + "/distorted.e";
  writeDistortedCopy(shippedMesh(c.mesh), meshFile, 0.25, true);
  const double error = columnUnderGravity(meshFile, dir, c.dimension);
  if (worldComm()->getRank() == 0)
    std::cout << c.mesh << ": quadratic field on a distorted straight-sided mesh, max relative nodal error " << error
              << "\n";
  EXPECT_LT(error, 1e-10) << c.mesh;
}

INSTANTIATE_TEST_SUITE_P(QuadraticSimplices, QuadraticSimplexPatch,
                         ::testing::Values(QuadraticCase{"block2d_tri6.e", 2}, QuadraticCase{"block3d_tet10.e", 3}),
                         name);

}  // namespace
}  // namespace coulomb::test
