#include "coulomb/solver/ModelEvaluator.hpp"

#include <limits>

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

namespace coulomb::solver {

using Extract = Thyra::TpetraOperatorVectorExtraction<Scalar, LocalOrdinal, GlobalOrdinal>;

ModelEvaluator::ModelEvaluator(fem::Assembler& assembler, const Teuchos::RCP<const Map>& ownedMap,
                               Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> factory,
                               std::function<void()> beforeJacobian)
    : assembler_(assembler),
      map_(ownedMap),
      space_(Thyra::createVectorSpace<Scalar>(ownedMap)),
      factory_(std::move(factory)),
      beforeJacobian_(std::move(beforeJacobian)) {
  nominal_ = createInArgs();
  auto x0 = Thyra::createMember(space_);
  Thyra::V_S(x0.ptr(), 0.0);
  nominal_.set_x(x0);
}

Thyra::ModelEvaluatorBase::InArgs<double> ModelEvaluator::createInArgs() const {
  Thyra::ModelEvaluatorBase::InArgsSetup<double> in;
  in.setModelEvalDescription("Coulomb bulk model");
  in.setSupports(Thyra::ModelEvaluatorBase::IN_ARG_x);
  return std::move(in);
}

Thyra::ModelEvaluatorBase::OutArgs<double> ModelEvaluator::createOutArgsImpl() const {
  Thyra::ModelEvaluatorBase::OutArgsSetup<double> out;
  out.setModelEvalDescription("Coulomb bulk model");
  out.set_Np_Ng(0, 0);
  out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_f);
  out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_W_op);
  return std::move(out);
}

Teuchos::RCP<Thyra::LinearOpBase<double>> ModelEvaluator::create_W_op() const {
  Teuchos::RCP<Tpetra::Operator<Scalar, LocalOrdinal, GlobalOrdinal>> matrix = assembler_.createMatrix();
  return Thyra::createLinearOp<Scalar, LocalOrdinal, GlobalOrdinal>(matrix, space_, space_);
}

void ModelEvaluator::evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& in,
                                   const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const {
  const auto x = Extract::getConstTpetraVector(in.get_x());
  Teuchos::RCP<Vector> f;
  if (out.get_f() != Teuchos::null) f = Extract::getTpetraVector(out.get_f());
  CrsMatrix* jacobian = nullptr;
  if (out.get_W_op() != Teuchos::null) {
    auto op = Extract::getTpetraOperator(out.get_W_op());
    jacobian = dynamic_cast<CrsMatrix*>(op.get());
    beforeJacobian_();
  }
  const auto status = assembler_.assemble(time_, *x, f.get(), jacobian);
  // An inverted element makes this iterate meaningless: a NaN residual makes
  // NOX's FiniteValue test fail the step, and the stepper cuts back.
  if (status.invertedElement && f != Teuchos::null) f->putScalar(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace coulomb::solver
