// StepController: the deck's step ends and the load functions' knots are
// landed on exactly after cutbacks, and the size grows back to nominal.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "coulomb/solver/StepController.hpp"

using coulomb::solver::StepController;

namespace {

StepController::Settings settings(double T, int N, int cutbacks = 5) {
  StepController::Settings s;
  s.finalTime = T;
  s.numberOfSteps = N;
  s.maximumCutbacks = cutbacks;
  return s;
}

/// Runs the controller to the end, failing every sub-step whose end is in `failAt` (once each).
std::vector<double> runWithFailures(StepController& c, std::vector<double> failAt) {
  std::vector<double> reached;
  while (!c.finished()) {
    const double t = c.nextTime();
    auto it = std::find_if(failAt.begin(), failAt.end(), [&](double f) { return std::abs(f - t) < 1e-12; });
    if (it != failAt.end()) {
      failAt.erase(it);
      EXPECT_TRUE(c.reject());
      continue;
    }
    c.accept(3);
    reached.push_back(c.time());
  }
  return reached;
}

bool contains(const std::vector<double>& v, double t) {
  return std::find(v.begin(), v.end(), t) != v.end();  // exact: landing points are hit bit for bit
}

}  // namespace

TEST(StepController, NominalGridWithoutFailures) {
  StepController c(settings(24.0, 24), {0.0, 4.0, 24.0});
  const auto reached = runWithFailures(c, {});
  ASSERT_EQ(reached.size(), 24u);
  for (int k = 1; k <= 24; ++k) EXPECT_EQ(reached[k - 1], 24.0 * k / 24);
}

TEST(StepController, EveryStepEndIsLandedOnAfterCutbacks) {
  // 10 steps of 0.1; the sub-steps ending at 0.3 fail twice (0.3, then 0.25),
  // which left the old controller on a grid 0.2 + k 0.05 + ... that skipped
  // step ends. Every deck step end must still be reached exactly.
  StepController c(settings(1.0, 10), {});
  const auto reached = runWithFailures(c, {0.3, 0.25, 0.7});
  for (int k = 1; k <= 10; ++k) EXPECT_TRUE(contains(reached, 1.0 * k / 10)) << "step end " << k;
  EXPECT_EQ(reached.back(), 1.0);
  // Between step ends no sub-step is longer than the nominal one.
  for (std::size_t i = 1; i < reached.size(); ++i) EXPECT_LE(reached[i] - reached[i - 1], 0.1 * (1 + 1e-12));
}

TEST(StepController, KnotsInsideAStepAreLandedOn) {
  // Function knots at 0.25 and 0.62 inside steps of 0.1: both reached exactly,
  // and the step ends too.
  StepController c(settings(1.0, 10), {0.0, 0.25, 0.62, 1.0, 3.0});
  const auto reached = runWithFailures(c, {});
  EXPECT_TRUE(contains(reached, 0.25));
  EXPECT_TRUE(contains(reached, 0.62));
  for (int k = 1; k <= 10; ++k) EXPECT_TRUE(contains(reached, 1.0 * k / 10));
  EXPECT_EQ(reached.size(), 12u);
  EXPECT_FALSE(contains(reached, 3.0));  // outside (0, T]
}

TEST(StepController, SizeGrowsBackToNominalAfterEasySubSteps) {
  StepController c(settings(8.0, 8), {});
  EXPECT_EQ(c.nextTime(), 1.0);
  ASSERT_TRUE(c.reject());  // 0.5
  ASSERT_TRUE(c.reject());  // 0.25
  EXPECT_DOUBLE_EQ(c.nextTime(), 0.25);
  std::vector<double> sizes;
  while (!c.finished()) {
    const double before = c.time();
    c.accept(2);
    sizes.push_back(c.time() - before);
  }
  // 0.25, 0.25 -> grow to 0.5: 0.5 lands at 1.0; two more -> 1.0 from then on.
  EXPECT_DOUBLE_EQ(sizes[0], 0.25);
  EXPECT_DOUBLE_EQ(sizes[1], 0.25);
  EXPECT_DOUBLE_EQ(sizes[2], 0.5);
  EXPECT_DOUBLE_EQ(c.size(), 1.0);
  EXPECT_DOUBLE_EQ(sizes.back(), 1.0);
}

TEST(StepController, HardSubStepsDoNotGrow) {
  auto s = settings(4.0, 4);
  s.easyIterations = 5;
  StepController c(s, {});
  ASSERT_TRUE(c.reject());
  for (int i = 0; i < 4; ++i) c.accept(9);  // hard: stays at 0.5
  EXPECT_DOUBLE_EQ(c.size(), 0.5);
  EXPECT_DOUBLE_EQ(c.time(), 2.0);
}

TEST(StepController, CutbacksAreLimitedInARow) {
  StepController c(settings(1.0, 1, 2), {});
  EXPECT_TRUE(c.reject());
  EXPECT_TRUE(c.reject());
  EXPECT_FALSE(c.reject());
  EXPECT_EQ(c.consecutiveCutbacks(), 2);
  c.accept(1);
  EXPECT_EQ(c.consecutiveCutbacks(), 0);
}

TEST(StepController, SizeHasAFloorWhenFailuresMoveWithTheLoad) {
  // A failure beyond t = 0.3 (a limit the load reaches): every sub-step ending
  // past it fails, those before converge. The run must stop after finitely
  // many sub-steps, not creep towards 0.3 in ever smaller ones.
  StepController c(settings(1.0, 10, 5), {});
  int subSteps = 0;
  bool stopped = false;
  while (!c.finished() && subSteps < 10000) {
    ++subSteps;
    if (c.nextTime() > 0.3 + 1e-12) {
      if (!c.reject()) {
        stopped = true;
        break;
      }
    } else {
      c.accept(2);
    }
  }
  EXPECT_TRUE(stopped);
  EXPECT_LT(subSteps, 100);
  EXPECT_GE(c.size(), 0.1 / 32 * (1 - 1e-12));
}

TEST(StepController, NoSliverStepBeforeALandingPoint) {
  // A knot at 0.06: the first sub-step fails and is halved to 0.03; from the
  // knot, the distance 0.04 to the step end 0.1 is split into two equal
  // sub-steps of 0.02, not 0.03 and a sliver of 0.01.
  auto s = settings(1.0, 10);
  s.easyIterations = 0;  // no growth
  StepController c(s, {0.06});
  EXPECT_DOUBLE_EQ(c.nextTime(), 0.06);
  EXPECT_FALSE(c.nextIsStepEnd());
  EXPECT_EQ(c.nominalStep(), 1);
  ASSERT_TRUE(c.reject());
  c.accept(1);
  c.accept(1);
  EXPECT_EQ(c.time(), 0.06);
  EXPECT_DOUBLE_EQ(c.nextTime(), 0.08);
  c.accept(1);
  EXPECT_EQ(c.nextTime(), 0.1);
  EXPECT_TRUE(c.nextIsStepEnd());
  c.accept(1);
  EXPECT_EQ(c.nominalStep(), 2);
}
