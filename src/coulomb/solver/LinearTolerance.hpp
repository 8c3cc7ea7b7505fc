#pragma once
/// @file LinearTolerance.hpp
/// @brief How accurately each Newton iteration solves its linear system
/// (inexact Newton): the relative Krylov tolerance eta_k of
/// ||J du + f|| <= eta_k ||f||.
///
/// A solve far below what the current iterate can use is wasted: while the
/// active set or the nonlinear error still dominates, the next residual is set
/// by the linearisation error, not by eta; and in the last iteration the
/// residual only has to fall below the Newton tolerance. NOX's fixed default
/// (1e-10) made hertz3d_r2 spend 31 of 39.5 s in GMRES for ~60 iterations a
/// solve (tests/performance/README.md).
namespace Teuchos {
class ParameterList;
}

namespace coulomb::solver {

struct LinearToleranceSettings {
  bool adaptive = true;       ///< false: NOX's "Linear Solver"/"Tolerance" (or its forcing term) as given
  double maximum = 1e-3;      ///< loosest eta: the active set is still read from a solve this accurate
  double minimum = 1e-10;     ///< tightest eta (NOX's fixed default)
  double quadraticFactor = 0.9;  ///< gamma of the Eisenstat-Walker choice 2 (alpha = 2)
  double targetFraction = 0.1;   ///< the last solve leaves at most this fraction of the Newton tolerance
  /// The first solve of a step at `maximum` (contact: the active set is read
  /// from an iterate that is far off anyway); else as tight as the Newton
  /// target asks, so that a linear problem still takes one iteration.
  bool looseFirstIteration = true;
};

/// @brief eta_k for the iteration at residual norm `normF`.
///
/// `normFPrevious` is the residual norm before the previous Newton step (<= 0
/// at the first iteration of a load step); `target` the residual norm at which
/// Newton stops (max(absolute, relative x ||f_0||)). Two estimates of the
/// accuracy the step can use, the larger wins, capped to [minimum, maximum]:
///  - quadratic: gamma (||f_k|| / ||f_k-1||)^2 (Eisenstat-Walker choice 2)
///    keeps Newton's rate: the linear error stays below the nonlinear one;
///  - target: a linear residual of targetFraction x target is all the last
///    iteration needs, however far ||f_k|| is above it.
/// At a step's first iteration there is no rate yet: eta = maximum
/// (looseFirstIteration) or what the target asks.
double linearTolerance(const LinearToleranceSettings& settings, double normF, double normFPrevious, double target);

/// The NOX list chooses the Krylov tolerance itself ("Direction"/"Newton"/
/// "Linear Solver"/"Tolerance" or a "Forcing Term Method"): then the
/// adaptive tolerance stays off, whatever the settings say.
bool noxSetsLinearTolerance(const Teuchos::ParameterList& nox);

}  // namespace coulomb::solver
