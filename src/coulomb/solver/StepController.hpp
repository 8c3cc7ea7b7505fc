#pragma once
/// @file StepController.hpp
/// @brief Which pseudo-time interval the next load (sub-)step covers: the
/// deck's step ends and the knots of its load functions are landed on
/// exactly, a failed sub-step is halved, and easy sub-steps grow back to the
/// nominal size. Pure logic (no MPI): every rank makes the same decisions
/// from the same converged/failed sequence.
#include <string>
#include <vector>

namespace coulomb::solver {

/// @brief Load-step sizes between 0 and the final time.
///
/// Landing points: t_k = k T / N (k = 1..N, the deck's step ends) and every
/// knot of a piecewise-linear load function inside (0, T) (a load's rate
/// changes there). A sub-step never crosses the next landing point; when the
/// current size does not divide the distance to it, the remaining distance
/// is split into equal sub-steps, so no sliver step is left before a landing
/// point. After a failure the size is halved (at most `maximumCutbacks`
/// times in a row, and never below T / N / 2^maximumCutbacks); after `growAfter` converged sub-steps in a row at a
/// reduced size, each taking at most `easyIterations` Newton iterations, it
/// doubles, up to the nominal size T / N.
class StepController {
public:
  struct Settings {
    double finalTime = 1.0;
    int numberOfSteps = 1;
    int maximumCutbacks = 5;
    int growAfter = 2;          ///< converged sub-steps in a row before the size doubles
    int easyIterations = 1000;  ///< a sub-step counts towards growth if it took at most this many iterations
  };
  /// `knots`: times where a load function's slope changes (any order, any
  /// range: those outside (0, T) are ignored).
  StepController(const Settings& settings, const std::vector<double>& knots);

  bool finished() const { return next_ >= landing_.size(); }
  /// Last converged time (0 at the start).
  double time() const { return time_; }
  /// End of the sub-step to try now (exactly a landing point when it reaches one).
  double nextTime() const;
  /// The size the controller aims at (nominal, or reduced after cutbacks).
  double size() const { return size_; }
  double nominalSize() const { return nominal_; }
  /// Whether nextTime() is one of the deck's step ends t_k = k T / N.
  bool nextIsStepEnd() const;
  /// The deck's step number (1-based) of the step end the next sub-step leads to.
  int nominalStep() const;
  /// Cutbacks since the last converged sub-step.
  int consecutiveCutbacks() const { return consecutiveCutbacks_; }
  /// Every landing point, in order (step ends and knots).
  const std::vector<double>& landingPoints() const { return landing_; }

  /// The sub-step to nextTime() converged in `newtonIterations` iterations.
  void accept(int newtonIterations);
  /// The sub-step failed: halves the size. Returns false when that would be
  /// more than `maximumCutbacks` halvings in a row or a size below
  /// T / N / 2^maximumCutbacks (the run must stop).
  bool reject();

private:
  Settings settings_;
  double nominal_;
  std::vector<double> landing_;
  std::vector<char> stepEnd_;   ///< per landing point: a deck step end
  std::size_t next_ = 0;        ///< index of the next landing point
  double time_ = 0.0;
  double size_;
  int consecutiveCutbacks_ = 0;
  int easyInARow_ = 0;
};

}  // namespace coulomb::solver
