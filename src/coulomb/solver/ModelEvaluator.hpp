#pragma once
/// @file ModelEvaluator.hpp
/// @brief The discrete problem as a Thyra ModelEvaluator for NOX:
/// x = displacements (owned map), f = residual, W = tangent (Tpetra CrsMatrix).
///
/// With contact (contact::ContactModel) f and W are the condensed residual and
/// tangent of ContactModel.hpp (or, with `Contact/System Form` = Saddle
/// Point, x = (u, z) with the multiplier unknowns z and the uncondensed
/// residual and tangent). The contact state (active set, multipliers)
/// is updated once per new iterate x, at its first evaluation (f or W), from
/// the bulk residual at x; W is then a new matrix per iterate (its pattern
/// follows the contact), put into the Thyra operator NOX holds.
#include <functional>
#include <string>

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/Assembler.hpp"

namespace coulomb::contact {
class ContactModel;
}

namespace coulomb::solver {

class ModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<double> {
public:
  /// `beforeJacobian` runs before each tangent assembly (it refreshes the
  /// preconditioner's user data).
  ModelEvaluator(fem::Assembler& assembler, const Teuchos::RCP<const Map>& ownedMap,
                 Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> factory,
                 std::function<void()> beforeJacobian, contact::ContactModel* contact = nullptr);

  /// Pseudo time at which loads and prescribed displacements are evaluated.
  void setTime(double time) {
    time_ = time;
    externalNorm_ = -1.0;
    forgetIterate();
  }
  /// The next evaluation recomputes the contact state even at the same x.
  void forgetIterate() const { lastX_ = Teuchos::null; }
  double time() const { return time_; }
  /// Contact, condensed form, constant K (fem::Assembler::tangentIsConstant):
  /// K is recovered from the last tangent instead of assembled (the same
  /// values bit for bit; 'Newton/Reuse Constant Tangent', default true).
  void reuseConstantTangent(bool reuse) { reuseConstantTangent_ = reuse; }
  /// 'Load Stepping/Boundary Increment' = Tangent: Newton residuals carry
  /// the linearised coupling of prescribed DoFs that lag behind ū
  /// (fem::Assembler::assemble, linearizeLaggingBoundary).
  void linearizeLaggingBoundary(bool on) { linearizeLaggingBoundary_ = on; }
  /// The last evaluated residual had a prescribed DoF behind ū (the same on
  /// every rank): it is not the residual of that iterate, which must not
  /// count as converged (NewtonSolver).
  bool boundaryLags() const { return boundaryLags_; }
  /// Why the last rejected iterate could not be evaluated (an inverted
  /// element, a contact geometry failure, a non-finite residual), or empty
  /// when none was rejected since clearFailure(). A rejected iterate gets a
  /// NaN residual on every rank: NOX's FiniteValue test fails the step.
  const std::string& lastFailure() const { return failure_; }
  void clearFailure() const { failure_.clear(); }
  /// The force scale of the last evaluated iterate, for the Newton test
  /// (NewtonSolver): max(||reactions||, ||f_ext(t)||, ||contact forces||),
  /// each a 2-norm over the DoFs [force]. It does not depend on how good the
  /// predictor was, and it carries the problem's force unit, so a problem in
  /// mm/N/MPa and the same one in m/N/Pa converge alike. 0 before any
  /// evaluation or when nothing is loaded.
  double forceScale() const { return forceScale_; }

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override { return space_; }
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override { return nominal_; }
  /// Owned-local indices of the prescribed DoFs (their residual rows are u − ū).
  std::vector<int> prescribedDofs() const;
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override { return factory_; }
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override;

private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override;
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const override;

  fem::Assembler& assembler_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> factory_;
  std::function<void()> beforeJacobian_;
  Thyra::ModelEvaluatorBase::InArgs<double> nominal_;
  double time_ = 0.0;
  contact::ContactModel* contact_ = nullptr;
  // Contact: the iterate whose state is current, its bulk residual, the bulk tangent.
  bool reuseConstantTangent_ = true;
  bool linearizeLaggingBoundary_ = false;
  mutable bool boundaryLags_ = false;
  bool saddlePoint_ = false;  ///< contact in the saddle-point form: x = (u, z) on ContactModel::saddlePointMap()
  mutable Teuchos::RCP<Vector> lastX_, bulkResidual_, displacement_;
  mutable Teuchos::RCP<CrsMatrix> bulkTangent_;
  mutable bool lastInvalid_ = false;  ///< the contact iterate lastX_ was rejected
  mutable std::string failure_;
  mutable Teuchos::RCP<Vector> reactions_;  ///< of the last residual evaluation
  mutable double externalNorm_ = -1.0;      ///< ||f_ext(time_)||, < 0: not yet computed
  mutable double forceScale_ = 0.0;
  /// Sets forceScale_ from reactions_ (filled by the last bulk residual) and the contact forces.
  void updateForceScale() const;
  /// Marks the iterate rejected with `why` and fills `f` with NaN.
  void reject(const std::string& why, Vector* f) const;
  void evalContact(const Vector& x, Vector* f, const Teuchos::RCP<Thyra::LinearOpBase<double>>& W) const;
};

}  // namespace coulomb::solver
