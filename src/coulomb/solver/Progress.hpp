#pragma once
/// @file Progress.hpp
/// @brief How much a run says on the console (Verbosity) and how far along
/// it is (RunClock: elapsed time and an estimate of the time left).
#include <chrono>
#include <string>

namespace coulomb::solver {

/// @brief Console detail: Quiet = one line per load step; Normal = a header
/// and a result line per step and the contact pairs; Verbose = Normal plus
/// the Newton iteration table of every step.
enum class Verbosity { Quiet, Normal, Verbose };

/// @brief A duration as a person reads it: "0.42 s", "12 s", "3 min 05 s", "1 h 02 min".
std::string formatDuration(double seconds);

/// @brief Wall clock of the load stepping, and the time left estimated
/// from the pseudo time covered so far.
///
/// The estimate is linear in pseudo time: elapsed × (T − t) / (t − t₀). A
/// step costs roughly the same per unit of pseudo time in a loaded problem
/// (the Newton count per step varies less than the steps' sizes), and it
/// needs nothing but what the run knows — a bad guess only while the first
/// steps are untypical (a first contact, a cutback).
class RunClock {
public:
  RunClock(double startTime, double finalTime);
  double elapsedSeconds() const;
  /// "about 12 s left" from the pseudo time reached; "time left: after the
  /// first step" before any was converged.
  std::string timeLeft(double reachedTime) const;

private:
  std::chrono::steady_clock::time_point start_;
  double startTime_, finalTime_;
};

}  // namespace coulomb::solver
