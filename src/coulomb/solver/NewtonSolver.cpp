#include "coulomb/solver/NewtonSolver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

#include <NOX_Observer.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_StatusTest_NormWRMS.H>
#include <NOX_Thyra.H>
#include <NOX_Utils.H>
#include <Thyra_SolveSupportTypes.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/core/Interrupt.hpp"
#include "coulomb/core/Parallel.hpp"
#include "coulomb/solver/PMultigrid.hpp"

namespace coulomb::solver {

namespace {

/// NOX::Thyra::Group that tells how many Krylov iterations its last solve took.
/// With an adaptive linear tolerance it also chooses the Krylov tolerance of
/// each Newton solve (LinearTolerance.hpp).
class CountingGroup : public NOX::Thyra::Group {
public:
  /// Shared by the clones NOX makes of the group: the residual norm before the previous step.
  struct Forcing {
    LinearToleranceSettings settings;
    std::function<double()> target;  ///< residual norm at which Newton stops (at the current iterate)
    double previousNormF = -1.0;   ///< <= 0: no Newton step taken yet
  };
  /// Shared by the clones: when the last preconditioner is kept (NewtonSettings::reusePreconditioner).
  struct PreconditionerReuse {
    const contact::ContactModel* contact = nullptr;
    int solves = 0;             ///< solves of this load step so far
    bool lastReused = false;    ///< the last solve kept the preconditioner
    bool lastCoarseKept = false;  ///< the last solve's new preconditioner kept the corner level of the one before
    /// The matrix the preconditioner was built from: the object, its graph
    /// and column map, its entries (this rank). Held, so that an address
    /// compared later is never a new object at a freed one's place.
    struct Structure {
      Teuchos::RCP<const CrsMatrix> matrix;
      Teuchos::RCP<const Tpetra::CrsGraph<LocalOrdinal, GlobalOrdinal>> graph;
      Teuchos::RCP<const Map> columns;
      std::size_t entries = 0;
      bool same(const Structure& o) const {
        return matrix.get() == o.matrix.get() && graph.get() == o.graph.get() && columns.get() == o.columns.get() &&
               entries == o.entries;
      }
    } built;
  };
  using NOX::Thyra::Group::Group;
  CountingGroup(const CountingGroup& source, NOX::CopyType type)
      : NOX::Thyra::Group(source, type),
        forcing_(source.forcing_),
        reuse_(source.reuse_),
        prescribed_(source.prescribed_),
        linearFailure_(source.linearFailure_) {}
  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type) const override {
    return Teuchos::rcp(new CountingGroup(*this, type));
  }
  int lastLinearIterations() const { return last_linear_solve_num_iters_; }
  void setForcing(std::shared_ptr<Forcing> forcing) { forcing_ = std::move(forcing); }
  void setPreconditionerReuse(std::shared_ptr<PreconditionerReuse> reuse) { reuse_ = std::move(reuse); }
  /// The owned-local prescribed DoFs (DirichletConstraints::ownedConstrainedDofs).
  void setPrescribedDofs(std::shared_ptr<const std::vector<int>> dofs) { prescribed_ = std::move(dofs); }
  /// Shared by the clones: why the first linear solve that threw failed
  /// (empty: none did).
  const std::shared_ptr<std::string>& linearFailure() const { return linearFailure_; }

  /// NOX passes the Newton direction's "Linear Solver" list; its "Tolerance"
  /// becomes the relative residual tolerance of the Belos solve.
  NOX::Abstract::Group::ReturnType computeNewton(Teuchos::ParameterList& p) override {
    if (forcing_) {
      const double normF = getNormF();
      p.set("Tolerance", linearTolerance(forcing_->settings, normF, forcing_->previousNormF, forcing_->target()));
      forcing_->previousNormF = normF;
    }
    auto* pMultigrid = reuse_ ? dynamic_cast<PMultigridFactory*>(prec_factory_.get()) : nullptr;
    if (reuse_) {
      const Reuse reuse = preconditionerReuse();  // CoarseLevel is a full setup but for P-Multigrid
      reuse_->lastReused = reuse == Reuse::Whole;
      updatePreconditioner_ = reuse != Reuse::Whole;  // NOX builds prec_ before each solve unless told not to
      if (pMultigrid != nullptr) pMultigrid->keepCoarseLevel(reuse == Reuse::CoarseLevel);
      ++reuse_->solves;
    }
    // What the factory did, not what was asked (it builds anew without a cycle to take the corner level from).
    const int coarseKeptBefore = pMultigrid != nullptr ? pMultigrid->coarseLevelReuses() : 0;
    auto recordCoarseLevel = [&] {
      if (reuse_) reuse_->lastCoarseKept = pMultigrid != nullptr && pMultigrid->coarseLevelReuses() > coarseKeptBefore;
    };
    try {
      const auto status = NOX::Thyra::Group::computeNewton(p);
      recordCoarseLevel();
      exactPrescribedUpdate();  // also for a solve that missed its tolerance: NOX may still take the step
      return status;
    } catch (const Thyra::CatastrophicSolveFailure& e) {
      // A Belos solve that throws (Thyra wraps Belos' errors in this: a NaN
      // in its residual norms, e.g. from a zero diagonal in the condensed
      // tangent; the norms are global, so every rank throws) rejects the
      // iterate instead of ending the run: the direction is not a number,
      // NOX's "Rescue Bad Newton Solve" (its default) takes it, the next
      // iterate fails the finite-value test and the step is cut back, with
      // this reason. Anything else (a preconditioner or a direct solver may
      // throw on some ranks only) still ends the run.
      recordCoarseLevel();
      if (linearFailure_->empty()) *linearFailure_ = lastLine(e.what());
      newton_vec_->init(std::numeric_limits<double>::quiet_NaN());
      is_valid_newton_dir_ = true;
      return NOX::Abstract::Group::Failed;
    }
  }

private:
  /// A prescribed DoF's row of the Jacobian is the identity's (the bulk
  /// assembly makes it so, and no contact row is written there), so its
  /// Newton update is -f exactly: u − ū
  /// becomes zero in one step, whatever the Krylov solve left in these rows
  /// (up to its tolerance, a length compared with forces). An iterate that
  /// starts a step behind its boundary values (DirichletConstraints.hpp)
  /// then carries them from its second iterate on.
  void exactPrescribedUpdate() {
    if (!prescribed_ || prescribed_->empty()) return;
    using Extract = Thyra::TpetraOperatorVectorExtraction<Scalar, LocalOrdinal, GlobalOrdinal>;
    auto direction = Extract::getTpetraVector(newton_vec_->getThyraRCPVector());
    const auto f = Extract::getConstTpetraVector(f_vec_->getThyraRCPVector());
    auto dx = direction->getDataNonConst(0);
    const auto fData = f->getData(0);
    for (int dof : *prescribed_) dx[dof] = -fData[dof];
  }

  /// Whether this solve keeps the last built preconditioner. The tangent
  /// changes little while the contact set stays the same, and the setup
  /// (MueLu: a quarter of a contact iteration) is saved. It is no longer
  /// the exact preconditioner of that matrix: the matrix is mostly updated
  /// in place, so the smoothers apply the new values with what they derived
  /// from the old ones (diagonals). Kept only
  ///  - after the step's first solve (a cutback or a new step may have
  ///    changed the set since);
  ///  - after a converged solve (a kept preconditioner that let GMRES fail
  ///    is not kept again);
  ///  - over the same matrix structure: the preconditioner keeps references
  ///    into the matrix it was built from (Ifpack2's smoother caches what it
  ///    derives from the graph), so a matrix completed in place with a new
  ///    column map would be read through stale indices.
  /// Where only the structure differs, a preconditioner that can keeps the
  /// part that holds no reference into the matrix: P-Multigrid its corner
  /// level (PMultigridFactory::keepCoarseLevel: P^T A P of the earlier
  /// matrix), with new smoothers on the new one. The condensed tangent's
  /// pattern often grows by a few small couplings while the set stays
  /// (HEX20 hertz3d --ref 1: in all 6 of 17 solves that had the set of the
  /// solve before).
  /// The set and the solve status are the same on every rank; the structure
  /// is agreed on. Records the structure whenever a new one is built.
  enum class Reuse { None, Whole, CoarseLevel };
  Reuse preconditionerReuse() {
    const auto& set = reuse_->contact->lastSummary().activeSet;
    const bool sameSet = set.changed == 0 && set.stickSlipChanged == 0;
    PreconditionerReuse::Structure now;
    now.matrix = Teuchos::rcp_dynamic_cast<const CrsMatrix>(
        Thyra::TpetraOperatorVectorExtraction<Scalar, LocalOrdinal, GlobalOrdinal>::getConstTpetraOperator(lop_));
    if (!now.matrix.is_null()) {
      now.graph = now.matrix->getCrsGraph();
      now.columns = now.matrix->getColMap();
      now.entries = now.matrix->getNodeNumEntries();
    }
    const bool keep = reuse_->solves > 0 && sameSet && last_linear_solve_status_ == NOX::Abstract::Group::Ok &&
                      !prec_.is_null() && !now.matrix.is_null();
    if (keep && !anyRank(*now.matrix->getRowMap()->getComm(), !now.same(reuse_->built))) return Reuse::Whole;
    reuse_->built = now;
    return keep ? Reuse::CoarseLevel : Reuse::None;
  }

  /// The last non-empty line of a (Teuchos, multi-line) exception message.
  static std::string lastLine(const std::string& what) {
    std::string line, last;
    std::istringstream in(what);
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t") != std::string::npos) last = line;
    while (!last.empty() && (last.back() == '.' || last.back() == ' ')) last.pop_back();
    return last.empty() ? std::string("an exception without a message") : last;
  }

  std::shared_ptr<Forcing> forcing_;
  std::shared_ptr<PreconditionerReuse> reuse_;
  std::shared_ptr<const std::vector<int>> prescribed_;
  std::shared_ptr<std::string> linearFailure_ = std::make_shared<std::string>();
};

/// The residual test: ||f|| <= max(tol, 1000 eps) × S, S the larger of the
/// force scale of the iterate (ModelEvaluator::forceScale: reactions, loads,
/// contact forces) and ||f_0|| of the step (what a problem with nothing
/// loaded has); or ||f|| <=
/// the deck's absolute tolerance when one is set. Measured against the
/// problem's forces, not the step's first residual (tiny after a good
/// predictor), and in the problem's force unit: the same iterations in
/// mm/N/MPa and m/N/Pa. 1000 eps is the round-off floor a residual summed
/// from element forces of size S can reach. The residual's noise can also
/// come from forces that cancel (a body moved rigidly, stresses much larger
/// than the reactions): so the test also passes once the Newton increment is
/// below round-off of the solution itself, ||du|| <= 1000 eps ||u|| — the
/// iterate no longer changes, whatever the residual's floor.
class ScaledResidualTest : public NOX::StatusTest::Generic {
public:
  ScaledResidualTest(const ModelEvaluator& model, const NewtonSettings& settings, double initialNorm)
      : model_(model), settings_(settings), initialNorm_(initialNorm) {}
  /// ||f|| at which the test passes for the model's current force scale.
  static double target(const ModelEvaluator& model, const NewtonSettings& settings, double initialNorm) {
    const double scale = std::max(model.forceScale(), initialNorm);
    const double relative = std::max(settings.relativeTolerance, 1e3 * std::numeric_limits<double>::epsilon());
    return std::max(relative * scale, settings.absoluteTolerance);
  }
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    normF_ = solver.getSolutionGroup().getNormF();
    target_ = target(model_, settings_, initialNorm_);
    bool converged = normF_ <= target_;
    if (!converged && solver.getNumIterations() > 0 && std::isfinite(normF_)) {
      const auto& x = solver.getSolutionGroup().getX();
      auto increment = x.clone(NOX::DeepCopy);
      increment->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
      const double size = x.norm();
      converged = size > 0 && increment->norm() <= 1e3 * std::numeric_limits<double>::epsilon() * size;
    }
    status_ = converged ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  /// The ||f|| the last check asked for.
  double target() const { return target_; }
  std::ostream& print(std::ostream& stream, int indent = 0) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << status_ << " ||f|| = " << normF_ << " <= " << target_ << " (force-scaled)\n";
  }

private:
  const ModelEvaluator& model_;
  const NewtonSettings& settings_;
  double initialNorm_;
  double normF_ = 0, target_ = 0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

/// A NOX status test read off a condition of the model: `whenMet` while
/// `condition()` holds, `otherwise` else. The contact and boundary parts of
/// the convergence test and the cycle test are such conditions (below, at
/// the Combo that holds them).
class ConditionTest : public NOX::StatusTest::Generic {
public:
  ConditionTest(std::function<bool()> condition, NOX::StatusTest::StatusType whenMet,
                NOX::StatusTest::StatusType otherwise, std::string label)
      : condition_(std::move(condition)), whenMet_(whenMet), otherwise_(otherwise), label_(std::move(label)) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic&, NOX::StatusTest::CheckType) override {
    status_ = condition_() ? whenMet_ : otherwise_;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent = 0) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << status_ << " " << label_ << "\n";
  }

private:
  std::function<bool()> condition_;
  NOX::StatusTest::StatusType whenMet_, otherwise_;
  std::string label_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

/// Fails the solve when some rank received SIGINT/SIGTERM (core/Interrupt.hpp):
/// the step is abandoned, the simulation stops with the converged steps.
class InterruptTest : public NOX::StatusTest::Generic {
public:
  explicit InterruptTest(Teuchos::RCP<const Teuchos::Comm<int>> comm) : comm_(std::move(comm)) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic&, NOX::StatusTest::CheckType) override {
    status_ = interruptSignalOnAnyRank(*comm_) != 0 ? NOX::StatusTest::Failed : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << status_ << " interrupt\n";
  }

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

/// Records one table row per iteration and prints it on rank 0.
class IterationTable : public NOX::Observer {
public:
  IterationTable(NewtonReport& report, std::ostream* console, const contact::ContactModel* contact,
                 std::shared_ptr<const CountingGroup::PreconditionerReuse> reuse)
      : report_(report), console_(console), contact_(contact), reuse_(std::move(reuse)) {}

  void runPreSolve(const NOX::Solver::Generic& solver) override {
    start_ = Clock::now();
    NewtonIteration row;
    row.residualNorm = solver.getSolutionGroup().getNormF();
    addContact(row);
    report_.iterations.push_back(row);
    if (console_) {
      *console_ << "    iter   |residual|    |increment|  lin.it  time[s]";
      if (contact_) *console_ << "  active changed  |r_normal|  ratio    ";
      if (contact_ && contact_->anyFrictional()) *console_ << "  stick st/sl   |r_stick|    |r_slip|";
      if (contact_) *console_ << "  set";
      *console_ << "\n";
      print(row);
    }
  }

  void runPostIterate(const NOX::Solver::Generic& solver) override {
    if (solver.getNumIterations() == 0) return;  // NOX reports a failed first status check here too
    const auto now = Clock::now();
    NewtonIteration row;
    row.iteration = solver.getNumIterations();
    const auto& group = solver.getSolutionGroup();
    row.residualNorm = group.isF() ? group.getNormF() : -1.0;
    auto difference = group.getX().clone(NOX::DeepCopy);
    difference->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
    row.incrementNorm = difference->norm();
    if (const auto* counting = dynamic_cast<const CountingGroup*>(&group)) row.linearIterations = counting->lastLinearIterations();
    row.preconditionerReused = reuse_ && reuse_->lastReused;
    row.coarseLevelKept = reuse_ && reuse_->lastCoarseKept;
    row.seconds = std::chrono::duration<double>(now - start_).count();
    addContact(row);
    start_ = now;
    report_.iterations.push_back(row);
    if (console_) print(row);
  }

private:
  using Clock = std::chrono::steady_clock;
  void addContact(NewtonIteration& row) const {
    if (!contact_) return;
    const auto& s = contact_->lastSummary();
    row.activeNodes = static_cast<long long>(s.activeSet.active);
    row.changedNodes = static_cast<long long>(s.activeSet.changed);
    row.normalResidual = s.normalResidual;
    row.normalRatio = s.contactForce > 0 ? s.normalResidual / s.contactForce : 0.0;
    row.contactConverged = contact_->converged();
    if (contact_->anyFrictional()) {
      row.stickNodes = static_cast<long long>(s.activeSet.stick);
      row.stickSlipChanged = static_cast<long long>(s.activeSet.stickSlipChanged);
      row.stickResidual = s.stickResidual;
      row.slipResidual = s.slipResidual;
    }
  }
  void print(const NewtonIteration& row) const {
    *console_ << "    " << std::setw(4) << row.iteration << std::scientific << std::setprecision(3) << "  "
              << std::setw(11) << row.residualNorm << "  " << std::setw(11);
    if (row.iteration == 0) *console_ << "-";
    else *console_ << row.incrementNorm;
    *console_ << "  " << std::setw(6) << row.linearIterations << "  " << std::fixed << std::setprecision(3)
              << std::setw(7) << row.seconds << std::defaultfloat;
    if (row.activeNodes >= 0)
      *console_ << "  " << std::setw(6) << row.activeNodes << "  " << std::setw(7) << row.changedNodes << "  "
                << std::scientific << std::setprecision(3) << std::setw(10) << row.normalResidual << "  "
                << std::setw(9) << row.normalRatio << std::defaultfloat;
    if (row.stickNodes >= 0)
      *console_ << "  " << std::setw(5) << row.stickNodes << "  " << std::setw(5) << row.stickSlipChanged << "  "
                << std::scientific << std::setprecision(3) << std::setw(10) << row.stickResidual << "  "
                << std::setw(10) << row.slipResidual << std::defaultfloat;
    if (row.activeNodes >= 0) *console_ << "  " << (row.contactConverged ? "yes" : "no");
    *console_ << "\n";
  }
  NewtonReport& report_;
  std::ostream* console_;
  const contact::ContactModel* contact_;
  std::shared_ptr<const CountingGroup::PreconditionerReuse> reuse_;
  Clock::time_point start_;
};

}  // namespace

int NewtonReport::linearIterations() const {
  int total = 0;
  for (const auto& row : iterations) total += row.linearIterations;
  return total;
}

int NewtonReport::preconditionerReuses() const {
  int total = 0;
  for (const auto& row : iterations) total += row.preconditionerReused ? 1 : 0;
  return total;
}

int NewtonReport::coarseLevelReuses() const {
  int total = 0;
  for (const auto& row : iterations) total += row.coarseLevelKept ? 1 : 0;
  return total;
}

Teuchos::RCP<Teuchos::ParameterList> NewtonSolver::defaultParameters() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Nonlinear Solver"));
  p->set("Nonlinear Solver", "Line Search Based");
  p->sublist("Line Search").set("Method", "Full Step");
  p->sublist("Direction").set("Method", "Newton");
  p->sublist("Printing").set("Output Information", static_cast<int>(NOX::Utils::Error));
  return p;
}

NewtonSolver::NewtonSolver(Teuchos::RCP<ModelEvaluator> model, const Teuchos::ParameterList& noxParameters,
                           const NewtonSettings& settings, std::ostream* console,
                           const contact::ContactModel* contact)
    : model_(std::move(model)),
      noxParameters_(Teuchos::rcp(new Teuchos::ParameterList(noxParameters))),
      settings_(settings),
      console_(console),
      contact_(contact && !contact->empty() ? contact : nullptr) {
  noxParameters_->setParametersNotAlreadySet(*defaultParameters());
}

NewtonReport NewtonSolver::solve(Vector& u) {
  using Extract = Thyra::TpetraOperatorVectorExtraction<Scalar, LocalOrdinal, GlobalOrdinal>;
  auto space = model_->get_x_space();
  auto thyraU = Thyra::createVector(Teuchos::rcpFromRef(u), space);
  NOX::Thyra::Vector initialGuess(thyraU);
  model_->clearFailure();
  auto group = Teuchos::rcp(new CountingGroup(initialGuess, model_));
  group->computeF();
  if (settings_.linearTolerance.adaptive && !noxSetsLinearTolerance(*noxParameters_)) {
    auto forcing = std::make_shared<CountingGroup::Forcing>();
    forcing->settings = settings_.linearTolerance;
    forcing->settings.looseFirstIteration = contact_ != nullptr;
    const double initialNorm = group->getNormF();
    const ModelEvaluator& model = *model_;
    const NewtonSettings& settings = settings_;
    forcing->target = [&model, &settings, initialNorm] {
      return ScaledResidualTest::target(model, settings, initialNorm);
    };
    group->setForcing(forcing);
  }
  group->setPrescribedDofs(std::make_shared<const std::vector<int>>(model_->prescribedDofs()));
  std::shared_ptr<CountingGroup::PreconditionerReuse> reuse;
  if (settings_.reusePreconditioner && contact_ && !directSolver_) {
    reuse = std::make_shared<CountingGroup::PreconditionerReuse>();
    reuse->contact = contact_;
    group->setPreconditionerReuse(reuse);
  }

  using namespace NOX::StatusTest;
  auto converged = Teuchos::rcp(new Combo(Combo::AND));
  // Contact/Convergence Criterion = Increment: the displacement increment instead of ||f||.
  Teuchos::RCP<NormWRMS> incrementTest;
  Teuchos::RCP<ScaledResidualTest> residualTest;
  if (contact_ && contact_->settings().criterion == contact::ConvergenceCriterion::Increment)
    converged->addStatusTest(incrementTest = Teuchos::rcp(new NormWRMS(contact_->settings().incrementRelativeTolerance,
                                                                       contact_->settings().incrementAbsoluteTolerance)));
  else
    converged->addStatusTest(residualTest = Teuchos::rcp(new ScaledResidualTest(*model_, settings_, group->getNormF())));
  const contact::ContactModel* contact = contact_;
  const ModelEvaluator* model = model_.get();
  // Contact: the active set did not change at the current iterate and the
  // normal constraint residual is small.
  if (contact)
    converged->addStatusTest(Teuchos::rcp(new ConditionTest([contact] { return contact->converged(); }, Converged,
                                                            Unconverged,
                                                            "contact: active set unchanged and normal residual converged")));
  // Not converged while the last residual had prescribed DoFs behind ū
  // ('Boundary Increment' = Tangent): that residual holds their linearised
  // coupling, and a step must not end before the first Newton update puts
  // them in place, however small the lag.
  converged->addStatusTest(Teuchos::rcp(new ConditionTest([model] { return !model->boundaryLags(); }, Converged,
                                                          Unconverged, "prescribed values in place")));
  auto tests = Teuchos::rcp(new Combo(Combo::OR));
  tests->addStatusTest(Teuchos::rcp(new FiniteValue));
  tests->addStatusTest(converged);
  tests->addStatusTest(Teuchos::rcp(new MaxIters(settings_.maximumIterations)));
  // The contact sets cycle (ActiveSetCycle.hpp): the step is cut back at
  // once instead of at the iteration limit.
  if (contact)
    tests->addStatusTest(Teuchos::rcp(new ConditionTest([contact] { return contact->cyclePeriod() > 0; }, Failed,
                                                        Unconverged, "active-set cycle")));
  tests->addStatusTest(Teuchos::rcp(new InterruptTest(u.getMap()->getComm())));

  NewtonReport report;
  auto parameters = Teuchos::rcp(new Teuchos::ParameterList(*noxParameters_));
  parameters->sublist("Solver Options").set<Teuchos::RCP<NOX::Observer>>(
      "Observer", Teuchos::rcp(new IterationTable(report, console_, contact_, reuse)));
  auto solver = NOX::Solver::buildSolver(group, tests, parameters);
  const auto status = solver->solve();
  report.converged = status == NOX::StatusTest::Converged;
  report.failure = model_->lastFailure();
  // A linear solve that threw: its reason, not the NaN iterate's it led to.
  if (!group->linearFailure()->empty()) report.failure = "the linear solve failed: " + *group->linearFailure();
  if (!report.converged && contact_ && contact_->cyclePeriod() > 0) report.stopReason = contact_->cycleDescription();
  if (!report.converged && report.stopReason.empty() && report.failure.empty()) {
    // Out of iterations (or NOX gave up): which groups the last iterate missed.
    std::ostringstream unmet;
    unmet << std::setprecision(3);
    const double normF = solver->getSolutionGroup().getNormF();
    if (!std::isfinite(normF)) unmet << "the residual is not a finite number";
    else if (residualTest && residualTest->getStatus() != Converged)
      unmet << "the equilibrium residual (||f|| = " << normF << " > " << residualTest->target() << ")";
    else if (incrementTest && incrementTest->getStatus() != Converged)
      unmet << "the displacement increment (WRMS = " << incrementTest->getNormWRMS() << " > " << incrementTest->getTolerance() << ")";
    const std::string contact = contact_ ? contact_->unmetCriteria() : "";
    if (!contact.empty()) unmet << (unmet.tellp() > 0 ? ", " : "") << contact;
    std::ostringstream reason;
    reason << "after " << report.iterations.size() - 1 << " iterations";
    if (static_cast<int>(report.iterations.size()) - 1 >= settings_.maximumIterations)
      reason << " (the limit, 'Newton/Maximum Iterations' = " << settings_.maximumIterations << ")";
    reason << " not met: " << (unmet.tellp() > 0 ? unmet.str() : std::string("the nonlinear solver's own tests"));
    report.stopReason = reason.str();
  }

  const auto& solution = dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
  u.assign(*Extract::getConstTpetraVector(solution.getThyraRCPVector()));
  return report;
}

}  // namespace coulomb::solver
