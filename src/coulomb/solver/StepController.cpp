#include "coulomb/solver/StepController.hpp"

#include <algorithm>
#include <cmath>

#include "coulomb/core/Error.hpp"

namespace coulomb::solver {

StepController::StepController(const Settings& settings, const std::vector<double>& knots)
    : settings_(settings), nominal_(settings.finalTime / settings.numberOfSteps), size_(nominal_) {
  COULOMB_CHECK(settings.finalTime > 0 && settings.numberOfSteps > 0,
                  "load stepping needs a positive final time and step count");
  const double T = settings.finalTime;
  // Two points closer than this are one (knots placed at a step end in
  // decimal arithmetic, e.g. 0.3 against 3 * 0.1).
  const double merge = 1e-9 * nominal_;
  struct Point {
    double t;
    bool stepEnd;
  };
  std::vector<Point> points;
  for (int k = 1; k <= settings.numberOfSteps; ++k)
    points.push_back({k == settings.numberOfSteps ? T : T * k / settings.numberOfSteps, true});
  for (double t : knots)
    if (t > merge && t < T - merge) points.push_back({t, false});
  std::stable_sort(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.t < b.t; });
  for (const Point& p : points) {
    if (!landing_.empty() && p.t - landing_.back() <= merge) {
      // A knot at a step end: keep the step end's exact value.
      if (p.stepEnd) {
        landing_.back() = p.t;
        stepEnd_.back() = 1;
      }
      continue;
    }
    landing_.push_back(p.t);
    stepEnd_.push_back(p.stepEnd ? 1 : 0);
  }
}

double StepController::nextTime() const {
  COULOMB_CHECK(!finished(), "no load step left");
  const double target = landing_[next_];
  const double distance = target - time_;
  // Equal sub-steps of at most size_ to the landing point; the small slack
  // keeps a distance that is size_ up to round-off one sub-step.
  const double substeps = std::ceil(distance / size_ * (1 - 1e-9));
  if (substeps <= 1) return target;
  return time_ + distance / substeps;
}

bool StepController::nextIsStepEnd() const { return !finished() && nextTime() == landing_[next_] && stepEnd_[next_]; }

int StepController::nominalStep() const {
  // The first step end at or after the next landing point (a knot lies inside a deck step).
  std::size_t j = std::min(next_, landing_.size() - 1);
  while (!stepEnd_[j]) ++j;  // the last landing point is T, a step end
  int count = 0;
  for (std::size_t i = 0; i <= j; ++i) count += stepEnd_[i];
  return count;
}

void StepController::accept(int newtonIterations) {
  const double reached = nextTime();
  time_ = reached;
  if (reached == landing_[next_]) ++next_;
  consecutiveCutbacks_ = 0;
  if (size_ < nominal_) {
    easyInARow_ = newtonIterations <= settings_.easyIterations ? easyInARow_ + 1 : 0;
    if (easyInARow_ >= settings_.growAfter) {
      size_ = std::min(2 * size_, nominal_);
      easyInARow_ = 0;
    }
  }
}

bool StepController::reject() {
  easyInARow_ = 0;
  // Halve the sub-step actually tried (it may have been shorter than size_
  // before a landing point).
  const double halved = std::min(size_, nextTime() - time_) / 2;
  // Never below T/N / 2^maximumCutbacks: converged sub-steps reset the
  // count in a row, and without a floor a failure that moves with the load
  // (a limit point) would be approached in ever smaller steps, forever.
  const double minimum = nominal_ * std::ldexp(1.0, -settings_.maximumCutbacks);
  if (consecutiveCutbacks_ >= settings_.maximumCutbacks || halved < minimum * (1 - 1e-9)) return false;
  ++consecutiveCutbacks_;
  size_ = halved;
  return true;
}

}  // namespace coulomb::solver
