// The frictionless active-set rule (4.73/4.74) and penalty rule, the slip
// reset pattern, the active-set summary, and the default penalty E / h.
// (The nodal rows with their complementarity and finite-difference checks:
// contact_ncp_node.cpp, contact_friction_node.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/laws/AutomaticPenalty.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

TEST(ActiveSetRule, ThresholdAtZeroAugmentedMultiplier) {
  // k lambda_n + eps g~ / D = 2 (-1.5) + 3 (1) / 1 = 0 exactly: closed.
  EXPECT_EQ(almContactState(-1.5, 1.0, 1.0, 2.0, 3.0), ContactState::Slip);
  EXPECT_EQ(almContactState(std::nextafter(-1.5, 0.0), 1.0, 1.0, 2.0, 3.0), ContactState::Inactive);
  EXPECT_EQ(almContactState(std::nextafter(-1.5, -2.0), 1.0, 1.0, 2.0, 3.0), ContactState::Slip);
  // D scales the gap: the same weighted gap on a larger weight is a smaller nodal gap.
  EXPECT_EQ(almContactState(-1.0, 1.0, 2.0, 1.0, 1.0), ContactState::Slip);    // -1 + 0.5 < 0
  EXPECT_EQ(almContactState(-1.0, 1.0, 0.5, 1.0, 1.0), ContactState::Inactive);  // -1 + 2 > 0
  EXPECT_THROW(almContactState(-1.0, 1.0, 0.0, 1.0, 1.0), coulomb::InternalError);
  // Surfaces within the touching gap count as closed (at most eps_n × touching of tension).
  EXPECT_EQ(almContactState(0.0, 1e-13, 1.0, 1.0, 3.0, 1e-12), ContactState::Slip);
  EXPECT_EQ(almContactState(0.0, 2e-12, 1.0, 1.0, 3.0, 1e-12), ContactState::Inactive);
  EXPECT_EQ(static_cast<int>(ContactState::Inactive), 0);
  EXPECT_EQ(static_cast<int>(ContactState::Slip), 1);
}

// Slip Reset Frequency counts deck steps: the sub-steps of a cut (or
// knot-split) deck step all follow that step, and the pattern 1, 1 + n, ...
// does not shift (counting sub-steps, steps 2 and 3 below would reset).
TEST(ActiveSetRule, SlipResetCountsDeckSteps) {
  const int deckStepOfSubStep[] = {1, 1, 2, 3, 3, 3, 4, 5, 6, 7};
  std::string two, three, one;
  for (int step : deckStepOfSubStep) {
    one += resetsSlip(1, step) ? 'R' : '.';
    two += resetsSlip(2, step) ? 'R' : '.';
    three += resetsSlip(3, step) ? 'R' : '.';
  }
  EXPECT_EQ(one, "RRRRRRRRRR");
  EXPECT_EQ(two, "RR.RRR.R.R");
  EXPECT_EQ(three, "RR....R..R");
  for (int step = 1; step < 5; ++step) EXPECT_FALSE(resetsSlip(0, step));
}

TEST(ActiveSetSummary, CountsChanges) {
  using S = ContactState;
  const std::vector<S> before{S::Slip, S::Inactive, S::Inactive, S::Slip, S::Stick};
  const std::vector<S> now{S::Slip, S::Slip, S::Inactive, S::Inactive, S::Slip};
  ActiveSetSummary s;
  for (std::size_t i = 0; i < now.size(); ++i) countState(s, now[i], before[i]);
  EXPECT_EQ(s.nodes, 5u);
  EXPECT_EQ(s.active, 3u);
  EXPECT_EQ(s.inactive, 2u);
  EXPECT_EQ(s.changed, 2u);           // opened or closed
  EXPECT_EQ(s.stickSlipChanged, 1u);  // stick -> slip
  EXPECT_FALSE(s.unchanged());
  ActiveSetSummary same;
  for (S state : now) countState(same, state, state);
  EXPECT_TRUE(same.unchanged());
  ActiveSetSummary sum = s;
  sum += same;
  EXPECT_EQ(sum.nodes, 10u);
  EXPECT_EQ(sum.changed, 2u);
  std::ostringstream out;
  out << S::Slip << " " << S::Stick;
  EXPECT_EQ(out.str(), "Slip Stick");
}

TEST(AutomaticPenaltyValue, DefaultPenaltyIsEOverH) {
  EXPECT_DOUBLE_EQ(defaultPenalty(210e9, 0.01), 210e11);
  EXPECT_DOUBLE_EQ(defaultPenalty(1.0, 0.5, 10.0), 20.0);
  EXPECT_THROW(defaultPenalty(0.0, 1.0), coulomb::InternalError);
  EXPECT_THROW(defaultPenalty(1.0, -1.0), coulomb::InternalError);
  EXPECT_THROW(defaultPenalty(1.0, 1.0, 0.0), coulomb::InternalError);
}

}  // namespace
}  // namespace coulomb::contact
