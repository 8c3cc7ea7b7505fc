// Progress and RunReport: the words and figures a person reads on the
// console (durations, time left, Q/P against mu, the problem size, the
// closing summary).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "coulomb/solver/Progress.hpp"
#include "coulomb/solver/RunReport.hpp"

using namespace coulomb::solver;

TEST(Progress, DurationsReadAsAPersonWouldSayThem) {
  EXPECT_EQ(formatDuration(0.4213), "0.42 s");
  EXPECT_EQ(formatDuration(12.4), "12 s");
  EXPECT_EQ(formatDuration(185), "3 min 05 s");
  EXPECT_EQ(formatDuration(3720), "1 h 02 min");
  EXPECT_EQ(formatDuration(-1), "?");
}

TEST(Progress, NoEstimateBeforeTheFirstStepThenNoTimeLeftAtTheEnd) {
  const RunClock clock(0.0, 24.0);
  EXPECT_EQ(clock.timeLeft(0.0), "time left: after the first step");
  EXPECT_EQ(clock.timeLeft(24.0), "about 0.00 s left");
  EXPECT_GE(clock.elapsedSeconds(), 0.0);
}

TEST(RunReport, QOverPAtMuIsSlidingBelowItHolding) {
  EXPECT_EQ(slidingState(0.3, 0.3), "Q/P = mu: the pair slides (gross slip)");
  EXPECT_EQ(slidingState(0.2985, 0.3), "Q/P = mu: the pair slides (gross slip)");  // within 1 %
  EXPECT_EQ(slidingState(0.25, 0.3), "Q/P < mu: the pair holds (stick or partial slip)");
}

namespace {

ProblemSize punch() {
  ProblemSize size;
  size.dimension = 3;
  size.nodes = 141;
  size.elements = 61;
  size.dofs = 423;
  size.blocks = {"base", "punch"};
  PairDescription pair;
  pair.name = "punch";
  pair.slave = "slave";
  pair.master = "master";
  pair.formulation = "ALM";
  pair.law = "Coulomb friction mu = 0.3";
  pair.mu = 0.3;
  pair.frictional = true;
  pair.slaveFaces = 8;
  pair.masterFaces = 15;
  pair.slaveNodes = 15;
  size.pairs = {pair};
  size.numberOfSteps = 24;
  size.finalTime = 24;
  size.meshFile = "punch.e";
  size.outputFile = "out.e";
  return size;
}

}  // namespace

TEST(RunReport, ProblemSizeNamesEveryCount) {
  std::ostringstream out;
  printProblemSize(out, punch());
  const std::string text = out.str();
  EXPECT_NE(text.find("3D, 141 nodes, 61 elements in 2 block(s) (base, punch), 423 DoFs"), std::string::npos) << text;
  EXPECT_NE(text.find("'punch': slave 'slave' 8 faces (15 nodes), master 'master' 15 faces; ALM"), std::string::npos)
      << text;
  EXPECT_NE(text.find("24 steps to t = 24"), std::string::npos) << text;
}

TEST(RunReport, SummaryGivesPeakPressureAndQOverPAgainstMu) {
  PairRecord record;
  record.peakPressure = 456.6;
  record.peakTime = 8;
  record.normalForce = 463.0;
  record.tangentialForce = 138.9;
  record.active = 15;
  record.stick = 3;
  std::ostringstream out;
  printRunSummary(out, punch(), {record}, 24, 0, 24.0, 0.99);
  const std::string text = out.str();
  EXPECT_NE(text.find("Summary: frictional contact, 3D"), std::string::npos) << text;
  EXPECT_NE(text.find("peak contact pressure 456.6 at t = 8"), std::string::npos) << text;
  EXPECT_NE(text.find("15 of 15 slave nodes in contact (3 stick, 12 slip)"), std::string::npos) << text;
  EXPECT_NE(text.find("Q/P = 0.3 against mu = 0.3: Q/P = mu"), std::string::npos) << text;
  EXPECT_NE(text.find("result: out.e"), std::string::npos) << text;
}
