#include "coulomb/solver/GatheredDirectSolver.hpp"

#include <mpi.h>

#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_LinearOpSourceBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <Trilinos_version.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/TpetraTypes.hpp"

namespace coulomb::solver {

namespace {

using Extract = Thyra::TpetraOperatorVectorExtraction<Scalar, LocalOrdinal, GlobalOrdinal>;
using DirectSolver = Amesos2::Solver<CrsMatrix, MultiVector>;
using LocalGraph = CrsGraph::local_graph_device_type;
using RowPointers = LocalGraph::row_map_type::non_const_type;
using ColumnIndices = LocalGraph::entries_type::non_const_type;
using Values = CrsMatrix::local_matrix_device_type::values_type;
using Clock = std::chrono::steady_clock;

constexpr const char* kSolverType = "Solver Type";
constexpr const char* kTolerance = "Relative Residual Tolerance";
constexpr const char* kRefinement = "Maximum Refinement Steps";
constexpr const char* kSettings = "Amesos2 Settings";

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

Teuchos::Time& counter(const char* what) {
  // Created on first use, on every rank (the calls below are collective), so
  // Teuchos::TimeMonitor::summarize sees them everywhere.
  return *Teuchos::TimeMonitor::getNewCounter(std::string("Coulomb: gathered direct solve: ") + what);
}

/// The Tpetra::CrsMatrix behind a Thyra operator, or null.
Teuchos::RCP<const CrsMatrix> crsMatrixOf(const Teuchos::RCP<const Thyra::LinearOpBase<double>>& op) {
  if (op.is_null()) return Teuchos::null;
  try {
    return Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(op));
  } catch (const std::exception&) {
    return Teuchos::null;
  }
}

/// Collective: if rank 0's `message` is not empty, every rank throws it.
/// Work done on rank 0 only must report its failure this way, or the other
/// ranks would wait for it forever.
void throwIfRootFailed(const Teuchos::Comm<int>& comm, std::string message) {
  int length = comm.getRank() == 0 ? static_cast<int>(message.size()) : 0;
  Teuchos::broadcast(comm, 0, &length);
  if (length == 0) return;
  message.resize(static_cast<std::size_t>(length));
  Teuchos::broadcast(comm, 0, length, &message[0]);
  throw Error(message);
}

/// A barrier at which ranks sleep instead of spinning: while rank 0 factors
/// alone, the others would otherwise poll MPI at full speed and take CPU
/// from it whenever ranks share cores (measured: np = 2 on two loaded
/// cores doubled rank 0's factorisation time).
void sleepingBarrier(const Teuchos::Comm<int>& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  if (mpi == nullptr || comm.getSize() == 1) return;
  MPI_Request request;
  MPI_Ibarrier((*mpi->getRawMpiComm())(), &request);
  auto pause = std::chrono::microseconds(20);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(pause);
    pause = std::min(2 * pause, std::chrono::microseconds(2000));
  }
}

/// The global indices of `map`, gathered to rank 0 and sorted (empty elsewhere).
std::vector<GlobalOrdinal> sortedIndicesOnRoot(const Map& map) {
  const auto& comm = *map.getComm();
  const auto mine = map.getNodeElementList();
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(comm.getSize()));
  Teuchos::gatherAll(comm, 1, &count, comm.getSize(), counts.data());
  std::vector<int> offsets(counts.size(), 0);
  for (std::size_t p = 1; p < counts.size(); ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<GlobalOrdinal> all(comm.getRank() == 0 ? static_cast<std::size_t>(offsets.back() + counts.back()) : 0);
  Teuchos::gatherv<int, GlobalOrdinal>(mine.getRawPtr(), count, all.data(), counts.data(), offsets.data(), 0, comm);
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

// ---------------------------------------------------------------------------
// GatheredDirectSolver

struct GatheredDirectSolver::Impl {
  GatheredDirectSettings settings;
  Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> source;
  Teuchos::RCP<const Thyra::LinearOpBase<double>> op;
  Teuchos::RCP<const CrsMatrix> matrix;  ///< the distributed forward operator

  // Gather plan, kept while the matrix's maps stay the same.
  Teuchos::RCP<const Map> rowMap, rangeMap, domainMap;
  Teuchos::RCP<const Map> gatheredMap;  ///< every index on rank 0, sorted: local index = new number
  Teuchos::RCP<const Export> rowExport, rangeExport;
  Teuchos::RCP<const Import> domainImport;

  // Rank 0 only: the renumbered matrix on a one-process communicator.
  Teuchos::RCP<const Teuchos::Comm<int>> selfComm;
  Teuchos::RCP<const Map> serialMap;  ///< contiguous 0..n-1
  Teuchos::RCP<const CrsGraph> serialGraph;
  RowPointers rowPointers;  ///< the pattern serialGraph was made from
  ColumnIndices columnIndices;
  Teuchos::RCP<DirectSolver> direct;
  std::string directType;

  GatheredDirectStatistics statistics;

  bool isRoot() const { return matrix->getComm()->getRank() == 0; }
  void planGather();
  /// Rank 0: renumbers `gathered`, factors it (numeric only if the pattern
  /// is unchanged). Returns {symbolic seconds or -1 if reused, numeric seconds}.
  std::pair<double, double> factorOnRoot(const CrsMatrix& gathered);
  /// Collective: x = A^{-1} b through rank 0 (b in the range map, x in the domain map).
  void solveOnRoot(const MultiVector& b, MultiVector& x) const;
};

void GatheredDirectSolver::Impl::planGather() {
  const auto comm = matrix->getComm();
  rowMap = matrix->getRowMap();
  rangeMap = matrix->getRangeMap();
  domainMap = matrix->getDomainMap();
  const auto indices = sortedIndicesOnRoot(*rangeMap);
  std::string problem;
  if (std::adjacent_find(indices.begin(), indices.end()) != indices.end())
    problem = "direct solver: the matrix's range map is not one-to-one";
  if (!domainMap->isSameAs(*rangeMap) && sortedIndicesOnRoot(*domainMap) != indices && problem.empty())
    problem = "direct solver: the matrix is not square (domain and range maps hold different global indices)";
  throwIfRootFailed(*comm, problem);

  gatheredMap = Teuchos::rcp(new Map(rangeMap->getGlobalNumElements(),
                                     Teuchos::ArrayView<const GlobalOrdinal>(indices.data(), indices.size()),
                                     rangeMap->getIndexBase(), comm));
  // Export (not Import) for the matrix: a row owned by several ranks is summed, as in apply().
  rowExport = Teuchos::rcp(new Export(rowMap, gatheredMap));
  rangeExport = rangeMap->isSameAs(*rowMap) ? rowExport : Teuchos::rcp<const Export>(new Export(rangeMap, gatheredMap));
  domainImport = Teuchos::rcp(new Import(gatheredMap, domainMap));
  // New numbering: nothing on rank 0 can be reused.
  serialGraph = Teuchos::null;
  direct = Teuchos::null;
}

std::pair<double, double> GatheredDirectSolver::Impl::factorOnRoot(const CrsMatrix& gathered) {
  // Renumber: rows are already in sorted global order (the gathered map's
  // local order); columns get the position of their global index in it.
  const auto local = gathered.getLocalMatrixHost();
  const auto n = static_cast<LocalOrdinal>(gathered.getNodeNumRows());
  const auto& columnMap = *gathered.getColMap();
  std::vector<LocalOrdinal> newColumn(columnMap.getNodeNumElements());
  for (std::size_t j = 0; j < newColumn.size(); ++j) {
    newColumn[j] = gatheredMap->getLocalElement(columnMap.getGlobalElement(static_cast<LocalOrdinal>(j)));
    COULOMB_REQUIRE(newColumn[j] != Teuchos::OrdinalTraits<LocalOrdinal>::invalid(),
                    "direct solver: column " << columnMap.getGlobalElement(static_cast<LocalOrdinal>(j))
                                             << " is not an index of the domain map");
  }
  const std::size_t nnz = local.values.extent(0);
  RowPointers rows("gathered row pointers", static_cast<std::size_t>(n) + 1);
  ColumnIndices columns("gathered column indices", nnz);
  Values values("gathered values", nnz);
  std::vector<std::pair<LocalOrdinal, double>> row;
  std::size_t k = 0;
  for (LocalOrdinal i = 0; i < n; ++i) {
    row.clear();
    for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e)
      row.emplace_back(newColumn[local.graph.entries(e)], local.values(e));
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [column, value] : row) {
      columns(k) = column;
      values(k++) = value;
    }
    rows(i + 1) = k;
  }

  bool samePattern = !direct.is_null() && !serialGraph.is_null() && directType == settings.solverType &&
                     rowPointers.extent(0) == rows.extent(0) && columnIndices.extent(0) == columns.extent(0);
  for (std::size_t i = 0; samePattern && i < rows.extent(0); ++i) samePattern = rowPointers(i) == rows(i);
  for (std::size_t e = 0; samePattern && e < nnz; ++e) samePattern = columnIndices(e) == columns(e);

  if (!samePattern) {
    if (selfComm.is_null()) selfComm = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    if (serialMap.is_null() || serialMap->getGlobalNumElements() != static_cast<Tpetra::global_size_t>(n))
      serialMap = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, selfComm));
    auto graph = Teuchos::rcp(new CrsGraph(serialMap, serialMap, rows, columns));
    graph->fillComplete(serialMap, serialMap);
    serialGraph = graph;
    rowPointers = rows;
    columnIndices = columns;
  }
  auto serialMatrix = Teuchos::rcp(new CrsMatrix(serialGraph, values));
  serialMatrix->fillComplete(serialMap, serialMap);

  double symbolic = -1;
  if (!samePattern) {
    direct = Teuchos::null;
    directType.clear();
    direct = Amesos2::create<CrsMatrix, MultiVector>(settings.solverType, serialMatrix);
    if (!settings.amesos2Settings.is_null() && settings.amesos2Settings->numParams() > 0) {
      auto p = Teuchos::rcp(new Teuchos::ParameterList(*settings.amesos2Settings));
      p->setName("Amesos2");
      direct->setParameters(p);
    }
    Teuchos::TimeMonitor scope(counter("symbolic factorisation (rank 0)"));
    const auto start = Clock::now();
    direct->symbolicFactorization();
    symbolic = secondsSince(start);
    directType = settings.solverType;
  } else {
    // Same pattern: keep the symbolic factorisation (ordering), refactor.
    direct->setA(serialMatrix, Amesos2::SYMBFACT);
  }
  Teuchos::TimeMonitor scope(counter("numeric factorisation (rank 0)"));
  const auto start = Clock::now();
  direct->numericFactorization();
  return {symbolic, secondsSince(start)};
}

void GatheredDirectSolver::Impl::solveOnRoot(const MultiVector& b, MultiVector& x) const {
  const std::size_t k = b.getNumVectors();
  MultiVector gatheredB(gatheredMap, k), gatheredX(gatheredMap, k);
  gatheredB.doExport(b, *rangeExport, Tpetra::REPLACE);
  std::string problem;
  if (isRoot()) {
    try {
      Teuchos::TimeMonitor scope(counter("triangular solves (rank 0)"));
      MultiVector serialB(serialMap, k), serialX(serialMap, k);
      {
        auto from = gatheredB.getLocalViewHost(Tpetra::Access::ReadOnly);
        auto to = serialB.getLocalViewHost(Tpetra::Access::OverwriteAll);
        Kokkos::deep_copy(to, from);
      }
      direct->solve(Teuchos::ptrFromRef(serialX), Teuchos::ptrFromRef(static_cast<const MultiVector&>(serialB)));
      auto from = serialX.getLocalViewHost(Tpetra::Access::ReadOnly);
      auto to = gatheredX.getLocalViewHost(Tpetra::Access::OverwriteAll);
      Kokkos::deep_copy(to, from);
    } catch (const std::exception& e) {
      problem = std::string("direct solver: Amesos2 '") + directType + "' solve on rank 0 failed: " + e.what();
    }
  }
  throwIfRootFailed(*matrix->getComm(), problem);
  x.doImport(gatheredX, *domainImport, Tpetra::REPLACE);
}

GatheredDirectSolver::GatheredDirectSolver() : impl_(std::make_unique<Impl>()) {}
GatheredDirectSolver::~GatheredDirectSolver() = default;

void GatheredDirectSolver::initialize(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
                                      const GatheredDirectSettings& settings) {
  TEUCHOS_TEST_FOR_EXCEPTION(source.is_null() || source->getOp().is_null(), std::invalid_argument,
                             "GatheredDirectSolver::initialize: no forward operator");
  const auto matrix = crsMatrixOf(source->getOp());
  TEUCHOS_TEST_FOR_EXCEPTION(matrix.is_null(), std::invalid_argument,
                             "GatheredDirectSolver: the forward operator is not a Tpetra::CrsMatrix<double, int, "
                             "long long> (through Thyra::TpetraLinearOp)");
  TEUCHOS_TEST_FOR_EXCEPTION(!matrix->isFillComplete(), std::invalid_argument,
                             "GatheredDirectSolver: the matrix is not fill complete");
  auto& s = *impl_;
  s.settings = settings;
  s.source = source;
  s.op = source->getOp();
  s.matrix = matrix;
  const bool samePlan = !s.rowMap.is_null() && s.rowMap->isSameAs(*matrix->getRowMap()) &&
                        s.rangeMap->isSameAs(*matrix->getRangeMap()) && s.domainMap->isSameAs(*matrix->getDomainMap());
  if (!samePlan) s.planGather();

  const auto comm = matrix->getComm();
  auto& gatherCounter = counter("gather matrix");
  counter("symbolic factorisation (rank 0)");
  counter("numeric factorisation (rank 0)");
  counter("triangular solves (rank 0)");
  Teuchos::RCP<CrsMatrix> gathered;
  const auto start = Clock::now();
  {
    Teuchos::TimeMonitor scope(gatherCounter);
    gathered = Tpetra::exportAndFillCompleteCrsMatrix<CrsMatrix>(matrix, *s.rowExport, s.gatheredMap, s.gatheredMap);
  }
  double times[3] = {secondsSince(start), -1, 0};  // gather, symbolic (-1: reused), numeric
  std::string problem;
  if (s.isRoot()) {
    try {
      const auto [symbolic, numeric] = s.factorOnRoot(*gathered);
      times[1] = symbolic;
      times[2] = numeric;
    } catch (const std::exception& e) {
      s.direct = Teuchos::null;
      s.serialGraph = Teuchos::null;
      std::string what = e.what();
      for (auto& c : what)
        if (c == '\n') c = ' ';
      problem = "direct solver: Amesos2 '" + s.settings.solverType + "' factorisation of the " +
                std::to_string(matrix->getGlobalNumRows()) + "-row matrix on rank 0 failed (singular matrix? " +
                "is the body held against rigid motion?): " + what.substr(0, 300);
    }
  }
  sleepingBarrier(*comm);
  throwIfRootFailed(*comm, problem);
  gathered = Teuchos::null;
  Teuchos::broadcast(*comm, 0, 3, times);
  auto& st = s.statistics;
  ++st.initializations;
  st.lastGatherSeconds = times[0];
  st.lastSymbolicSeconds = std::max(times[1], 0.0);
  st.lastNumericSeconds = times[2];
  if (times[1] >= 0) ++st.symbolicFactorizations;
  ++st.numericFactorizations;
}

Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> GatheredDirectSolver::uninitialize() {
  auto source = impl_->source;
  impl_->source = Teuchos::null;
  impl_->op = Teuchos::null;
  impl_->matrix = Teuchos::null;
  return source;
}

Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> GatheredDirectSolver::source() const { return impl_->source; }
const GatheredDirectStatistics& GatheredDirectSolver::statistics() const { return impl_->statistics; }

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> GatheredDirectSolver::range() const {
  return impl_->op.is_null() ? Teuchos::null : impl_->op->range();
}
Teuchos::RCP<const Thyra::VectorSpaceBase<double>> GatheredDirectSolver::domain() const {
  return impl_->op.is_null() ? Teuchos::null : impl_->op->domain();
}

std::string GatheredDirectSolver::description() const {
  std::ostringstream out;
  out << "coulomb::solver::GatheredDirectSolver{Amesos2 " << impl_->settings.solverType << " on rank 0";
  if (!impl_->matrix.is_null()) out << ", " << impl_->matrix->getGlobalNumRows() << " rows";
  out << "}";
  return out.str();
}

bool GatheredDirectSolver::opSupportedImpl(Thyra::EOpTransp transp) const {
  return !impl_->op.is_null() && Thyra::opSupported(*impl_->op, transp);
}

void GatheredDirectSolver::applyImpl(Thyra::EOpTransp transp, const Thyra::MultiVectorBase<double>& X,
                                     const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& Y, double alpha,
                                     double beta) const {
  Thyra::apply(*impl_->op, transp, X, Y, alpha, beta);
}

bool GatheredDirectSolver::solveSupportsImpl(Thyra::EOpTransp transp) const { return transp == Thyra::NOTRANS; }

bool GatheredDirectSolver::solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp transp,
                                                             const Thyra::SolveMeasureType& measure) const {
  if (transp != Thyra::NOTRANS) return false;
  if (measure.useDefault()) return true;
  return measure.numerator == Thyra::SOLVE_MEASURE_NORM_RESIDUAL &&
         (measure.denominator == Thyra::SOLVE_MEASURE_NORM_RHS ||
          measure.denominator == Thyra::SOLVE_MEASURE_NORM_INIT_RESIDUAL ||
          measure.denominator == Thyra::SOLVE_MEASURE_ONE);
}

Thyra::SolveStatus<double> GatheredDirectSolver::solveImpl(
    Thyra::EOpTransp transp, const Thyra::MultiVectorBase<double>& B,
    const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& X,
    const Teuchos::Ptr<const Thyra::SolveCriteria<double>> criteria) const {
  TEUCHOS_TEST_FOR_EXCEPTION(transp != Thyra::NOTRANS, std::invalid_argument,
                             "GatheredDirectSolver: only NOTRANS solves are supported");
  const auto& s = *impl_;
  TEUCHOS_TEST_FOR_EXCEPTION(s.matrix.is_null(), std::logic_error, "GatheredDirectSolver: solve before initialize");
  const auto start = Clock::now();
  const auto b = Extract::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
  const auto x = Extract::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
  const std::size_t k = b->getNumVectors();

  // What "converged" means: the caller's criteria if given, else ours;
  // always measured as the true residual with the distributed matrix.
  Thyra::SolveMeasureType measure;
  double tolerance = s.settings.relativeResidualTolerance;
  if (!criteria.is_null() && !criteria->solveMeasureType.useDefault() &&
      criteria->requestedTol != Thyra::SolveCriteria<double>::unspecifiedTolerance()) {
    measure = criteria->solveMeasureType;
    tolerance = criteria->requestedTol;
  }
  MultiVector r(b->getMap(), k);
  std::vector<double> scale(k, 1.0), norms(k, 0.0);
  auto computeResidual = [&] {
    s.matrix->apply(*x, r);
    r.update(1.0, *b, -1.0);
    r.norm2(Teuchos::arrayViewFromVector(norms));
  };
  if (measure.denominator == Thyra::SOLVE_MEASURE_NORM_INIT_RESIDUAL) {
    computeResidual();
    scale = norms;
  } else if (measure.useDefault() || measure.denominator != Thyra::SOLVE_MEASURE_ONE) {
    b->norm2(Teuchos::arrayViewFromVector(scale));
  }
  for (auto& v : scale)
    if (!(v > 0)) v = 1.0;  // b = 0: x = 0, and the residual is measured absolutely

  auto worst = [&] {
    double w = 0;
    for (std::size_t j = 0; j < k; ++j) {
      if (std::isnan(norms[j])) return norms[j];
      w = std::max(w, norms[j] / scale[j]);
    }
    return w;
  };
  s.solveOnRoot(*b, *x);
  computeResidual();
  double achieved = worst();
  int steps = 0;
  while (!(achieved <= tolerance) && steps < s.settings.maximumRefinementSteps && !std::isnan(achieved)) {
    MultiVector correction(x->getMap(), k);
    s.solveOnRoot(r, correction);
    x->update(1.0, correction, 1.0);
    computeResidual();
    achieved = worst();
    ++steps;
  }

  auto& st = impl_->statistics;
  ++st.solves;
  st.refinementSteps += steps;
  st.lastRelativeResidual = achieved;
  st.lastSolveSeconds = secondsSince(start);

  Thyra::SolveStatus<double> status;
  status.solveStatus = achieved <= tolerance ? Thyra::SOLVE_STATUS_CONVERGED : Thyra::SOLVE_STATUS_UNCONVERGED;
  status.achievedTol = achieved;
  std::ostringstream message;
  message << "Amesos2 " << s.directType << " on rank 0: relative residual " << achieved << " (tolerance "
          << tolerance << ", " << steps << " refinement steps)";
  status.message = message.str();
  status.extraParameters = Teuchos::rcp(new Teuchos::ParameterList("Gathered direct solve"));
  status.extraParameters->set("Iteration Count", 1 + steps);
  status.extraParameters->set("Refinement Steps", steps);
  return status;
}

// ---------------------------------------------------------------------------
// GatheredDirectSolverFactory

bool GatheredDirectSolverFactory::isCompatible(const Thyra::LinearOpSourceBase<double>& source) const {
  return !crsMatrixOf(source.getOp()).is_null();
}

Teuchos::RCP<Thyra::LinearOpWithSolveBase<double>> GatheredDirectSolverFactory::createOp() const {
  return Teuchos::rcp(new GatheredDirectSolver());
}

void GatheredDirectSolverFactory::initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
                                               Thyra::LinearOpWithSolveBase<double>* op,
                                               Thyra::ESupportSolveUse /*use*/) const {
  TEUCHOS_TEST_FOR_EXCEPTION(op == nullptr, std::invalid_argument, "GatheredDirectSolverFactory: null op");
  Teuchos::dyn_cast<GatheredDirectSolver>(*op).initialize(source, settings_);
}

void GatheredDirectSolverFactory::uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                                                 Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* source,
                                                 Teuchos::RCP<const Thyra::PreconditionerBase<double>>* prec,
                                                 Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* approxSource,
                                                 Thyra::ESupportSolveUse* /*use*/) const {
  TEUCHOS_TEST_FOR_EXCEPTION(op == nullptr, std::invalid_argument, "GatheredDirectSolverFactory: null op");
  auto old = Teuchos::dyn_cast<GatheredDirectSolver>(*op).uninitialize();
  if (source) *source = old;
  if (prec) *prec = Teuchos::null;
  if (approxSource) *approxSource = Teuchos::null;
}

bool GatheredDirectSolverFactory::supportsPreconditionerInputType(Thyra::EPreconditionerInputType) const {
  return false;
}

void GatheredDirectSolverFactory::initializePreconditionedOp(
    const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
    const Teuchos::RCP<const Thyra::PreconditionerBase<double>>& /*prec*/, Thyra::LinearOpWithSolveBase<double>* op,
    Thyra::ESupportSolveUse use) const {
  initializeOp(source, op, use);
}

void GatheredDirectSolverFactory::initializeApproxPreconditionedOp(
    const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& source,
    const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& /*approxSource*/,
    Thyra::LinearOpWithSolveBase<double>* op, Thyra::ESupportSolveUse use) const {
  initializeOp(source, op, use);
}

void GatheredDirectSolverFactory::setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& list) {
  TEUCHOS_TEST_FOR_EXCEPTION(list.is_null(), std::invalid_argument, "GatheredDirectSolverFactory: null list");
  list->validateParametersAndSetDefaults(*getValidParameters());
  GatheredDirectSettings settings;
  settings.solverType = list->get<std::string>(kSolverType);
  TEUCHOS_TEST_FOR_EXCEPTION(!Amesos2::query(settings.solverType), std::invalid_argument,
                             "'" << list->name() << "/" << kSolverType << "' = '" << settings.solverType
                                 << "' is not an Amesos2 solver of this Trilinos (Debian's 13.2 has KLU2 and Tacho)");
#if TRILINOS_MAJOR_MINOR_VERSION < 140000
  // Measured: Tacho's numeric factorisation segfaults even on one process
  // (a 20^3 7-point Laplacian through plain Amesos2), killing the run
  // without a message. Refuse it instead.
  std::string upper = settings.solverType;
  for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  TEUCHOS_TEST_FOR_EXCEPTION(upper == "TACHO", std::invalid_argument,
                             "'" << list->name() << "/" << kSolverType
                                 << "' = 'Tacho' crashes in Trilinos 13.2 (segmentation fault in its numeric "
                                    "factorisation); use KLU2");
#endif
  settings.relativeResidualTolerance = list->get<double>(kTolerance);
  TEUCHOS_TEST_FOR_EXCEPTION(!(settings.relativeResidualTolerance > 0), std::invalid_argument,
                             "'" << list->name() << "/" << kTolerance << "' must be > 0");
  settings.maximumRefinementSteps = list->get<int>(kRefinement);
  TEUCHOS_TEST_FOR_EXCEPTION(settings.maximumRefinementSteps < 0, std::invalid_argument,
                             "'" << list->name() << "/" << kRefinement << "' must be >= 0");
  settings.amesos2Settings = Teuchos::rcp(new Teuchos::ParameterList(list->sublist(kSettings)));
  settings_ = settings;
  list_ = list;
}

Teuchos::RCP<Teuchos::ParameterList> GatheredDirectSolverFactory::getNonconstParameterList() { return list_; }

Teuchos::RCP<Teuchos::ParameterList> GatheredDirectSolverFactory::unsetParameterList() {
  auto old = list_;
  list_ = Teuchos::null;
  return old;
}

Teuchos::RCP<const Teuchos::ParameterList> GatheredDirectSolverFactory::getParameterList() const { return list_; }

Teuchos::RCP<const Teuchos::ParameterList> GatheredDirectSolverFactory::getValidParameters() const {
  static const Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto p = Teuchos::rcp(new Teuchos::ParameterList("Amesos2"));
    p->set<std::string>(kSolverType, "KLU2",
                        "Amesos2 solver run on rank 0 on the gathered, contiguously renumbered matrix "
                        "(a name Amesos2::query() accepts)");
    p->set<double>(kTolerance, 1e-9,
                   "A solve converges when ||b - A x|| / ||b|| (true residual) is at most this, unless the caller "
                   "passes its own solve criteria");
    p->set<int>(kRefinement, 2, "Iterative refinement steps tried while the residual is above the tolerance");
    p->sublist(kSettings, false, "Handed to the Amesos2 solver's setParameters() as its \"Amesos2\" list")
        .disableRecursiveValidation();
    return p;
  }();
  return valid;
}

std::string GatheredDirectSolverFactory::description() const {
  return "coulomb::solver::GatheredDirectSolverFactory{Amesos2 " + settings_.solverType + " on rank 0}";
}

}  // namespace coulomb::solver
