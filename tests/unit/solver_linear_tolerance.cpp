// The adaptive Krylov tolerance of a Newton iteration (solver/LinearTolerance.hpp).
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include "coulomb/solver/Deck.hpp"
#include "coulomb/solver/LinearTolerance.hpp"

namespace coulomb::solver {
namespace {

const LinearToleranceSettings kDefaults;

TEST(LinearTolerance, FirstIterationOfAStepSolvesToTheMaximum) {
  // Far from the Newton tolerance, with no rate yet: the loosest tolerance.
  EXPECT_DOUBLE_EQ(linearTolerance(kDefaults, 100.0, -1.0, 1e-6), kDefaults.maximum);
}

TEST(LinearTolerance, WithoutContactTheFirstSolveMeetsTheTarget) {
  // No active set to find: a linear problem must converge in one iteration,
  // so the first solve goes to 0.1 x target / ||f|| (1e-9 here).
  LinearToleranceSettings bulk = kDefaults;
  bulk.looseFirstIteration = false;
  EXPECT_NEAR(linearTolerance(bulk, 100.0, -1.0, 1e-6), 1e-9, 1e-21);
}

TEST(LinearTolerance, FastConvergenceTightensAsTheSquareOfTheRate) {
  // ||f|| fell by 1e-3: Eisenstat-Walker choice 2 gives 0.9 x 1e-6, tighter
  // than the maximum; the Newton target (1e-12 x 0.1 / 1e-3) asks for less.
  const double eta = linearTolerance(kDefaults, 1e-3, 1.0, 1e-12);
  EXPECT_NEAR(eta, 0.9e-6, 1e-18);
  // A slow iteration (rate 0.5) is capped by the maximum.
  EXPECT_DOUBLE_EQ(linearTolerance(kDefaults, 0.5, 1.0, 1e-12), kDefaults.maximum);
}

TEST(LinearTolerance, LastIterationOnlyReachesTheNewtonTarget) {
  // Rate 1e-4 would ask for 9e-9; but ||f|| = 1e-5 is 10x the target 1e-6,
  // and a linear residual of 0.1 x target needs only eta = 1e-2 -> capped 1e-3.
  EXPECT_DOUBLE_EQ(linearTolerance(kDefaults, 1e-5, 1e-1, 1e-6), kDefaults.maximum);
  // 1e4 x the target: eta = 0.1 / 1e4 = 1e-5 (larger than the rate's 9e-9).
  EXPECT_NEAR(linearTolerance(kDefaults, 1e-2, 1e2, 1e-6), 1e-5, 1e-17);
}

TEST(LinearTolerance, NeverBelowTheMinimum) {
  EXPECT_DOUBLE_EQ(linearTolerance(kDefaults, 1e-9, 1.0, 1e-30), kDefaults.minimum);
  EXPECT_DOUBLE_EQ(linearTolerance(kDefaults, 0.0, 1.0, 1e-6), kDefaults.minimum);
  LinearToleranceSettings loose = kDefaults;
  loose.maximum = 1e-2;
  EXPECT_DOUBLE_EQ(linearTolerance(loose, 100.0, -1.0, 1e-6), 1e-2);
  // A maximum below the minimum: the minimum (no inverted clamp).
  LinearToleranceSettings inverted = kDefaults;
  inverted.maximum = 1e-12;
  EXPECT_DOUBLE_EQ(linearTolerance(inverted, 100.0, -1.0, 1e-6), kDefaults.minimum);
}

Teuchos::ParameterList deckWithMesh() {
  Teuchos::ParameterList deck("Coulomb");
  deck.sublist("Mesh").set("File", std::string("mesh.e"));
  return deck;
}

TEST(LinearToleranceDeck, AdaptiveByDefaultWithItsMaximumFromTheDeck) {
  auto deck = deckWithMesh();
  EXPECT_TRUE(parseRunSettings(deck, "deck.xml").newton.linearTolerance.adaptive);
  EXPECT_DOUBLE_EQ(parseRunSettings(deck, "deck.xml").newton.linearTolerance.maximum, 1e-3);
  deck.sublist("Newton").set("Maximum Linear Tolerance", 1e-4);
  EXPECT_DOUBLE_EQ(parseRunSettings(deck, "deck.xml").newton.linearTolerance.maximum, 1e-4);
  deck.sublist("Newton").set("Linear Tolerance", std::string("Fixed"));
  EXPECT_FALSE(parseRunSettings(deck, "deck.xml").newton.linearTolerance.adaptive);
}

TEST(LinearToleranceDeck, NoxToleranceOrForcingTermInTheDeckMeansFixed) {
  // What the deck gives NOX is not overridden silently.
  auto tolerance = deckWithMesh();
  tolerance.sublist("Nonlinear Solver").sublist("Direction").sublist("Newton").sublist("Linear Solver").set(
      "Tolerance", 1e-6);
  EXPECT_FALSE(parseRunSettings(tolerance, "deck.xml").newton.linearTolerance.adaptive);
  auto forcing = deckWithMesh();
  forcing.sublist("Nonlinear Solver").sublist("Direction").sublist("Newton").set("Forcing Term Method",
                                                                                   std::string("Type 2"));
  EXPECT_FALSE(parseRunSettings(forcing, "deck.xml").newton.linearTolerance.adaptive);
  EXPECT_TRUE(noxSetsLinearTolerance(forcing.sublist("Nonlinear Solver")));
  EXPECT_FALSE(noxSetsLinearTolerance(deckWithMesh()));
}

}  // namespace
}  // namespace coulomb::solver
