#pragma once
/// @file ModelEvaluator.hpp
/// @brief The discrete problem as a Thyra ModelEvaluator for NOX:
/// x = displacements (owned map), f = residual, W = tangent (Tpetra CrsMatrix).
#include <functional>

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/Assembler.hpp"

namespace coulomb::solver {

class ModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<double> {
public:
  /// `beforeJacobian` runs before each tangent assembly (it refreshes the
  /// preconditioner's user data).
  ModelEvaluator(fem::Assembler& assembler, const Teuchos::RCP<const Map>& ownedMap,
                 Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> factory,
                 std::function<void()> beforeJacobian);

  /// Pseudo time at which loads and prescribed displacements are evaluated.
  void setTime(double time) { time_ = time; }
  double time() const { return time_; }

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override { return space_; }
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override { return nominal_; }
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
};

}  // namespace coulomb::solver
