#pragma once
/// @file GatheredDirectSolver.hpp
/// @brief A Thyra linear-solver strategy that solves with an Amesos2 direct
/// solver on ONE rank, correct at any rank count.
///
/// Debian's Trilinos 13.2 Amesos2 KLU2 returns wrong solutions when the
/// matrix is distributed (or not contiguously numbered), while Stratimikos
/// reports convergence (docs: ../shared/notes/trilinos-debian-13.2.md).
/// This strategy gathers the distributed Tpetra::CrsMatrix to rank 0,
/// renumbers it contiguously (0..n-1 in sorted global-index order) on a
/// one-process communicator, factors it there, and for each solve gathers
/// the right-hand sides, solves on rank 0 and scatters the solution back.
/// The true residual b - A x is always computed with the distributed matrix:
/// a solve reports SOLVE_STATUS_CONVERGED only when it is small enough.
///
/// It is registered in Stratimikos under "Linear Solver Type" = "Amesos2"
/// (LinearSolverFactory.cpp), with these parameters (sublist "Amesos2"):
///  - "Solver Type" (string, "KLU2"): any name Amesos2::query() accepts.
///  - "Relative Residual Tolerance" (double, 1e-9): ||b - A x|| / ||b|| a
///    solve must reach, unless the caller passes its own SolveCriteria.
///  - "Maximum Refinement Steps" (int, 2): iterative refinement steps (one
///    more solve each) tried while the residual is above the tolerance.
///  - "Amesos2 Settings" (free sublist): handed to the Amesos2 solver's
///    setParameters() as its "Amesos2" list, e.g. a "KLU2" sublist.
///
/// Re-initialising with a matrix of the same sparsity pattern (what Newton
/// does every iteration) keeps the gather plan and the symbolic
/// factorisation and redoes only the numeric one.
#include <memory>
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

namespace coulomb::solver {

/// @brief What the factory hands to each solver it initialises.
struct GatheredDirectSettings {
  std::string solverType = "KLU2";
  double relativeResidualTolerance = 1e-9;
  int maximumRefinementSteps = 2;
  Teuchos::RCP<const Teuchos::ParameterList> amesos2Settings;  ///< may be null
};

/// @brief Counters and timings of one solver object (per rank; the
/// factorisation counts and times are those of rank 0, broadcast).
struct GatheredDirectStatistics {
  int initializations = 0;
  int symbolicFactorizations = 0;  ///< each one also means a fresh Amesos2 solver
  int numericFactorizations = 0;
  int solves = 0;                  ///< calls of solve()
  int refinementSteps = 0;         ///< over all solves
  double lastGatherSeconds = 0;    ///< export of the matrix to rank 0
  double lastSymbolicSeconds = 0;  ///< 0 when the last initialisation reused it
  double lastNumericSeconds = 0;
  double lastSolveSeconds = 0;     ///< whole solve(): gather, solve, scatter, residual
  double lastRelativeResidual = -1;
};

/// @brief The linear operator with solve: the forward operator plus the
/// factorisation that lives on rank 0. Made and initialised by
/// GatheredDirectSolverFactory.
class GatheredDirectSolver final : public Thyra::LinearOpWithSolveBase<double> {
public:
  GatheredDirectSolver();
  ~GatheredDirectSolver() override;

  /// Collective. Gathers and factors the Tpetra::CrsMatrix behind
  /// `source->getOp()`; reuses the symbolic factorisation when the
  /// sparsity pattern (and solver type) did not change. Throws
  /// coulomb::Error on every rank if the factorisation fails.
  void initialize(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
                  const GatheredDirectSettings& settings);
  /// Forgets the forward operator (the factorisation is kept for reuse).
  Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> uninitialize();
  Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> source() const;
  const GatheredDirectStatistics& statistics() const;

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> range() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> domain() const override;
  std::string description() const override;

protected:
  bool opSupportedImpl(Thyra::EOpTransp transp) const override;
  void applyImpl(Thyra::EOpTransp transp, const Thyra::MultiVectorBase<double>& X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& Y, double alpha, double beta) const override;
  bool solveSupportsImpl(Thyra::EOpTransp transp) const override;
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp transp,
                                         const Thyra::SolveMeasureType& measure) const override;
  Thyra::SolveStatus<double> solveImpl(Thyra::EOpTransp transp, const Thyra::MultiVectorBase<double>& B,
                                       const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& X,
                                       const Teuchos::Ptr<const Thyra::SolveCriteria<double>> criteria) const override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// @brief The Stratimikos strategy ("Linear Solver Type" = "Amesos2").
class GatheredDirectSolverFactory final : public Thyra::LinearOpWithSolveFactoryBase<double> {
public:
  GatheredDirectSolverFactory() = default;

  bool isCompatible(const Thyra::LinearOpSourceBase<double>& source) const override;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
                    Thyra::LinearOpWithSolveBase<double>* op,
                    Thyra::ESupportSolveUse use = Thyra::SUPPORT_SOLVE_UNSPECIFIED) const override;
  void uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* source = nullptr,
                      Teuchos::RCP<const Thyra::PreconditionerBase<double>>* prec = nullptr,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* approxSource = nullptr,
                      Thyra::ESupportSolveUse* use = nullptr) const override;
  /// A direct solver needs no preconditioner: one given is ignored.
  bool supportsPreconditionerInputType(Thyra::EPreconditionerInputType type) const override;
  void initializePreconditionedOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
                                  const Teuchos::RCP<const Thyra::PreconditionerBase<double>>& prec,
                                  Thyra::LinearOpWithSolveBase<double>* op,
                                  Thyra::ESupportSolveUse use = Thyra::SUPPORT_SOLVE_UNSPECIFIED) const override;
  void initializeApproxPreconditionedOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
                                        const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& approxSource,
                                        Thyra::LinearOpWithSolveBase<double>* op,
                                        Thyra::ESupportSolveUse use = Thyra::SUPPORT_SOLVE_UNSPECIFIED) const override;

  /// Validates the list (throws std::invalid_argument on an unknown
  /// parameter or a solver name Amesos2 does not have) and keeps it.
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;
  std::string description() const override;

  const GatheredDirectSettings& settings() const { return settings_; }

private:
  Teuchos::RCP<Teuchos::ParameterList> list_;
  GatheredDirectSettings settings_;
};

}  // namespace coulomb::solver
