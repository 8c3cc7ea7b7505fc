#include "coulomb/solver/ModelEvaluator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"
#include "coulomb/fem/Assembler.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"

namespace coulomb::solver {

using Extract = Thyra::TpetraOperatorVectorExtraction<Scalar, LocalOrdinal, GlobalOrdinal>;

ModelEvaluator::ModelEvaluator(fem::Assembler& assembler, const Teuchos::RCP<const Map>& ownedMap,
                               Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> factory,
                               std::function<void()> beforeJacobian, contact::ContactModel* contact)
    : assembler_(assembler),
      map_(ownedMap),
      factory_(std::move(factory)),
      beforeJacobian_(std::move(beforeJacobian)),
      contact_(contact && !contact->empty() ? contact : nullptr) {
  saddlePoint_ = contact_ && contact_->saddlePoint();
  space_ = Thyra::createVectorSpace<Scalar>(saddlePoint_ ? contact_->saddlePointMap() : ownedMap);
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

std::vector<int> ModelEvaluator::prescribedDofs() const { return assembler_.constraints().ownedConstrainedDofs(); }

Teuchos::RCP<Thyra::LinearOpBase<double>> ModelEvaluator::create_W_op() const {
  Teuchos::RCP<Tpetra::Operator<Scalar, LocalOrdinal, GlobalOrdinal>> matrix;
  if (saddlePoint_) {
    // A placeholder on the extended map: evalContact puts the tangent in.
    const auto& map = contact_->saddlePointMap();
    std::vector<linalg::MatrixTriplet> identity;
    for (GlobalOrdinal gid : map->getNodeElementList()) identity.push_back({gid, gid, 1.0});
    matrix = linalg::matrixFromTriplets(identity, map);
  } else if (contact_ && !contact_->tangentStorage().is_null()) {
    // Condensed contact: evalContact puts the condensed tangent in at the
    // first Jacobian, before any solve (NOX asks for none at a rejected
    // iterate: its NaN residual fails the step first), so the last one (of
    // the previous step or attempt) holds the place; a new K-sized matrix
    // here, zero-filled and never read, was 5 % of the peak memory of a
    // quadratic Hertz run (HEX20, 36k DoFs: 400 -> 380 MB).
    matrix = contact_->tangentStorage();
  } else {
    matrix = assembler_.createMatrix();
  }
  return Thyra::createLinearOp<Scalar, LocalOrdinal, GlobalOrdinal>(matrix, space_, space_);
}

void ModelEvaluator::evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& in,
                                   const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const {
  const auto x = Extract::getConstTpetraVector(in.get_x());
  if (contact_) {
    Teuchos::RCP<Vector> f;
    if (out.get_f() != Teuchos::null) f = Extract::getTpetraVector(out.get_f());
    evalContact(*x, f.get(), out.get_W_op());
    return;
  }
  Teuchos::RCP<Vector> f;
  if (out.get_f() != Teuchos::null) f = Extract::getTpetraVector(out.get_f());
  CrsMatrix* jacobian = nullptr;
  if (out.get_W_op() != Teuchos::null) {
    auto op = Extract::getTpetraOperator(out.get_W_op());
    jacobian = dynamic_cast<CrsMatrix*>(op.get());
    beforeJacobian_();
  }
  if (f != Teuchos::null && reactions_.is_null()) reactions_ = Teuchos::rcp(new Vector(map_));
  const auto status = assembler_.assemble(time_, *x, f.get(), jacobian, f != Teuchos::null ? reactions_.get() : nullptr,
                                          linearizeLaggingBoundary_);
  if (f != Teuchos::null) boundaryLags_ = status.boundaryLags;
  if (f != Teuchos::null) updateForceScale();
  // An inverted element makes this iterate meaningless: a NaN residual makes
  // NOX's FiniteValue test fail the step, and the stepper cuts back.
  if (status.invertedElement) reject(status.invertedMessage(), f.get());
}

void ModelEvaluator::updateForceScale() const {
  if (externalNorm_ < 0) externalNorm_ = assembler_.externalForceNorm(time_);
  double scale = std::max(externalNorm_, reactions_->norm2());
  if (contact_) scale = std::max(scale, contact_->lastSummary().contactForce);
  forceScale_ = std::isfinite(scale) ? scale : 0.0;
}

void ModelEvaluator::reject(const std::string& why, Vector* f) const {
  failure_ = why;
  if (f) f->putScalar(std::numeric_limits<double>::quiet_NaN());
}

namespace {

bool sameVector(const Vector& a, const Vector& b) {
  const auto da = a.getData(0), db = b.getData(0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(da.size()); ++i)
    if (da[i] != db[i]) return false;
  return true;
}

bool allFinite(const Vector& v) {
  const auto d = v.getData(0);
  for (double value : d)
    if (!std::isfinite(value)) return false;
  return true;
}

}  // namespace

void ModelEvaluator::evalContact(const Vector& x, Vector* f, const Teuchos::RCP<Thyra::LinearOpBase<double>>& W) const {
  // The same iterate on every rank or none: agree before any collective.
  const bool local = lastX_.is_null() || !sameVector(x, *lastX_);
  // Saddle-point form: x = (u, z), u the leading part of the local data.
  if (saddlePoint_) {
    if (displacement_.is_null()) displacement_ = Teuchos::rcp(new Vector(map_));
    contact::ContactModel::displacementPart(x, *displacement_);
  }
  const Vector& u = saddlePoint_ ? *displacement_ : x;
  if (anyRank(*map_->getComm(), local)) {
    if (bulkResidual_.is_null()) bulkResidual_ = Teuchos::rcp(new Vector(map_));
    const auto& comm = *map_->getComm();
    if (reactions_.is_null()) reactions_ = Teuchos::rcp(new Vector(map_));
    const auto assembled =
        assembler_.assemble(time_, u, bulkResidual_.get(), nullptr, reactions_.get(), linearizeLaggingBoundary_);
    boundaryLags_ = assembled.boundaryLags;
    const bool inverted = assembled.invertedElement;  // the same on every rank (Assembler::assemble)
    lastInvalid_ = inverted || anyRank(comm, !allFinite(*bulkResidual_));
    if (lastInvalid_) failure_ = inverted ? assembled.invertedMessage() : "the bulk residual is not finite";
    try {
      if (!lastInvalid_ && saddlePoint_) contact_->updateSaddlePoint(x, u);
      else if (!lastInvalid_) contact_->update(u, *bulkResidual_);
    } catch (const EvaluationError& e) {
      // Thrown on every rank alike (Parallel.hpp): the contact state of this
      // iterate is incomplete, the step fails and restores it.
      lastInvalid_ = true;
      failure_ = e.what();
    }
    if (!lastInvalid_) updateForceScale();
    lastX_ = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  }
  if (f) {
    if (lastInvalid_) {
      f->putScalar(std::numeric_limits<double>::quiet_NaN());
    } else if (saddlePoint_) {
      contact_->saddlePointResidual(*bulkResidual_, *f);
    } else {
      f->assign(*bulkResidual_);
      contact_->condenseResidual(*f);
    }
    if (!lastInvalid_ && anyRank(*map_->getComm(), !allFinite(*f))) {
      lastInvalid_ = true;
      reject("the contact residual is not finite", f);
    }
  }
  if (W != Teuchos::null && !lastInvalid_) {
    beforeJacobian_();
    // Condensed form: K is assembled into the last condensed tangent (its
    // pattern holds K's), which condensedTangent() completes in place.
    auto storage = saddlePoint_ ? Teuchos::null : contact_->tangentStorage();
    // A constant K is taken back from the storage (its rows were K's before
    // the interface rows were added): no element loop at all. Every choice
    // is agreed on by all ranks (anyRank). A stale storage (too many dead couplings) gets K assembled apart.
    const auto& comm = *map_->getComm();
    const bool usable = !storage.is_null() && !anyRank(comm, contact_->tangentStorageStale());
    const bool restored = usable && reuseConstantTangent_ && assembler_.tangentIsConstant() &&
                          !anyRank(comm, !contact_->restoreBulkTangent());
    const bool inPlace = restored || (usable && !anyRank(comm, !assembler_.acceptsTangent(*storage)));
    if (inPlace) bulkTangent_ = storage;
    else if (bulkTangent_.is_null()) bulkTangent_ = assembler_.createMatrix();
    storage = Teuchos::null;
    if (!restored) assembler_.assemble(time_, u, nullptr, bulkTangent_.get());
    auto tangent = saddlePoint_ ? contact_->saddlePointTangent(*bulkTangent_) : contact_->condensedTangent(bulkTangent_);
    // The bulk tangent is consumed: hold no second K-sized matrix through the
    // linear solve (the next Jacobian allocates it again, ~1 % of its time).
    if (inPlace || tangent.get() != bulkTangent_.get()) bulkTangent_ = Teuchos::null;
    using ThyraOp = Thyra::TpetraLinearOp<Scalar, LocalOrdinal, GlobalOrdinal, typename CrsMatrix::node_type>;
    auto* op = dynamic_cast<ThyraOp*>(W.get());
    COULOMB_CHECK(op != nullptr, "the Jacobian operator is not a Thyra::TpetraLinearOp");
    op->initialize(space_, space_, tangent);
  }
}

}  // namespace coulomb::solver
