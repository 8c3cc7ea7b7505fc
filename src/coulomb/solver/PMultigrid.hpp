#pragma once
/// @file PMultigrid.hpp
/// @brief The preconditioner of systems on quadratic cells: one geometric
/// p-coarsening to the corner nodes (fem/VertexCoarsening.hpp), then MueLu
/// on the linear-element operator P^T A P.
///
/// Why: MueLu's aggregation on a quadratic element matrix makes aggregates
/// of some 50 nodes (a HEX20 node couples to up to 80) whose piecewise
/// rigid-body basis a Gauss-Seidel sweep cannot complement well: HEX20 and
/// TET10 contact solves took about twice the GMRES iterations of HEX8 ones
/// at the same DoF count. On the corner nodes the operator is that of a
/// linear mesh, where MueLu's defaults are measured (LinearSolverFactory).
///
/// One application (a V-cycle on top of MueLu's): a forward l1 Gauss-Seidel
/// sweep on A (Ifpack2), the residual restricted by P^T, MueLu's V-cycle on
/// P^T A P, the correction prolongated by P, a backward sweep: a symmetric
/// cycle, as MueLu's own on a linear mesh (LinearSolverFactory.cpp).
///
/// Registered with Stratimikos as the preconditioner "P-Multigrid"; its
/// parameter list holds "Coarse MueLu" (MueLu's list for P^T A P), "Pre
/// Smoother" and "Post Smoother" (Ifpack2 relaxation lists), and, set by
/// the caller before each setup as MueLu's near-null space is, the
/// non-serializable "Prolongator" (RCP<CrsMatrix>), "Coarse Nullspace" and
/// "Coarse Coordinates" (RCP<MultiVector>).
#include <Teuchos_RCP.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

namespace coulomb::solver {

/// The Stratimikos name of the preconditioner.
inline constexpr const char* kPMultigridName = "P-Multigrid";

/// @brief Thyra's face of the preconditioner (Stratimikos builds it by name).
class PMultigridFactory : public Thyra::PreconditionerFactoryBase<double> {
public:
  bool isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                      Thyra::PreconditionerBase<double>* prec, const Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                        Thyra::ESupportSolveUse* supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& paramList) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

  /// @brief Whether the next setup keeps the corner level (P^T A P and its
  /// MueLu hierarchy, three quarters of a setup) of the cycle the
  /// preconditioner holds, and makes only the smoothers on the new matrix.
  /// The Newton solver asks for it while the contact set does not change
  /// and the tangent's pattern did (NewtonSolver.cpp): the smoothers must
  /// see the matrix they sweep, the corner correction may be that of a
  /// nearby one. For the next setup only (a setup clears it).
  void keepCoarseLevel(bool keep) { keepCoarseLevel_ = keep; }
  /// Setups that kept the corner level (for tests and diagnostics).
  int coarseLevelReuses() const { return coarseLevelReuses_; }

private:
  Teuchos::RCP<Teuchos::ParameterList> parameters_;
  mutable bool keepCoarseLevel_ = false;
  mutable int coarseLevelReuses_ = 0;
};

}  // namespace coulomb::solver
