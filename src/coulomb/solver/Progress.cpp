#include "coulomb/solver/Progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace coulomb::solver {

std::string formatDuration(double seconds) {
  char text[64];
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "?";
  if (seconds < 10) std::snprintf(text, sizeof text, "%.2f s", seconds);
  else if (seconds < 60) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 3600) {
    const long s = std::lround(seconds);
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  } else {
    const long m = std::lround(seconds / 60);
    std::snprintf(text, sizeof text, "%ld h %02ld min", m / 60, m % 60);
  }
  return text;
}

RunClock::RunClock(double startTime, double finalTime)
    : start_(std::chrono::steady_clock::now()), startTime_(startTime), finalTime_(finalTime) {}

double RunClock::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string RunClock::timeLeft(double reachedTime) const {
  const double covered = reachedTime - startTime_;
  if (!(covered > 0)) return "time left: after the first step";
  const double left = elapsedSeconds() * std::max(0.0, finalTime_ - reachedTime) / covered;
  return "about " + formatDuration(left) + " left";
}

}  // namespace coulomb::solver
