// The adaptive Krylov tolerance of a Newton iteration (solver/LinearTolerance.hpp).
#include <gtest/gtest.h>

#include "coulomb/solver/LinearTolerance.hpp"

namespace coulomb::solver {
namespace {

const LinearToleranceSettings kDefaults;

TEST(LinearTolerance, FirstIterationOfAStepSolvesToTheMaximum) {
  // Far from the Newton tolerance, with no rate yet: the loosest tolerance.
  EXPECT_DOUBLE_EQ(linearTolerance(kDefaults, 100.0, -1.0, 1e-6), kDefaults.maximum);
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
}

}  // namespace
}  // namespace coulomb::solver
