#include "coulomb/solver/Simulation.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <set>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Interrupt.hpp"
#include "coulomb/core/Parallel.hpp"
#include "coulomb/fem/Assembler.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/fem/MeshChecks.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/fem/RigidBodyModes.hpp"
#include "coulomb/fem/VertexCoarsening.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/mesh/Mesh.hpp"
#include "coulomb/solver/LinearSolverFactory.hpp"
#include "coulomb/solver/PMultigrid.hpp"
#include "coulomb/solver/ModelEvaluator.hpp"
#include "coulomb/solver/NewtonSolver.hpp"
#include "coulomb/solver/ResultWriter.hpp"
#include "coulomb/solver/StepController.hpp"

namespace coulomb::solver {

namespace {

const char* const kComponents[] = {"x", "y", "z"};

std::string formatTime(double t) {
  std::ostringstream out;
  out << t;
  return out.str();
}

std::vector<std::string> componentNames(const std::string& field, int dim) {
  std::vector<std::string> names;
  for (int c = 0; c < dim; ++c) names.push_back(field + "_" + kComponents[c]);
  return names;
}

/// Owned-DoF vector viewed as an owned-node MultiVector with one column per component.
Teuchos::RCP<MultiVector> byNode(const Vector& v, const fem::DofMap& dofs) {
  const int dim = dofs.dofsPerNode();
  auto out = Teuchos::rcp(new MultiVector(dofs.ownedNodeMap(), dim));
  auto in = v.getData(0);
  auto view = out->get2dViewNonConst();
  const std::size_t n = dofs.ownedNodeMap()->getNodeNumElements();
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < dim; ++c) view[c][i] = in[i * dim + c];
  return out;
}

}  // namespace

struct Simulation::Solvers {
  LinearSolver linear;
  Teuchos::RCP<MultiVector> nullspace, coordinates;
  fem::VertexCoarsening vertices;  ///< quadratic cells: MueLu's first coarse level
  Teuchos::RCP<ModelEvaluator> model;
  std::unique_ptr<NewtonSolver> newton;
  std::unique_ptr<ResultWriter> writer;
};

Simulation::Simulation(const std::string& deckPath, const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                       std::ostream* console, const std::string& outputOverride, const std::string& meshOverride)
    : comm_(comm), console_(comm->getRank() == 0 ? console : nullptr) {
  // Every rank reads the deck and the mesh itself (no broadcast needed): the
  // same files give the same errors everywhere, so all ranks fail together.
  const auto deck = readDeck(deckPath);
  settings_ = parseRunSettings(*deck, deckPath);
  if (!outputOverride.empty()) settings_.outputFile = outputOverride;
  if (!meshOverride.empty()) settings_.meshFile = meshOverride;
  auto global = std::make_shared<mesh::GlobalMesh>(io::readExodus(settings_.meshFile, memoryBudget(*comm_)));
  const auto model = fem::parseModelSettings(*deck, global->dimension);
  if (model.axisymmetric(global->dimension)) fem::checkAxisymmetricMesh(*global, settings_.meshFile);
  mesh_ = std::make_unique<mesh::Mesh>(global, comm_);
  dofs_ = std::make_unique<fem::DofMap>(*mesh_);
  assembler_ = std::make_unique<fem::Assembler>(*mesh_, *dofs_, model);
  auto contactSettings = contact::parseContactSettings(*deck);
  contact::loadFrictionFields(contactSettings, settings_.meshFile);
  if (!contactSettings.pairs.empty())
    contact_ = std::make_unique<contact::ContactModel>(*mesh_, dofs_->ownedMap(), contactSettings, model);
  // Nodes at one point that no element joins: legitimate on contact
  // surfaces (bodies meshed touching), an unmerged mesh elsewhere.
  std::vector<char> onContactSurface(static_cast<std::size_t>(global->numNodes()), 0);
  for (std::size_t p = 0; contact_ && p < contact_->pairs().size(); ++p)
    for (long long node : contact_->pairs()[p]->interface().interfaceNodes())
      onContactSurface[static_cast<std::size_t>(node)] = 1;
  fem::checkCoincidentNodes(*global, onContactSurface, settings_.meshFile);

  if (contact_ && contact_->saddlePoint()) {
    // The saddle-point matrix (zero multiplier block on active normal rows)
    // is for the direct solver; MueLu or Krylov defaults would not solve it.
    auto& linear = settings_.linearSolver;
    COULOMB_REQUIRE(!linear.isParameter("Linear Solver Type") || linear.get<std::string>("Linear Solver Type") == "Amesos2",
                    "deck: 'Contact/System Form' = Saddle Point is solved by the direct solver: 'Linear Solver/Linear "
                    "Solver Type' must be Amesos2 or left out, got '"
                        << linear.get<std::string>("Linear Solver Type") << "'");
    linear.set("Linear Solver Type", "Amesos2");
  }
  solvers_ = std::make_unique<Solvers>();
  const long long corners = fem::cornerNodeCount(mesh_->global());
  solvers_->linear = buildLinearSolver(settings_.linearSolver, dofs_->dofsPerNode(),
                                      static_cast<long long>(dofs_->ownedMap()->getGlobalNumElements()),
                                      !(contact_ && contact_->needsNonsymmetricSolver()), corners * dofs_->dofsPerNode());
  COULOMB_REQUIRE(!solvers_->linear.usesPMultigrid || corners > 0,
                  "deck: 'Linear Solver/Preconditioner Type' = " << kPMultigridName
                      << " coarsens quadratic cells to their corners, but the mesh has none (use MueLu)");
  solvers_->nullspace = fem::rigidBodyModes(*mesh_, *dofs_);
  solvers_->coordinates = fem::nodalCoordinates(*mesh_, *dofs_);
  if (solvers_->linear.usesPMultigrid) solvers_->vertices = fem::vertexCoarsening(*mesh_, *dofs_);
  Solvers* s = solvers_.get();
  solvers_->model = Teuchos::rcp(new ModelEvaluator(*assembler_, dofs_->ownedMap(), solvers_->linear.factory,
                                                    [s] { setMueLuUserData(s->linear, s->nullspace, s->coordinates, &s->vertices); },
                                                    contact_.get()));
  solvers_->model->reuseConstantTangent(settings_.reuseConstantTangent);
  solvers_->model->linearizeLaggingBoundary(settings_.boundaryThroughTangent);
  // The iteration table is for --verbose (setVerbosity).
  solvers_->newton = std::make_unique<NewtonSolver>(solvers_->model, settings_.nonlinearSolver, settings_.newton,
                                                    nullptr, contact_.get());
  solvers_->newton->setDirectSolver(solvers_->linear.isDirect);
  displacement_ = Teuchos::rcp(new Vector(dofs_->ownedMap()));
  reactions_ = Teuchos::rcp(new Vector(dofs_->ownedMap()));
  if (contact_ && contact_->saddlePoint()) saddlePointState_ = Teuchos::rcp(new Vector(contact_->saddlePointMap()));

  // Load stepping lands on every knot of a load function (its rate changes there).
  auto addKnots = [this](const fem::TimeFunction& f) {
    loadKnots_.insert(loadKnots_.end(), f.knots().begin(), f.knots().end());
  };
  for (const auto& d : model.dirichlet) addKnots(d.function);
  for (const auto& n : model.neumann) addKnots(n.function);
  for (const auto& b : model.bodyForces) addKnots(b.function);

  std::set<std::string> seen;
  for (const auto& d : model.dirichlet)
    if (seen.insert(d.nodeSet).second) reactionSets_.push_back(d.nodeSet);
}

Simulation::~Simulation() = default;

void Simulation::setVerbosity(Verbosity verbosity) {
  verbosity_ = verbosity;
  solvers_->newton->setConsole(verbosity == Verbosity::Verbose ? console_ : nullptr);
}

void Simulation::checkOutputFolder() const {
  // Rank 0 writes the result: its view of the file system is the one that counts.
  std::string failure;
  if (comm_->getRank() == 0) {
    try {
      io::checkOutputFolder(ResultWriter::partialPath(settings_.outputFile));
    } catch (const Error& e) {
      failure = e.what();
    }
  }
  throwIfAnyRankFailed(*comm_, failure);
}

ProblemSize Simulation::problemSize() const {
  const auto& global = mesh_->global();
  ProblemSize size;
  size.dimension = global.dimension;
  size.nodes = global.numNodes();
  size.elements = global.numElements();
  size.dofs = static_cast<long long>(dofs_->ownedMap()->getGlobalNumElements());
  for (const auto& block : global.blocks) size.blocks.push_back(mesh::displayName(block.name, "block", block.id));
  size.numberOfSteps = settings_.numberOfSteps;
  size.finalTime = settings_.finalTime;
  size.meshFile = settings_.meshFile;
  size.outputFile = settings_.outputFile;
  for (std::size_t p = 0; contact_ && p < contact_->pairs().size(); ++p) {
    const auto& pair = *contact_->pairs()[p];
    const auto& s = pair.settings();
    PairDescription d;
    d.name = s.name;
    d.slave = s.slave;
    d.master = s.master;
    d.formulation = contact::toString(s.formulation);
    d.frictional = pair.frictional();
    std::ostringstream law;
    if (!d.frictional) law << "frictionless";
    else if (!s.frictionCoefficientField.empty()) law << "Coulomb friction, mu from the field '" << s.frictionCoefficientField << "'";
    else if (s.friction.type == contact::FrictionLawType::Coulomb) {
      law << "Coulomb friction mu = " << s.friction.coefficient;
      d.mu = s.friction.coefficient;
    } else law << contact::toString(s.friction.type) << " friction, threshold " << s.friction.threshold;
    d.law = law.str();
    d.slaveFaces = static_cast<long long>(pair.interface().slaveFaces().size());
    d.masterFaces = static_cast<long long>(pair.interface().masterFaces().size());
    d.slaveNodes = static_cast<long long>(pair.interface().slaveNodes().size());
    size.pairs.push_back(d);
  }
  return size;
}

std::vector<double> Simulation::reactionTotal(const std::string& nodeSet) const {
  const int dim = mesh_->dimension();
  const auto& set = mesh_->global().nodeSets[mesh_->nodeSetIndex(nodeSet, "reaction total")];
  std::vector<double> local(dim, 0.0), total(dim, 0.0);
  auto r = reactions_->getData(0);
  for (long long node : set.nodes) {
    const int i = mesh_->localNode(node);
    if (i < 0 || i >= mesh_->numOwnedNodes()) continue;
    for (int c = 0; c < dim; ++c) local[c] += r[i * dim + c];
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, dim, local.data(), total.data());
  return total;
}

void Simulation::writeStep(double time, const std::vector<double>& stepGlobals) {
  const int dim = mesh_->dimension();
  auto stress = Teuchos::rcp(new MultiVector(dofs_->ownedNodeMap(), 7));
  assembler_->nodalStress(*displacement_, *stress);
  std::vector<NodalField> fields;
  fields.push_back({componentNames("displacement", dim), byNode(*displacement_, *dofs_)});
  fields.push_back({componentNames("reaction", dim), byNode(*reactions_, *dofs_)});
  fields.push_back({{"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz", "von_mises"}, stress});
  if (contact_) {
    auto values = Teuchos::rcp(new MultiVector(dofs_->ownedNodeMap(), contact_->nodalFieldNames().size()));
    contact_->nodalFields(dofs_->ownedNodeMap(), *values);
    fields.push_back({contact_->nodalFieldNames(), values});
  }
  std::vector<double> globals = stepGlobals;
  for (const auto& set : reactionSets_)
    for (double value : reactionTotal(set)) globals.push_back(value);
  if (contact_)
    for (double value : contact_->globals()) globals.push_back(value);
  try {
    solvers_->writer->writeStep(time, fields, globals);
  } catch (const Error& e) {
    // Every rank has the same error (ResultWriter::writeStep agrees on it).
    std::ostringstream message;
    message << e.what() << "; the result file keeps the steps written before t = " << time << " as "
            << ResultWriter::partialPath(settings_.outputFile);
    throw Error(message.str());
  }
}

void Simulation::reportContact(RunSummary& summary, double time) {
  const int dim = mesh_->dimension();
  summary.pairMaximumActive.resize(contact_->pairs().size(), 0);
  summary.pairs.resize(contact_->pairs().size());
  for (std::size_t p = 0; p < contact_->pairs().size(); ++p) {
    const auto& pair = contact_->pairSummaries()[p];
    const auto active = static_cast<long long>(pair.activeSet.active);
    summary.pairMaximumActive[p] = std::max(summary.pairMaximumActive[p], active);
    // The summary's record: the peak over the owned slave nodes of all ranks.
    auto& record = summary.pairs[p];
    double peak = 0, globalPeak = 0;
    for (const auto& o : contact_->pairs()[p]->nodeOutput()) peak = std::max(peak, o.pressure);
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &peak, &globalPeak);
    if (globalPeak > record.peakPressure) {
      record.peakPressure = globalPeak;
      record.peakTime = time;
    }
    double normal2 = 0, tangential2 = 0;
    for (int c = 0; c < 3; ++c) {
      normal2 += pair.normalForce[c] * pair.normalForce[c];
      tangential2 += pair.tangentialForce[c] * pair.tangentialForce[c];
    }
    record.normalForce = std::sqrt(normal2);
    record.tangentialForce = std::sqrt(tangential2);
    record.active = active;
    record.stick = static_cast<long long>(pair.activeSet.stick);
    const auto notes = contact_->pairs()[p]->takeNotes();
    if (!console_) continue;
    for (const auto& note : notes) *console_ << "  note: " << note << "\n";
    if (verbosity_ == Verbosity::Quiet) continue;
    *console_ << "  contact '" << contact_->pairs()[p]->settings().name << "': " << active << " active nodes, force (";
    for (int c = 0; c < dim; ++c) *console_ << (c ? ", " : "") << std::setprecision(6) << pair.slaveForce[c];
    *console_ << ")\n" << std::defaultfloat;
  }
}

NewtonReport Simulation::solve(Vector& trial) {
  if (saddlePointState_.is_null()) return solvers_->newton->solve(trial);
  // Saddle-point form: x = (u, z), the multipliers starting from the last
  // converged step's; u is the leading part of the local data.
  Vector x(*saddlePointState_, Teuchos::Copy);
  contact::ContactModel::setDisplacementPart(trial, x);
  const NewtonReport report = solvers_->newton->solve(x);
  contact::ContactModel::displacementPart(x, trial);
  if (report.converged) saddlePointState_->assign(x);
  return report;
}

RunSummary Simulation::run() {
  const auto start = std::chrono::steady_clock::now();
  const int dim = mesh_->dimension();
  std::vector<std::string> nodalNames = componentNames("displacement", dim);
  for (const auto& n : componentNames("reaction", dim)) nodalNames.push_back(n);
  for (const char* n : {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz", "von_mises"})
    nodalNames.push_back(n);
  if (contact_)
    for (const auto& n : contact_->nodalFieldNames()) nodalNames.push_back(n);
  std::vector<std::string> globalNames = {"newton_iterations", "linear_iterations", "cutbacks"};
  for (const auto& set : reactionSets_)
    for (const auto& n : componentNames("reaction_" + set, dim)) globalNames.push_back(n);
  if (contact_)
    for (const auto& n : contact_->globalNames()) globalNames.push_back(n);
  solvers_->writer = std::make_unique<ResultWriter>(settings_.outputFile, *mesh_, dofs_->ownedNodeMap(), nodalNames,
                                                    globalNames);

  RunSummary summary;
  summary.dofs = static_cast<long long>(dofs_->ownedMap()->getGlobalNumElements());
  if (console_)
    *console_ << "coulomb: " << mesh_->global().numElements() << " elements, " << summary.dofs << " DoFs, "
              << comm_->getSize() << " rank(s); result " << settings_.outputFile << "\n";
  StepController::Settings stepping;
  stepping.finalTime = settings_.finalTime;
  stepping.numberOfSteps = settings_.numberOfSteps;
  stepping.maximumCutbacks = settings_.maximumCutbacks;
  // A sub-step that needed more than half the allowed iterations does not
  // count towards growing the size back (it would likely fail at twice it).
  stepping.easyIterations = std::max(1, settings_.newton.maximumIterations / 2);
  StepController steps(stepping, loadKnots_);
  const auto& constraints = assembler_->constraints();
  Vector trial(dofs_->ownedMap());
  // Linear extrapolation predictor: u_trial = u_n + (dt / dt_n) (u_n - u_n-1).
  // In contact it starts the step near the new contact zone, which saves
  // the semi-smooth iterations of nodes entering it.
  Vector lastIncrement(dofs_->ownedMap());
  double lastStep = 0.0;
  std::string rejected;  // since the last converged step: the last rejected iterate, or why Newton stopped
  // SIGINT/SIGTERM (core/Interrupt.hpp): asked before each step and after
  // each solve; the Newton iterations stop at the signal (NewtonSolver.cpp).
  auto stopIfInterrupted = [&](double time, double next) {
    const int signal = interruptSignalOnAnyRank(*comm_);
    if (signal == 0) return;
    solvers_->writer->abandon();
    std::ostringstream kept;
    if (summary.steps == 0) kept << "no step yet";
    else kept << "the " << summary.steps << " converged steps up to t = " << time;
    std::ostringstream message;
    message << "interrupted by " << signalName(signal) << " during the step to t = " << next
            << ": stopped; the result file keeps " << kept.str() << " as "
            << ResultWriter::partialPath(settings_.outputFile);
    throw Error(message.str());
  };
  const RunClock clock(steps.time(), settings_.finalTime);
  // "step n of N": the deck's step the (sub-)step leads to, N the deck's steps.
  auto progress = [&](double reached) {
    return formatDuration(clock.elapsedSeconds()) + " elapsed, " + clock.timeLeft(reached);
  };
  while (!steps.finished()) {
    const double time = steps.time(), next = steps.nextTime();
    stopIfInterrupted(time, next);
    const double nominalDt = settings_.finalTime / settings_.numberOfSteps;
    const int deckStep = steps.nominalStep();
    // Shorter than the deck's step: after a cutback, or before a load function's knot.
    const bool subStep = next - time < nominalDt * (1 - 1e-12);
    if (console_ && verbosity_ != Verbosity::Quiet)
      *console_ << "step " << deckStep << " of " << settings_.numberOfSteps << "  t = " << std::setprecision(6) << next
                << "  (" << (subStep ? "sub-step, " : "") << "dt = " << next - time << ")  " << progress(time) << "\n";
    const auto stepStart = std::chrono::steady_clock::now();
    // 'Boundary Increment' = Tangent (settings_.boundaryThroughTangent): the
    // prescribed DoFs keep the predictor's values, and the first Newton step
    // takes the rest of their increment through the tangent together with
    // the interior (fem/DirichletConstraints.hpp), as a linear solve would.
    // Imposed: the predictor carries ū, and the interior only follows from
    // the second iterate on; a boundary increment that is not proportional
    // to the last one (a rotation setting in) can invert the elements next
    // to the boundary before it does.
    auto attempt = [&](bool extrapolate) {
      trial.assign(*displacement_);
      if (extrapolate) trial.update((next - time) / lastStep, lastIncrement, 1.0);
      if (!settings_.boundaryThroughTangent) constraints.setPrescribedValues(next, trial);
      solvers_->model->setTime(next);
      if (contact_) contact_->beginStep(steps.nominalStep());
      return solve(trial);
    };
    const bool extrapolate = settings_.extrapolate && lastStep > 0;
    NewtonReport report = attempt(extrapolate);
    if (extrapolate && report.rejectedStart()) {
      // The extrapolated state could not be evaluated (it may fold a
      // contact face or invert an element): start from the last converged
      // state instead, before cutting the step.
      if (console_)
        *console_ << "  the extrapolated predictor was rejected (" << report.failure
                  << "): starting the step from the last converged state\n";
      if (contact_) contact_->restoreStep();
      report = attempt(false);
    }
    stopIfInterrupted(time, next);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count();
    const int iterations = static_cast<int>(report.iterations.size()) - 1;
    if (!report.converged) {
      ++summary.cutbacks;
      if (!report.failure.empty()) rejected = "an iterate was rejected: " + report.failure;
      else if (!report.stopReason.empty()) rejected = report.stopReason;
      if (console_) {
        *console_ << "  not converged after " << iterations << " iterations";
        if (!report.failure.empty()) *console_ << ": an iterate was rejected (" << report.failure << ")";
        else if (!report.stopReason.empty()) *console_ << ": " << report.stopReason;
        *console_ << "\n";
      }
      COULOMB_REQUIRE(steps.reject(),
                      "Newton did not converge at t = " << next << " (deck step " << steps.nominalStep() << " of "
                          << settings_.numberOfSteps << ") with dt = " << next - time
                          << (steps.consecutiveCutbacks() >= settings_.maximumCutbacks
                                  ? " after " + std::to_string(steps.consecutiveCutbacks()) + " cutbacks in a row"
                                  : std::string(", the smallest step (Final Time / Number of Steps / 2^cutbacks)"))
                          << " ('Load Stepping/Maximum Cutbacks' = " << settings_.maximumCutbacks << ")"
                          << (rejected.empty() ? std::string() : "; " + rejected)
                          << "; the result file keeps "
                          << (summary.steps == 0 ? std::string("no converged step")
                                                 : "the converged steps up to t = " + formatTime(time))
                          << " as " << ResultWriter::partialPath(settings_.outputFile));
      if (console_) *console_ << "  cutting the step: next dt = " << steps.nextTime() - time << "\n";
      if (contact_) contact_->restoreStep();
      continue;
    }
    if (contact_) contact_->checkContact(next);
    steps.accept(iterations);
    rejected.clear();
    lastIncrement.update(1.0, trial, -1.0, *displacement_, 0.0);
    lastStep = next - time;
    displacement_->assign(trial);
    assembler_->assemble(next, *displacement_, nullptr, nullptr, reactions_.get());
    // A contact force on a prescribed DoF never enters the equations: the
    // support carries it (reaction = f_int - f_ext - f_c there).
    if (contact_) contact_->subtractPrescribedForces(*reactions_);
    ++summary.steps;
    summary.newtonIterations += iterations;
    summary.linearIterations += report.linearIterations();
    summary.stepTimes.push_back(next);
    summary.stepNewtonIterations.push_back(iterations);
    std::vector<double> norms;
    for (const auto& row : report.iterations) norms.push_back(row.residualNorm);
    summary.stepResidualNorms.push_back(norms);
    std::vector<long long> active, changed, stickSlip;
    std::vector<int> kept, coarseKept;
    for (const auto& row : report.iterations) {
      active.push_back(row.activeNodes);
      changed.push_back(row.changedNodes);
      stickSlip.push_back(row.stickSlipChanged);
      kept.push_back(row.preconditionerReused ? 1 : 0);
      coarseKept.push_back(row.coarseLevelKept ? 1 : 0);
    }
    summary.stepActiveNodes.push_back(active);
    summary.stepChangedNodes.push_back(changed);
    summary.stepStickSlipChanged.push_back(stickSlip);
    summary.stepPreconditionerKept.push_back(kept);
    summary.stepCoarseLevelKept.push_back(coarseKept);
    writeStep(next, {double(iterations), double(report.linearIterations()), double(summary.cutbacks)});
    if (console_ && verbosity_ == Verbosity::Quiet)
      *console_ << "step " << deckStep << " of " << settings_.numberOfSteps
                << "  t = " << std::setprecision(6) << next << "  " << iterations << " Newton / "
                << report.linearIterations() << " linear  " << progress(next) << "\n";
    else if (console_)
      *console_ << "  step " << summary.steps << " converged: t = " << next << ", " << iterations << " Newton / "
                << report.linearIterations() << " linear iterations, |f| = " << std::scientific << std::setprecision(2)
                << report.iterations.back().residualNorm << std::defaultfloat << ", " << std::fixed
                << std::setprecision(2) << seconds << " s" << std::defaultfloat
                << (report.preconditionerReuses() > 0
                        ? ", preconditioner kept in " + std::to_string(report.preconditionerReuses()) + " solves"
                        : std::string())
                << (report.coarseLevelReuses() > 0
                        ? ", corner level kept in " + std::to_string(report.coarseLevelReuses()) + " solves"
                        : std::string())
                << "\n";
    if (contact_) reportContact(summary, next);
  }
  solvers_->writer->finish();
  if (contact_ && console_)
    for (std::size_t p = 0; p < contact_->pairs().size(); ++p)
      if (summary.pairMaximumActive.size() > p && summary.pairMaximumActive[p] == 0)
        *console_ << "coulomb: note: contact pair '" << contact_->pairs()[p]->settings().name
                  << "' had no active node in any step: do its surfaces meet? (check 'Slave', 'Master' and "
                     "'Search Radius Factor')\n";
  summary.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (settings_.printTimers) Teuchos::TimeMonitor::summarize(comm_.ptr(), console_ ? *console_ : std::cout);
  if (console_)
    *console_ << "coulomb: " << summary.steps << " steps, " << summary.newtonIterations << " Newton and "
              << summary.linearIterations << " linear iterations, " << summary.cutbacks << " cutbacks, "
              << std::fixed << std::setprecision(2) << summary.wallSeconds << " s" << std::defaultfloat << "\n";
  if (console_)
    printRunSummary(*console_, problemSize(), summary.pairs, summary.steps, summary.cutbacks, steps.time(),
                    summary.wallSeconds);
  return summary;
}

}  // namespace coulomb::solver
