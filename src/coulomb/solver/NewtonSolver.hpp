#pragma once
/// @file NewtonSolver.hpp
/// @brief One nonlinear solve (a load step) with NOX over the model
/// evaluator, and the per-iteration console table.
#include <ostream>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/solver/LinearTolerance.hpp"
#include "coulomb/solver/ModelEvaluator.hpp"

namespace coulomb::contact {
class ContactModel;
}

namespace coulomb::solver {

/// @brief Convergence settings (deck sublist "Newton").
struct NewtonSettings {
  int maximumIterations = 25;
  /// Converged when ||f|| <= relativeTolerance × the force scale of the
  /// iterate (reactions, loads, contact forces: ModelEvaluator::forceScale;
  /// never below 1000 eps × it) ...
  double relativeTolerance = 1e-8;
  /// ... or when ||f|| <= absoluteTolerance [force] (0: no absolute test).
  double absoluteTolerance = 0.0;
  LinearToleranceSettings linearTolerance;  ///< Krylov tolerance per iteration (LinearTolerance.hpp)
  /// With contact and an iterative solver: a Newton iteration whose contact
  /// set (active nodes, stick/slip) did not change since the last solve of
  /// the step, whose matrix has the same structure and whose last solve
  /// converged keeps the last built preconditioner instead of building a
  /// new one (NOX::Thyra::Group's updatePreconditioner_ cleared for that
  /// solve; 'Newton/Reuse Preconditioner').
  bool reusePreconditioner = true;
};

/// @brief One row of the iteration table.
struct NewtonIteration {
  int iteration = 0;
  double residualNorm = 0;
  double incrementNorm = 0;
  int linearIterations = 0;
  double seconds = 0;
  // Contact (when present; Fig. 4.23 columns): active nodes, nodes that
  // changed state at this iterate, normal constraint residual, set converged.
  long long activeNodes = -1;
  long long stickNodes = -1;          ///< frictional runs: active nodes in stick
  long long stickSlipChanged = -1;    ///< frictional runs: stick <-> slip changes at this iterate
  double stickResidual = 0, slipResidual = 0;  ///< frictional runs: the tangential groups of (4.78)
  long long changedNodes = 0;
  double normalResidual = 0;
  double normalRatio = 0;   ///< normalResidual / ||contact forces||
  bool contactConverged = false;
  bool preconditionerReused = false;  ///< the solve of this row's step kept the last preconditioner
  bool coarseLevelKept = false;  ///< ... or only its corner level (P-Multigrid, PMultigridFactory::keepCoarseLevel)
};

struct NewtonReport {
  bool converged = false;
  /// Why an iterate could not be evaluated (ModelEvaluator::lastFailure), or empty.
  std::string failure;
  /// Why Newton stopped before its iteration limit without converging
  /// (e.g. a cycling active set, contact::ActiveSetCycle), or empty.
  std::string stopReason;
  std::vector<NewtonIteration> iterations;  ///< row 0: the initial residual
  int linearIterations() const;
  int preconditionerReuses() const;
  int coarseLevelReuses() const;
  /// The step's first iterate (the predictor) could not be evaluated.
  bool rejectedStart() const { return !converged && !failure.empty() && iterations.size() <= 1; }
};

class NewtonSolver {
public:
  /// `noxParameters`: the deck's "Nonlinear Solver" sublist (NOX names), completed with defaults.
  NewtonSolver(Teuchos::RCP<ModelEvaluator> model, const Teuchos::ParameterList& noxParameters,
               const NewtonSettings& settings, std::ostream* console,
               const contact::ContactModel* contact = nullptr);

  /// `directSolver`: the linear solver factors the matrix (Amesos2): a
  /// preconditioner is never reused.
  void setDirectSolver(bool direct) { directSolver_ = direct; }
  /// Where the iteration table goes (null: nowhere; `coulomb --verbose` shows it).
  void setConsole(std::ostream* console) { console_ = console; }

  /// Solves f(u) = 0 starting from `u`; on return `u` holds the last iterate.
  NewtonReport solve(Vector& u);

  /// NOX defaults Coulomb uses (full Newton step, NOX's own printing off).
  static Teuchos::RCP<Teuchos::ParameterList> defaultParameters();

private:
  Teuchos::RCP<ModelEvaluator> model_;
  Teuchos::RCP<Teuchos::ParameterList> noxParameters_;
  NewtonSettings settings_;
  std::ostream* console_;
  const contact::ContactModel* contact_ = nullptr;
  bool directSolver_ = false;
};

}  // namespace coulomb::solver
