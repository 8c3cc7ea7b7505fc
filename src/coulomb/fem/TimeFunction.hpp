#pragma once
/// @file TimeFunction.hpp
/// @brief Scalar functions of pseudo time that scale loads: piecewise linear
/// through (time, value) points, constant beyond the first and last point.
#include <string>
#include <vector>

namespace coulomb::fem {

/// @brief f(t) piecewise linear through (times[i], values[i]); times strictly increasing.
class TimeFunction {
public:
  /// f(t) = t: the default ramp of the load-stepping pseudo time.
  static TimeFunction ramp();
  /// f(t) = 1.
  static TimeFunction constant();
  /// Throws coulomb::Error naming `where` if the points are not usable.
  TimeFunction(std::vector<double> times, std::vector<double> values, const std::string& where);

  double operator()(double time) const;
  /// The times of the points: where the slope changes (load stepping lands there).
  const std::vector<double>& knots() const { return times_; }

private:
  std::vector<double> times_;
  std::vector<double> values_;
};

}  // namespace coulomb::fem
