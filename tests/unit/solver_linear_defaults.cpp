// The linear-solver defaults merged into a deck's "Linear Solver" list: what
// the user wrote must survive (no default key that overrides it).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include "coulomb/solver/LinearSolverFactory.hpp"

namespace coulomb::solver {
namespace {

constexpr long long kLarge = 100000;  // MueLu, not Ifpack2

const Teuchos::ParameterList& mueLu(const LinearSolver& s) {
  return s.parameters->sublist("Preconditioner Types").sublist("MueLu");
}

// MueLu gives "smoother: pre/post type" precedence over "smoother: type": a
// default pre/post pair merged beside a deck's "smoother: type" replaced it
// silently (xml/friction_punch.xml's RILUK ran as Gauss-Seidel).
TEST(LinearSolverDefaults, UserSmootherIsNotOverriddenByDefaultPrePost) {
  Teuchos::ParameterList user("Linear Solver");
  user.sublist("Preconditioner Types").sublist("MueLu").set("smoother: type", "RILUK");
  const LinearSolver s = buildLinearSolver(user, 3, kLarge, /*symmetric=*/false);
  EXPECT_EQ(mueLu(s).get<std::string>("smoother: type"), "RILUK");
  EXPECT_FALSE(mueLu(s).isParameter("smoother: pre type"));
  EXPECT_FALSE(mueLu(s).isParameter("smoother: post type"));
  EXPECT_FALSE(mueLu(s).isSublist("smoother: pre params"));
  // The other defaults are still filled in.
  EXPECT_EQ(mueLu(s).get<std::string>("multigrid algorithm"), "unsmoothed");
  EXPECT_EQ(s.parameters->get<std::string>("Preconditioner Type"), "MueLu");
}

TEST(LinearSolverDefaults, NonsymmetricDefaultsSmoothForwardThenBackward) {
  const LinearSolver s = buildLinearSolver(Teuchos::ParameterList("Linear Solver"), 3, kLarge, false);
  EXPECT_EQ(mueLu(s).get<std::string>("smoother: pre type"), "RELAXATION");
  EXPECT_EQ(mueLu(s).sublist("smoother: pre params").get<std::string>("relaxation: type"), "Gauss-Seidel");
  EXPECT_TRUE(mueLu(s).sublist("smoother: post params").get<bool>("relaxation: backward mode"));
  EXPECT_FALSE(mueLu(s).isParameter("smoother: type"));
}

}  // namespace
}  // namespace coulomb::solver
