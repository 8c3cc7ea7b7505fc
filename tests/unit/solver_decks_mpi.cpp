// The decks users copy from xml/ give the analytic answers their header
// comments promise (each deck's comment states the expected result).
#include <gtest/gtest.h>

#include <cmath>

#include <Tpetra_MultiVector.hpp>

#include "TestSupport.hpp"
#include "coulomb/io/ExodusResults.hpp"

namespace coulomb::test {
namespace {

std::string deckPath(const std::string& name) { return std::string(COULOMB_SOURCE_DIR) + "/xml/" + name + ".xml"; }

/// Runs a shipped deck with its result in the scratch folder.
std::unique_ptr<solver::Simulation> runDeck(const std::string& name, std::string* result = nullptr) {
  const std::string output = scratchDirectory("deck_" + name) + "/" + name + ".e";
  auto simulation = std::make_unique<solver::Simulation>(deckPath(name), worldComm(), nullptr, output);
  simulation->run();
  if (result) *result = output;
  return simulation;
}

TEST(DeckBlockCompression, UniaxialStressAndDisplacement) {
  std::string result;
  auto simulation = runDeck("block_compression", &result);
  const double p = 100, E = 210000, nu = 0.3;
  double error = 0;
  forOwnedNodes(*simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[2] + p / E * X[2]), std::abs(u[0] - nu * p / E * X[0]),
                      std::abs(u[1] - nu * p / E * X[1])});
  });
  EXPECT_LT(globalMax(error), 1e-9 * p / E);
  const auto reaction = simulation->reactionTotal("bottom");
  EXPECT_NEAR(reaction[2], p * 1.0, 1e-6 * p);
  // The written file (read back with the exodusII library) has the stress.
  if (worldComm()->getRank() == 0) {
    const auto r = io::readExodusResults(result);
    ASSERT_EQ(r.times.size(), 4u);
    EXPECT_DOUBLE_EQ(r.times.back(), 1.0);
    for (double s : r.nodal.back()[r.nodalIndex("stress_zz")]) EXPECT_NEAR(s, -p, 1e-6 * p);
    for (double s : r.nodal.back()[r.nodalIndex("von_mises")]) EXPECT_NEAR(s, p, 1e-6 * p);
    EXPECT_NEAR(r.global.back()[r.globalIndex("reaction_bottom_z")], p, 1e-6 * p);
    EXPECT_NEAR(r.global[1][r.globalIndex("reaction_bottom_z")], p / 2, 1e-6 * p);  // ramp: half load at t = 0.5
  }
}

TEST(DeckPlateTraction, PlaneStressWithThickness) {
  auto simulation = runDeck("plate_traction_plane_stress");
  const double s = 50, E = 70000, nu = 0.33, t = 0.5;
  double error = 0;
  forOwnedNodes(*simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[0] - s / E * X[0]), std::abs(u[1] + nu * s / E * X[1])});
  });
  EXPECT_LT(globalMax(error), 1e-9 * s / E);
  EXPECT_NEAR(simulation->reactionTotal("left")[0], -s * 1.0 * t, 1e-8);
}

TEST(DeckColumnGravity, NodallyExactUnderBodyForce) {
  auto simulation = runDeck("column_gravity");
  const double b = 10, E = 1000;
  double error = 0;
  forOwnedNodes(*simulation, [&](long long, const double* X, const double* u) {
    error = std::max(error, std::abs(u[2] + b / E * (X[2] - X[2] * X[2] / 2)));
  });
  EXPECT_LT(globalMax(error), 1e-9 * b / E);
  EXPECT_NEAR(simulation->reactionTotal("bottom")[2], b, 1e-8);
}

TEST(DeckCylinderPressure, RadialDisplacementNearLame) {
  auto simulation = runDeck("cylinder_pressure_2d");
  const double nu = 0.3, E = 1000, A = 1.0 / 3, B = 4.0 / 3;
  double error = 0, scale = 0;
  forOwnedNodes(*simulation, [&](long long, const double* X, const double* u) {
    const double r = std::hypot(X[0], X[1]);
    const double ur = (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r);
    error = std::max(error, std::abs((u[0] * X[0] + u[1] * X[1]) / r - ur));
    scale = std::max(scale, ur);
  });
  // n = 8 mesh: the rate test shows 0.3 % RMS error; the pointwise error stays below 1 %.
  EXPECT_LT(globalMax(error), 1e-2 * globalMax(scale));
}

}  // namespace
}  // namespace coulomb::test
