// Patch tests: a linear displacement field prescribed on the whole boundary
// of a distorted mesh must be reproduced inside, for every cell type.
#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

struct PatchCase {
  const char* mesh;
  int dimension;
};

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, LinearFieldIsReproducedOnDistortedMesh) {
  const PatchCase c = GetParam();
  const std::string name = std::string("patch_") + c.mesh;
  const std::string dir = scratchDirectory(name);
  const std::string meshFile = dir + "/distorted.e";
  writeDistortedCopy(shippedMesh(c.mesh), meshFile, 0.25);

  // u = A X + b, a general linear field (stretch, shear and rotation parts).
  const double A[3][3] = {{1e-3, 4e-4, -2e-4}, {-3e-4, 2e-3, 5e-4}, {1e-4, -6e-4, -1e-3}};
  const double b[3] = {1e-3, -2e-3, 5e-4};
  const char* axes[] = {"x", "y", "z"};
  const std::vector<std::string> sets = c.dimension == 2 ? std::vector<std::string>{"left", "right", "bottom", "top"}
                                                        : std::vector<std::string>{"left", "right", "bottom", "top", "front", "back"};
  std::string conditions = "<ParameterList name=\"Dirichlet Conditions\">";
  for (const auto& set : sets)
    for (int i = 0; i < c.dimension; ++i)
      conditions += dirichletXml(set + "_" + axes[i], set, axes[i], b[i],
                                 std::vector<double>(A[i], A[i] + c.dimension), "constant");
  conditions += "</ParameterList>"
                "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-14\"/>"
                "<Parameter name=\"Absolute Tolerance\" type=\"double\" value=\"1e-14\"/></ParameterList>";
  const std::string material =
      "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"1000\"/>"
      "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.3\"/>";
  const std::string deck = dir + "/patch.xml";
  writeOnRoot(deck, deckXml(meshFile, material, conditions));

  solver::Simulation simulation(deck, worldComm(), nullptr);
  const auto summary = simulation.run();
  EXPECT_EQ(summary.steps, 1);

  const auto [maxError, maxValue] = linearFieldError(simulation, A, b);
  EXPECT_LT(maxError, 1e-10 * maxValue) << "patch test failed on " << c.mesh;
}

INSTANTIATE_TEST_SUITE_P(AllCellTypes, PatchTest,
                         ::testing::Values(PatchCase{"block2d.e", 2}, PatchCase{"block2d_tri.e", 2},
                                           PatchCase{"block3d.e", 3}, PatchCase{"block3d_tet.e", 3}),
                         [](const auto& info) {
                           std::string n = info.param.mesh;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace coulomb::test
