#include "coulomb/fem/TimeFunction.hpp"

#include <algorithm>

#include "coulomb/core/Error.hpp"

namespace coulomb::fem {

TimeFunction TimeFunction::ramp() { return TimeFunction({0.0, 1.0}, {0.0, 1.0}, "ramp"); }
TimeFunction TimeFunction::constant() { return TimeFunction({0.0}, {1.0}, "constant"); }

TimeFunction::TimeFunction(std::vector<double> times, std::vector<double> values, const std::string& where)
    : times_(std::move(times)), values_(std::move(values)) {
  COULOMB_REQUIRE(!times_.empty(), "deck: '" << where << "' needs at least one time point");
  COULOMB_REQUIRE(times_.size() == values_.size(), "deck: '" << where << "' has " << times_.size()
                                                             << " Times but " << values_.size() << " Values");
  for (std::size_t i = 1; i < times_.size(); ++i)
    COULOMB_REQUIRE(times_[i] > times_[i - 1], "deck: '" << where << "/Times' must be strictly increasing");
}

double TimeFunction::operator()(double time) const {
  if (time <= times_.front()) return values_.front();
  if (time >= times_.back()) return values_.back();
  const auto upper = std::upper_bound(times_.begin(), times_.end(), time);
  const std::size_t i = static_cast<std::size_t>(upper - times_.begin());
  const double w = (time - times_[i - 1]) / (times_[i] - times_[i - 1]);
  return (1.0 - w) * values_[i - 1] + w * values_[i];
}

}  // namespace coulomb::fem
