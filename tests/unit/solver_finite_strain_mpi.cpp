// Finite strain: a homogeneous deformation with a 60 degree rotation and
// stretches, prescribed on the whole boundary of a Neo-Hookean cube, is an
// exact equilibrium state; Newton must find it and converge quadratically.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

TEST(FiniteStrain, LargeRotationConvergesQuadraticallyToExactField) {
  const std::string dir = scratchDirectory("finite_strain");
  const double theta = M_PI / 3;
  const double U[3] = {1.2, 0.9, 1.05};  // principal stretches along x, y, z
  // F = R_z(theta) diag(U); u = (F - I) X
  double F[3][3] = {{std::cos(theta) * U[0], -std::sin(theta) * U[1], 0},
                    {std::sin(theta) * U[0], std::cos(theta) * U[1], 0},
                    {0, 0, U[2]}};
  const char* axes[] = {"x", "y", "z"};
  std::string body = "<ParameterList name=\"Dirichlet Conditions\">";
  for (const char* set : {"left", "right", "bottom", "top", "front", "back"})
    for (int i = 0; i < 3; ++i) {
      std::vector<double> c(F[i], F[i] + 3);
      c[i] -= 1.0;
      body += dirichletXml(std::string(set) + "_" + axes[i], set, axes[i], 0.0, c);
    }
  body += "</ParameterList><ParameterList name=\"Load Stepping\"><Parameter name=\"Number of Steps\" type=\"int\" value=\"12\"/></ParameterList>"
          "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-11\"/>"
          "<Parameter name=\"Absolute Tolerance\" type=\"double\" value=\"1e-12\"/></ParameterList>"
          "<ParameterList name=\"Linear Solver\"><Parameter name=\"Linear Solver Type\" type=\"string\" value=\"Belos\"/>"
          "<ParameterList name=\"Linear Solver Types\"><ParameterList name=\"Belos\">"
          "<Parameter name=\"Solver Type\" type=\"string\" value=\"Pseudo Block GMRES\"/><ParameterList name=\"Solver Types\">"
          "<ParameterList name=\"Pseudo Block GMRES\"><Parameter name=\"Convergence Tolerance\" type=\"double\" value=\"1e-12\"/>"
          "<Parameter name=\"Maximum Iterations\" type=\"int\" value=\"1000\"/><Parameter name=\"Num Blocks\" type=\"int\" value=\"200\"/></ParameterList></ParameterList></ParameterList>"
          "</ParameterList></ParameterList>";
  const std::string material =
      "<Parameter name=\"Model\" type=\"string\" value=\"Neo-Hookean\"/>"
      "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"1000\"/>"
      "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.3\"/>";
  const std::string deck = dir + "/rotation.xml";
  writeOnRoot(deck, deckXml(shippedMesh("block3d.e"), material, body));

  solver::Simulation simulation(deck, worldComm(), nullptr);
  const auto summary = simulation.run();
  ASSERT_EQ(summary.steps, 12);
  ASSERT_EQ(summary.cutbacks, 0);

  double maxError = 0;
  forOwnedNodes(simulation, [&](long long, const double* X, const double* u) {
    for (int i = 0; i < 3; ++i) {
      double exact = -X[i];
      for (int j = 0; j < 3; ++j) exact += F[i][j] * X[j];
      maxError = std::max(maxError, std::abs(u[i] - exact));
    }
  });
  EXPECT_LT(globalMax(maxError), 1e-8);

  // Quadratic convergence: in the asymptotic range (relative residual below
  // 1e-2, above round-off) each iteration roughly squares the residual, so
  // the estimated order log(q_{k+1}) / log(q_k) of q = |f_k|/|f_0| is near 2.
  for (const auto& norms : summary.stepResidualNorms) {
    std::vector<double> q;
    for (double n : norms) q.push_back(n / norms.front());
    if (worldComm()->getRank() == 0) {
      std::cout << "relative residuals:";
      for (double v : q) std::cout << " " << v;
      std::cout << "\n";
    }
    int checked = 0;
    for (std::size_t k = 1; k + 1 < q.size(); ++k) {
      if (q[k] > 1e-2 || q[k + 1] < 1e-13) continue;
      EXPECT_GT(std::log(q[k + 1]) / std::log(q[k]), 1.8) << "at iteration " << k;
      ++checked;
    }
    EXPECT_GE(checked, 1) << "no iteration in the asymptotic range";
  }
}

}  // namespace
}  // namespace coulomb::test
