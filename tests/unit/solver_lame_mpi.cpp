// Convergence: the thick-walled cylinder under internal pressure (Lamé),
// plane strain, on three quarter-annulus meshes (h, h/2, h/4). The nodal RMS
// displacement error must fall at the rate of bilinear elements, 2.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

constexpr double kE = 1000.0, kNu = 0.3, kPressure = 1.0, kInner = 1.0, kOuter = 2.0;

/// Plane-strain Lamé solution: sigma_rr = A - B/r^2, u_r = (1+nu)/E ((1-2nu) A r + B/r).
double exactRadialDisplacement(double r) {
  const double A = kPressure * kInner * kInner / (kOuter * kOuter - kInner * kInner);
  const double B = A * kOuter * kOuter;
  return (1 + kNu) / kE * ((1 - 2 * kNu) * A * r + B / r);
}

/// Relative nodal RMS error of one mesh.
double solveAndMeasure(const std::string& meshFile, const std::string& dir) {
  const std::string body =
      "<ParameterList name=\"Dirichlet Conditions\">" + dirichletXml("sym x", "symmetry_x", "x", 0.0) +
      dirichletXml("sym y", "symmetry_y", "y", 0.0) +
      "</ParameterList><ParameterList name=\"Neumann Conditions\"><ParameterList name=\"inner pressure\">"
      "<Parameter name=\"Side Set\" type=\"string\" value=\"inner\"/>"
      "<Parameter name=\"Value\" type=\"double\" value=\"1.0\"/></ParameterList></ParameterList>"
      "<ParameterList name=\"Problem\"><Parameter name=\"Plane Assumption\" type=\"string\" value=\"Plane Strain\"/></ParameterList>"
      "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-12\"/></ParameterList>";
  const std::string material =
      "<Parameter name=\"Young's Modulus\" type=\"double\" value=\"1000\"/>"
      "<Parameter name=\"Poisson's Ratio\" type=\"double\" value=\"0.3\"/>";
  const std::string deck = dir + "/lame.xml";
  writeOnRoot(deck, deckXml(meshFile, material, body));
  solver::Simulation simulation(deck, worldComm(), nullptr);
  simulation.run();
  double error2 = 0, norm2 = 0;
  forOwnedNodes(simulation, [&](long long, const double* X, const double* u) {
    const double r = std::hypot(X[0], X[1]);
    const double ur = exactRadialDisplacement(r);
    const double ex = ur * X[0] / r, ey = ur * X[1] / r;
    error2 += (u[0] - ex) * (u[0] - ex) + (u[1] - ey) * (u[1] - ey);
    norm2 += ex * ex + ey * ey;
  });
  return std::sqrt(globalSum(error2) / globalSum(norm2));
}

TEST(LameCylinder, DisplacementErrorConvergesAtRateTwo) {
  const std::string dir = scratchDirectory("lame");
  std::vector<double> errors;
  for (const char* mesh : {"quarter_annulus2d_n4.e", "quarter_annulus2d_n8.e", "quarter_annulus2d_n16.e"})
    errors.push_back(solveAndMeasure(shippedMesh(mesh), dir));
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double rate = std::log2(errors[i] / errors[i + 1]);
    if (worldComm()->getRank() == 0)
      std::cout << "Lame: error " << errors[i] << " -> " << errors[i + 1] << ", rate " << rate << "\n";
    EXPECT_GT(rate, 1.8);
    EXPECT_LT(rate, 2.3);
  }
  EXPECT_LT(errors.back(), 2e-3);
}

}  // namespace
}  // namespace coulomb::test
