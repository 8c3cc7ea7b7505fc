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
  EXPECT_TRUE(mueLu(s).sublist("smoother: pre params").get<bool>("relaxation: use l1"));
  EXPECT_TRUE(mueLu(s).sublist("smoother: post params").get<bool>("relaxation: use l1"));
  EXPECT_FALSE(mueLu(s).isParameter("smoother: type"));
}

// Naming the default choices must not lose the tuned defaults: MueLu's own
// (smoothed aggregation, Chebyshev) made hertz3d_r2 take 27.9 s and 446 MB
// instead of 16.4 s and 300 MB.
TEST(LinearSolverDefaults, NamingTheDefaultChoicesKeepsTheirTunedKeys) {
  Teuchos::ParameterList user("Linear Solver");
  user.set("Linear Solver Type", "Belos");
  user.set("Preconditioner Type", "MueLu");
  auto& belos = user.sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block GMRES");
  belos.sublist("Solver Types").sublist("Pseudo Block GMRES").set("Maximum Iterations", 77);
  const LinearSolver s = buildLinearSolver(user, 3, kLarge, /*symmetric=*/false);
  EXPECT_EQ(mueLu(s).get<std::string>("multigrid algorithm"), "unsmoothed");
  EXPECT_EQ(mueLu(s).get<std::string>("smoother: pre type"), "RELAXATION");
  const auto& gmres = s.parameters->sublist("Linear Solver Types").sublist("Belos").sublist("Solver Types").sublist(
      "Pseudo Block GMRES");
  EXPECT_EQ(gmres.get<int>("Num Blocks"), 100);
  EXPECT_EQ(gmres.get<int>("Maximum Iterations"), 77);  // the deck's value stays
  EXPECT_TRUE(s.usesMueLu);
}

// Another Krylov method or preconditioner gets exactly what the deck wrote for
// it; a choice the deck left at the default still gets its keys.
TEST(LinearSolverDefaults, OtherChoicesGetExactlyWhatTheDeckWrote) {
  Teuchos::ParameterList user("Linear Solver");
  user.set("Linear Solver Type", "Belos");
  user.sublist("Linear Solver Types").sublist("Belos").set("Solver Type", "Block CG");
  const LinearSolver krylov = buildLinearSolver(user, 3, kLarge, /*symmetric=*/true);
  const auto& belos = krylov.parameters->sublist("Linear Solver Types").sublist("Belos");
  // (Stratimikos fills in Belos' own values for every Krylov method; ours are 1e-9 and false.)
  EXPECT_NE(belos.sublist("Solver Types").sublist("Block CG").get<double>("Convergence Tolerance"), 1e-9);
  EXPECT_TRUE(belos.sublist("Solver Types").sublist("Pseudo Block CG").get<bool>("Assert Positive Definiteness"));
  EXPECT_EQ(krylov.parameters->get<std::string>("Preconditioner Type"), "MueLu");
  EXPECT_EQ(mueLu(krylov).get<std::string>("multigrid algorithm"), "unsmoothed");

  user.set("Preconditioner Type", "Ifpack2");
  const LinearSolver ifpack2 = buildLinearSolver(user, 3, kLarge, /*symmetric=*/true);
  EXPECT_FALSE(ifpack2.usesMueLu);
  EXPECT_NE(ifpack2.parameters->sublist("Preconditioner Types").sublist("Ifpack2").get<std::string>("Prec Type"),
            "RELAXATION");
}

// Below 5000 DoFs the default is Ifpack2 RELAXATION: a deck that names
// Ifpack2 with another method (ILUT) must not get its relaxation keys.
TEST(LinearSolverDefaults, AnotherIfpack2MethodGetsNoRelaxationKeys) {
  Teuchos::ParameterList user("Linear Solver");
  user.set("Preconditioner Type", "Ifpack2");
  user.sublist("Preconditioner Types").sublist("Ifpack2").set("Prec Type", "ILUT");
  const LinearSolver ilut = buildLinearSolver(user, 3, 1000, /*symmetric=*/true);
  const auto& settings = ilut.parameters->sublist("Preconditioner Types").sublist("Ifpack2").sublist("Ifpack2 Settings");
  // (Ifpack2 fills in its own "Jacobi"; the default's would be "Symmetric Gauss-Seidel".)
  EXPECT_NE(settings.get<std::string>("relaxation: type"), "Symmetric Gauss-Seidel");

  Teuchos::ParameterList relaxation("Linear Solver");
  relaxation.set("Preconditioner Type", "Ifpack2");
  const LinearSolver same = buildLinearSolver(relaxation, 3, 1000, /*symmetric=*/true);
  EXPECT_EQ(same.parameters->sublist("Preconditioner Types").sublist("Ifpack2").sublist("Ifpack2 Settings").get<std::string>(
                "relaxation: type"),
            "Symmetric Gauss-Seidel");
}

}  // namespace
}  // namespace coulomb::solver
