/// @file PMultigrid.cpp
/// @brief The p-coarsening preconditioner of quadratic meshes (see the header).
#include "coulomb/solver/PMultigrid.hpp"

#include <Ifpack2_Relaxation.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <TpetraExt_TripleMatrixMultiply.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/TpetraTypes.hpp"

namespace coulomb::solver {
namespace {

using Operator = Tpetra::Operator<double, LocalOrdinal, GlobalOrdinal>;
using RowMatrix = Tpetra::RowMatrix<double, LocalOrdinal, GlobalOrdinal>;
using Relaxation = Ifpack2::Relaxation<RowMatrix>;

/// One two-level cycle (the header): Tpetra operator z = M^-1 r.
class PMultigridOperator : public Operator {
public:
  /// A new cycle on A; with `keepCoarseFrom`, the corner level of that
  /// cycle (its P and MueLu hierarchy) is used as it is, and only the
  /// smoothers are made on A.
  PMultigridOperator(const Teuchos::RCP<const CrsMatrix>& A, const Teuchos::ParameterList& parameters,
                     const PMultigridOperator* keepCoarseFrom)
      : A_(A) {
    static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: p-multigrid setup");
    Teuchos::TimeMonitor scope(*timer);
    if (keepCoarseFrom != nullptr) {
      P_ = keepCoarseFrom->P_;
      coarse_ = keepCoarseFrom->coarse_;
    } else {
      P_ = parameters.get<Teuchos::RCP<CrsMatrix>>("Prolongator");
      COULOMB_CHECK(!P_.is_null() && P_->getRangeMap()->isSameAs(*A->getRangeMap()),
                    "P-Multigrid: the prolongator's rows are the system's DoFs");
      // P^T A P, the operator of the linear mesh on the corner nodes.
      auto coarse = Teuchos::rcp(new CrsMatrix(P_->getDomainMap(), 0));
      Tpetra::TripleMatrixMultiply::MultiplyRAP(*P_, true, *A, false, *P_, false, *coarse);
      Teuchos::ParameterList muelu = parameters.sublist("Coarse MueLu");
      muelu.sublist("user data").set("Nullspace", parameters.get<Teuchos::RCP<MultiVector>>("Coarse Nullspace"));
      muelu.sublist("user data").set("Coordinates", parameters.get<Teuchos::RCP<MultiVector>>("Coarse Coordinates"));
      coarse_ = MueLu::CreateTpetraPreconditioner<double, LocalOrdinal, GlobalOrdinal, CrsMatrix::node_type>(
          Teuchos::RCP<Operator>(coarse), muelu);
    }
    auto smoother = [&](const char* name, bool zeroStart) {
      auto relaxation = Teuchos::rcp(new Relaxation(A));
      Teuchos::ParameterList list = parameters.sublist(name);
      list.set("relaxation: zero starting solution", zeroStart);
      relaxation->setParameters(list);
      relaxation->initialize();
      relaxation->compute();
      return relaxation;
    };
    pre_ = smoother("Pre Smoother", true);
    // The post-smoother sweeps from the corrected iterate (no residual to form).
    post_ = smoother("Post Smoother", false);
  }

  Teuchos::RCP<const Map> getDomainMap() const override { return A_->getDomainMap(); }
  Teuchos::RCP<const Map> getRangeMap() const override { return A_->getRangeMap(); }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS, double alpha = 1.0,
             double beta = 0.0) const override {
    COULOMB_CHECK(mode == Teuchos::NO_TRANS, "P-Multigrid: no transposed application");
    const std::size_t k = X.getNumVectors();
    if (z_.is_null() || z_->getNumVectors() != k) {
      z_ = Teuchos::rcp(new MultiVector(A_->getRangeMap(), k));
      r_ = Teuchos::rcp(new MultiVector(A_->getRangeMap(), k));
      rc_ = Teuchos::rcp(new MultiVector(P_->getDomainMap(), k));
      zc_ = Teuchos::rcp(new MultiVector(P_->getDomainMap(), k));
    }
    MultiVector& z = *z_;
    MultiVector& r = *r_;
    pre_->apply(X, z);  // from z = 0
    A_->apply(z, r);
    r.update(1.0, X, -1.0);  // r = X - A z
    P_->apply(r, *rc_, Teuchos::TRANS);
    coarse_->apply(*rc_, *zc_);
    P_->apply(*zc_, z, Teuchos::NO_TRANS, 1.0, 1.0);
    post_->apply(X, z);  // from z
    Y.update(alpha, z, beta);
  }

private:
  Teuchos::RCP<const CrsMatrix> A_;
  Teuchos::RCP<CrsMatrix> P_;
  Teuchos::RCP<Operator> coarse_;
  Teuchos::RCP<Relaxation> pre_, post_;
  mutable Teuchos::RCP<MultiVector> z_, r_, rc_, zc_;
};

Teuchos::RCP<const CrsMatrix> matrixOf(const Thyra::LinearOpSourceBase<double>& source) {
  using ThyraOp = Thyra::TpetraLinearOp<double, LocalOrdinal, GlobalOrdinal, CrsMatrix::node_type>;
  const auto op = Teuchos::rcp_dynamic_cast<const ThyraOp>(source.getOp());
  if (op.is_null()) return Teuchos::null;
  return Teuchos::rcp_dynamic_cast<const CrsMatrix>(op->getConstTpetraOperator());
}

}  // namespace

bool PMultigridFactory::isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const {
  return !matrixOf(fwdOpSrc).is_null();
}

Teuchos::RCP<Thyra::PreconditionerBase<double>> PMultigridFactory::createPrec() const {
  return Teuchos::rcp(new Thyra::DefaultPreconditioner<double>());
}

void PMultigridFactory::initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                                       Thyra::PreconditionerBase<double>* prec,
                                       const Thyra::ESupportSolveUse /*supportSolveUse*/) const {
  const auto A = matrixOf(*fwdOpSrc);
  COULOMB_CHECK(!A.is_null(), "P-Multigrid: the operator is a Tpetra::CrsMatrix");
  auto* target = dynamic_cast<Thyra::DefaultPreconditioner<double>*>(prec);
  COULOMB_CHECK(target != nullptr, "P-Multigrid: a Thyra::DefaultPreconditioner");
  // The cycle this preconditioner holds now, if any (NOX passes the same
  // object at every setup), for its corner level.
  const PMultigridOperator* last = nullptr;
  const bool keep = keepCoarseLevel_;
  keepCoarseLevel_ = false;
  if (keep) {
    using ThyraOp = Thyra::TpetraLinearOp<double, LocalOrdinal, GlobalOrdinal, CrsMatrix::node_type>;
    const auto held = Teuchos::rcp_dynamic_cast<const ThyraOp>(target->getUnspecifiedPrecOp());
    if (!held.is_null()) last = dynamic_cast<const PMultigridOperator*>(held->getConstTpetraOperator().get());
    if (last != nullptr && !last->getRangeMap()->isSameAs(*A->getRangeMap())) last = nullptr;
  }
  if (last != nullptr) ++coarseLevelReuses_;
  Teuchos::RCP<Operator> op = Teuchos::rcp(new PMultigridOperator(A, *parameters_, last));
  Teuchos::RCP<Thyra::LinearOpBase<double>> thyraOp =
      Thyra::tpetraLinearOp<double, LocalOrdinal, GlobalOrdinal, CrsMatrix::node_type>(
          Thyra::tpetraVectorSpace<double>(op->getRangeMap()), Thyra::tpetraVectorSpace<double>(op->getDomainMap()), op);
  target->initializeUnspecified(thyraOp);
}

void PMultigridFactory::uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                                         Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                                         Thyra::ESupportSolveUse* supportSolveUse) const {
  auto* target = dynamic_cast<Thyra::DefaultPreconditioner<double>*>(prec);
  if (target != nullptr) target->uninitialize();
  if (fwdOpSrc != nullptr) *fwdOpSrc = Teuchos::null;
  if (supportSolveUse != nullptr) *supportSolveUse = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
}

void PMultigridFactory::setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& paramList) {
  parameters_ = paramList;
}
Teuchos::RCP<Teuchos::ParameterList> PMultigridFactory::getNonconstParameterList() { return parameters_; }
Teuchos::RCP<Teuchos::ParameterList> PMultigridFactory::unsetParameterList() {
  auto old = parameters_;
  parameters_ = Teuchos::null;
  return old;
}
Teuchos::RCP<const Teuchos::ParameterList> PMultigridFactory::getParameterList() const { return parameters_; }
Teuchos::RCP<const Teuchos::ParameterList> PMultigridFactory::getValidParameters() const {
  // Not validated here: MueLu and Ifpack2 check their own sublists.
  static const auto valid = Teuchos::rcp(new Teuchos::ParameterList(kPMultigridName));
  return valid;
}

}  // namespace coulomb::solver
