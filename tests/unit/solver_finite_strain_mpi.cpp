// Finite strain: a homogeneous deformation with a 60 degree rotation and
// stretches, prescribed on the whole boundary of a Neo-Hookean cube, is an
// exact equilibrium state; Newton must find it and converge quadratically.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include <filesystem>

#include <Tpetra_Vector.hpp>

#include "TestSupport.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusResults.hpp"

namespace coulomb::test {
namespace {

/// u = (F - I) X with F = R_z(60 deg) diag(1.2, 0.9, 1.05) on every face of
/// a Neo-Hookean cube, reached in `steps` load steps. `boundaryIncrement`:
/// the deck's Load Stepping/Boundary Increment.
std::string rotationDeck(const std::string& name, int steps, int maximumCutbacks, double F[3][3],
                         const std::string& mesh = shippedMesh("block3d.e"),
                         const std::string& boundaryIncrement = "Imposed") {
  const std::string dir = scratchDirectory(name);
  const double theta = M_PI / 3;
  const double U[3] = {1.2, 0.9, 1.05};  // principal stretches along x, y, z
  // F = R_z(theta) diag(U); u = (F - I) X
  const double rotation[3][3] = {{std::cos(theta) * U[0], -std::sin(theta) * U[1], 0},
                                 {std::sin(theta) * U[0], std::cos(theta) * U[1], 0},
                                 {0, 0, U[2]}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F[i][j] = rotation[i][j];
  const char* axes[] = {"x", "y", "z"};
  std::string body = "<ParameterList name=\"Dirichlet Conditions\">";
  for (const char* set : {"left", "right", "bottom", "top", "front", "back"})
    for (int i = 0; i < 3; ++i) {
      std::vector<double> c(F[i], F[i] + 3);
      c[i] -= 1.0;
      body += dirichletXml(std::string(set) + "_" + axes[i], set, axes[i], 0.0, c);
    }
  body += "</ParameterList><ParameterList name=\"Load Stepping\"><Parameter name=\"Number of Steps\" type=\"int\" value=\"" + std::to_string(steps) +
          "\"/><Parameter name=\"Maximum Cutbacks\" type=\"int\" value=\"" + std::to_string(maximumCutbacks) +
          // Each step starts from the last converged state with the new
          // boundary values imposed (the interior where it was), so that the
          // residual sequence measures Newton from a cold start (the rate
          // test below); an extrapolated start, or the boundary increment
          // taken through the tangent, would begin near the answer.
          "\"/><Parameter name=\"Predictor\" type=\"string\" value=\"Previous\"/>"
          "<Parameter name=\"Boundary Increment\" type=\"string\" value=\"" + boundaryIncrement + "\"/></ParameterList>"
          "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-11\"/>"
          "<Parameter name=\"Absolute Tolerance\" type=\"double\" value=\"1e-12\"/>"
          // Exact linear solves: the rate test measures the tangent, not the
          // adaptive Krylov tolerance (which trades the last digits of the rate
          // for fewer Krylov iterations).
          "<Parameter name=\"Linear Tolerance\" type=\"string\" value=\"Fixed\"/></ParameterList>"
          "<ParameterList name=\"Linear Solver\"><Parameter name=\"Linear Solver Type\" type=\"string\" value=\"Belos\"/>"
          "<ParameterList name=\"Linear Solver Types\"><ParameterList name=\"Belos\">"
          "<Parameter name=\"Solver Type\" type=\"string\" value=\"Pseudo Block GMRES\"/><ParameterList name=\"Solver Types\">"
          "<ParameterList name=\"Pseudo Block GMRES\"><Parameter name=\"Convergence Tolerance\" type=\"double\" value=\"1e-12\"/>"
          "<Parameter name=\"Maximum Iterations\" type=\"int\" value=\"1000\"/><Parameter name=\"Num Blocks\" type=\"int\" value=\"200\"/></ParameterList></ParameterList></ParameterList>"
          "</ParameterList></ParameterList>";
  const std::string material = neoHookeanXml(1000, 0.3);
  const std::string deck = dir + "/rotation.xml";
  writeOnRoot(deck, deckXml(mesh, material, body));
  return deck;
}

/// The largest nodal error (all ranks) against u = (F - I) X.
double rotationError(const solver::Simulation& simulation, double F[3][3]) {
  double A[3][3], b[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A[i][j] = F[i][j] - (i == j ? 1.0 : 0.0);
  return linearFieldError(simulation, A, b).error;
}

TEST(FiniteStrain, LargeRotationConvergesQuadraticallyToExactField) {
  double F[3][3];
  solver::Simulation simulation(rotationDeck("finite_strain", 12, 5, F), worldComm(), nullptr);
  const auto summary = simulation.run();
  ASSERT_EQ(summary.steps, 12);
  ASSERT_EQ(summary.cutbacks, 0);

  double maxError = rotationError(simulation, F);
  EXPECT_LT(maxError, 1e-8);

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

// The same homogeneous deformation on the quadratic cells, on a distorted copy
// of their mesh whose interior corner and mid-side nodes moved (curved
// cells): still an exact equilibrium state, reached to round-off.
class FiniteStrainQuadratic : public ::testing::TestWithParam<const char*> {};

TEST_P(FiniteStrainQuadratic, LargeRotationIsExactOnCurvedDistortedMesh) {
  const std::string type = GetParam();
  const std::string dir = scratchDirectory("finite_strain_" + type);
  const std::string mesh = dir + "/distorted.e";
  writeDistortedCopy(shippedMesh("block3d_" + type + ".e"), mesh, 0.25);
  double F[3][3];
  // The boundary increment through the tangent (not the default): with it
  // imposed instead, the first iterate of a step (interior nodes where the
  // last step left them) inverted a small curved TET10 cell near the moving
  // boundary and the step was cut back; now no step is.
  solver::Simulation simulation(rotationDeck("finite_strain_" + type, 12, 5, F, mesh, "Tangent"), worldComm(),
                                nullptr);
  const auto summary = simulation.run();
  double maxError = rotationError(simulation, F);
  if (worldComm()->getRank() == 0)
    std::cout << type << ": Neo-Hookean 60 degree rotation in " << summary.steps << " steps (" << summary.cutbacks
              << " cutbacks), max nodal error " << maxError << "\n";
  EXPECT_LT(maxError, 1e-8) << type;
  EXPECT_EQ(summary.cutbacks, 0) << type;
}

// Boundary Increment = Tangent: the first Newton step of each load step
// solves the problem linearised at the last converged state with the whole
// boundary increment. At a homogeneous state with a homogeneous increment
// prescribed on the whole boundary, the homogeneous increment solves the
// linearised problem, so that first iterate is the exact next state, up to
// the linear solve's tolerance (with the increment imposed on the boundary
// alone, Newton needs 6 iterations from the cold interior); even the
// whole 60 degree rotation in one step, which then inverts elements.
TEST(FiniteStrain, TangentBoundaryIncrementReachesAHomogeneousStateInOneIteration) {
  for (int steps : {12, 1}) {
    double F[3][3];
    solver::Simulation simulation(
        rotationDeck("finite_strain_tangent_" + std::to_string(steps), steps, 0, F, shippedMesh("block3d.e"), "Tangent"),
        worldComm(), nullptr);
    const auto summary = simulation.run();
    ASSERT_EQ(summary.steps, steps);
    EXPECT_LT(rotationError(simulation, F), 1e-8);
    for (const auto& norms : summary.stepResidualNorms) {
      ASSERT_GE(norms.size(), 2u);
      EXPECT_LT(norms[1], 1e-9 * norms[0]) << "the first iterate is the next state (to the linear solve's tolerance)";
      EXPECT_LE(norms.size(), 3u) << "at most one more iteration, to meet the Newton tolerance of 1e-11";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(QuadraticCells, FiniteStrainQuadratic, ::testing::Values("hex20", "hex27", "tet10"));

/// The Neo-Hookean unit cube (block3d.e), bottom fixed, top pulled up by 0.3
/// and turned in its plane (u_x = 0.2 - 0.4 y, u_y = 0.4 x - 0.2: about 22
/// degrees), in `steps` steps, no cutback allowed.
std::string twistDeck(const std::string& name, int steps, const std::string& boundaryIncrement) {
  const std::string dir = scratchDirectory(name);
  const std::string body =
      "<ParameterList name=\"Dirichlet Conditions\">" + dirichletXml("fix", "bottom", "all", 0.0) +
      dirichletXml("twist x", "top", "x", 0.2, {0.0, -0.4, 0.0}) + dirichletXml("twist y", "top", "y", -0.2, {0.4, 0.0, 0.0}) +
      dirichletXml("pull", "top", "z", 0.3) +
      "</ParameterList><ParameterList name=\"Load Stepping\"><Parameter name=\"Number of Steps\" type=\"int\" value=\"" +
      std::to_string(steps) + "\"/><Parameter name=\"Maximum Cutbacks\" type=\"int\" value=\"0\"/>"
      "<Parameter name=\"Boundary Increment\" type=\"string\" value=\"" + boundaryIncrement + "\"/></ParameterList>"
      "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-10\"/></ParameterList>";
  const std::string material = neoHookeanXml(1000, 0.35);
  const std::string deck = dir + "/twist.xml";
  writeOnRoot(deck, deckXml(shippedMesh("block3d.e"), material, body));
  return deck;
}

// The twist in one step: with the increment imposed on the top face, an
// iterate inverts an element next to it and the run stops (no cutback
// allowed); through the tangent the step converges, to the state that five
// imposed steps reach (hyperelastic, no contact: the path does not matter).
TEST(FiniteStrain, TwistInOneStepConvergesWithTheBoundaryIncrementThroughTheTangent) {
  {
    solver::Simulation imposed(twistDeck("twist_imposed_1", 1, "Imposed"), worldComm(), nullptr);
    try {
      imposed.run();
      ADD_FAILURE() << "the imposed twist in one step converged";
    } catch (const coulomb::Error& e) {
      EXPECT_NE(std::string(e.what()).find("is inverted (det F <= 0)"), std::string::npos) << e.what();
    }
  }
  solver::Simulation reference(twistDeck("twist_imposed_5", 5, "Imposed"), worldComm(), nullptr);
  reference.run();
  solver::Simulation tangent(twistDeck("twist_tangent_1", 1, "Tangent"), worldComm(), nullptr);
  const auto summary = tangent.run();
  EXPECT_EQ(summary.steps, 1);
  EXPECT_EQ(summary.cutbacks, 0);
  Vector difference(tangent.displacement(), Teuchos::Copy);
  difference.update(-1.0, reference.displacement(), 1.0);
  EXPECT_LT(difference.normInf(), 1e-8 * reference.displacement().normInf());
  EXPECT_GT(reference.displacement().normInf(), 0.25);  // the pull of 0.3 is in it
  // The converged state carries the prescribed values (no DoF left behind).
  Vector pending(tangent.displacement(), Teuchos::Copy);
  const bool lags = tangent.assembler().constraints().pendingIncrements(1.0, tangent.displacement(), pending);
  EXPECT_FALSE(globalMax(lags ? 1.0 : 0.0) > 0.0);
}

// One step of 60 degrees inverts boundary elements in the first iterate:
// the stepper must halve the step until Newton converges, and write only
// converged steps.
TEST(FiniteStrain, FailedStepsAreCutBackAndNotWritten) {
  double F[3][3];
  const std::string deck = rotationDeck("cutback", 1, 6, F);
  solver::Simulation simulation(deck, worldComm(), nullptr);
  const auto summary = simulation.run();
  EXPECT_GE(summary.cutbacks, 2);
  EXPECT_DOUBLE_EQ(summary.stepTimes.back(), 1.0);
  if (worldComm()->getRank() == 0) {
    const auto written = io::readExodusResults(simulation.settings().outputFile);
    EXPECT_EQ(written.times, summary.stepTimes);
    EXPECT_LT(written.times.front(), 0.5);  // the first converged step is a cut one
  }
}

TEST(FiniteStrain, RunStopsWhenCutbacksAreExhausted) {
  double F[3][3];
  const std::string deck = rotationDeck("no_cutback", 1, 0, F);
  solver::Simulation simulation(deck, worldComm(), nullptr);
  try {
    simulation.run();
    FAIL() << "a step that cannot converge must end the run";
  } catch (const coulomb::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Maximum Cutbacks"), std::string::npos) << message;
    // The rejected iterate names the inverted element and its block (the
    // lowest-numbered one on any rank: the same message at every np).
    const auto at = message.find("an iterate was rejected: element ");
    ASSERT_NE(at, std::string::npos) << message;
    EXPECT_NE(message.find(" of block '", at), std::string::npos) << message;
    EXPECT_NE(message.find("' is inverted (det F <= 0)", at), std::string::npos) << message;
  }
  worldComm()->barrier();
  EXPECT_FALSE(std::filesystem::exists(simulation.settings().outputFile)) << "no complete-looking result may remain";
}

}  // namespace
}  // namespace coulomb::test
