// Detection of a cycling active set (ActiveSetCycle.hpp).
#include <gtest/gtest.h>

#include "coulomb/contact/ActiveSetCycle.hpp"

namespace coulomb::contact {
namespace {

void recordAll(ActiveSetCycle& cycle, const std::vector<std::uint64_t>& signatures) {
  for (std::uint64_t s : signatures) cycle.record(s, 60 + s, 3);
}

// Period 5, as neo_hookean_shear_3d's step 14: found once the sequence has
// repeated for two full periods, not before.
TEST(ActiveSetCycle, FindsAPeriodFiveCycleAfterTwoPeriods) {
  ActiveSetCycle cycle;
  recordAll(cycle, {11, 12, 1, 2, 3, 4, 5, 1, 2, 3, 4});
  EXPECT_EQ(cycle.period(), 0);
  cycle.record(5, 65, 2);
  EXPECT_EQ(cycle.period(), 5);
  EXPECT_EQ(cycle.describe(), "the active set cycles with period 5 (61 … 65 active nodes, 2 … 3 state changes per iterate)");
}

// Period 2 needs three periods: two flips back and forth may still settle.
TEST(ActiveSetCycle, PeriodTwoNeedsThreePeriods) {
  ActiveSetCycle cycle;
  recordAll(cycle, {7, 8, 7, 8, 7});
  EXPECT_EQ(cycle.period(), 0);
  recordAll(cycle, {8});
  EXPECT_EQ(cycle.period(), 2);
}

// An iterate that keeps its set ends the cycle (Newton iterates on that set);
// so does a new step.
TEST(ActiveSetCycle, AnUnchangedSetOrANewStepClearsIt) {
  ActiveSetCycle cycle;
  recordAll(cycle, {7, 8, 7, 8, 7, 8});
  ASSERT_EQ(cycle.period(), 2);
  cycle.record(8, 68, 0);
  EXPECT_EQ(cycle.period(), 0);
  EXPECT_EQ(cycle.describe(), "");
  recordAll(cycle, {7, 8, 7, 8, 7, 8});
  cycle.clear();
  EXPECT_EQ(cycle.period(), 0);
}

// Sets that keep changing without returning are no cycle, however long the
// sequence; nor is a sequence that revisits a set once.
TEST(ActiveSetCycle, NewSetsAreNoCycle) {
  ActiveSetCycle cycle;
  for (std::uint64_t s = 1; s <= 40; ++s) cycle.record(s, 60, 1);
  EXPECT_EQ(cycle.period(), 0);
  recordAll(cycle, {1, 2, 3, 1, 2, 4, 1, 2, 3});
  EXPECT_EQ(cycle.period(), 0);
}

// The shortest period is named: a period-2 cycle also repeats with 4.
TEST(ActiveSetCycle, NamesTheShortestPeriod) {
  ActiveSetCycle cycle;
  recordAll(cycle, {1, 2, 1, 2, 1, 2, 1, 2});
  EXPECT_EQ(cycle.period(), 2);
  ActiveSetCycle three;
  recordAll(three, {1, 2, 3, 1, 2, 3});
  EXPECT_EQ(three.period(), 3);
}

}  // namespace
}  // namespace coulomb::contact
