#include "coulomb/contact/ContactModel.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/PairChaining.hpp"
#include "coulomb/contact/PairMerging.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::contact {

namespace {
const char* const kComponents[] = {"x", "y", "z"};
}

ContactModel::ContactModel(const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedDofMap,
                           const ContactSettings& settings, const fem::ModelSettings& model)
    : settings_(settings), dim_(mesh.dimension()), map_(ownedDofMap) {
  // Pairs sharing slave nodes become one pair (PairMerging.hpp).
  for (const auto& pair : mergePairsSharingSlaveNodes(mesh, settings.pairs))
    pairs_.push_back(std::make_unique<ContactPair>(mesh, ownedDofMap, pair, model, settings.systemForm));
  for (const auto& pair : pairs_) transformedSlaves_ = transformedSlaves_ || pair->transformedSlaves();
  pairSummaries_.resize(pairs_.size());
  if (!saddlePoint()) {
    chaining_ = std::make_unique<PairChaining>(pairs_);
    return;
  }
  // The multiplier block: dim unknowns per slave node of each pair, numbered
  // after the displacements, owned by the slave node's owner.
  const auto owned = ownedDofMap->getNodeElementList();
  std::vector<GlobalOrdinal> gids(owned.begin(), owned.end());
  GlobalOrdinal next = static_cast<GlobalOrdinal>(dim_) * mesh.global().numNodes();
  for (auto& pair : pairs_) {
    pair->setMultiplierOffset(next);
    for (int s : pair->interface().ownedSlaveNodes())
      for (int c = 0; c < dim_; ++c) gids.push_back(pair->multiplierDof(s, c));
    next += static_cast<GlobalOrdinal>(dim_ * pair->interface().slaveNodes().size());
  }
  saddlePointMap_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                         Teuchos::ArrayView<const GlobalOrdinal>(gids), 0, ownedDofMap->getComm()));
}

ContactModel::~ContactModel() = default;

bool ContactModel::anyFrictional() const {
  for (const auto& pair : pairs_)
    if (pair->frictional()) return true;
  return false;
}

bool ContactModel::needsNonsymmetricSolver() const {
  // ALM and MPC: the condensed rows; penalty friction: the slip branch's tangent.
  for (const auto& pair : pairs_)
    if (pair->settings().formulation != ContactFormulation::Penalty || pair->frictional()) return true;
  return false;
}

void ContactModel::beginStep(int deckStep) {
  updatesInStep_ = 0;
  cycle_.clear();
  for (auto& pair : pairs_) pair->beginStep(deckStep);
}

void ContactModel::checkContact(double time) const {
  // The summaries are sums over the ranks: every rank takes the same branch.
  for (std::size_t p = 0; p < pairs_.size(); ++p)
    COULOMB_REQUIRE(!pairs_[p]->settings().ensureContact || pairSummaries_[p].activeSet.active > 0,
                    "Contact/Pairs/" << pairs_[p]->settings().name << ": 'Ensure Contact' is set but the step to t = "
                                     << time << " converged with no slave node in contact");
}

void ContactModel::restoreStep() {
  updatesInStep_ = 0;
  cycle_.clear();
  for (auto& pair : pairs_) pair->restoreStep();
}

template <class UpdatePair>
void ContactModel::updatePairs(bool freezeSet, UpdatePair&& updatePair) {
  clear(contributions_);
  summary_ = ContactIterationSummary();
  PairIterationSummary total;
  std::vector<std::size_t> order(pairs_.size());
  std::iota(order.begin(), order.end(), 0);
  for (std::size_t p : chaining_ ? chaining_->order() : order) {
    // Simplified semi-smooth Newton: the set moves at the predictor and the first iterate only.
    const bool updateSet =
        !freezeSet && (pairs_[p]->settings().semiSmooth == SemiSmoothNewton::Full || updatesInStep_ < 2);
    pairSummaries_[p] = updatePair(p, updateSet);
    total += pairSummaries_[p];
    summary_.frictional = summary_.frictional || pairs_[p]->frictional();
  }
  summary_.activeSet = total.activeSet;
  ++updatesInStep_;
  // Simplified semi-smooth Newton: a frozen set that the update rule no
  // longer accepts is not converged; it is updated again at the next
  // iterates (as at the start of a step) instead of converging to a state
  // with penetrating or adhesive nodes.
  if (total.violations > 0) {
    summary_.activeSet.changed += static_cast<std::size_t>(total.violations);
    updatesInStep_ = 0;
  }
  if (!freezeSet) {
    std::uint64_t signature = 0;
    for (std::size_t p = 0; p < pairs_.size(); ++p) signature += (2 * p + 1) * pairSummaries_[p].setSignature;
    cycle_.record(signature, summary_.activeSet.active, summary_.activeSet.changed + summary_.activeSet.stickSlipChanged);
  }
  summary_.normalResidual = std::sqrt(total.normalResidual2);
  summary_.contactForce = std::sqrt(total.contactForce2);
  summary_.stickResidual = std::sqrt(total.stickResidual2);
  summary_.slipResidual = std::sqrt(total.slipResidual2);
  summary_.tangentialForce = std::sqrt(total.tangentialForce2);
  summary_.normalIncrement = std::sqrt(total.normalIncrement2);
  summary_.stickIncrement = std::sqrt(total.stickIncrement2);
  summary_.slipIncrement = std::sqrt(total.slipIncrement2);
}

void ContactModel::update(const Vector& u, const Vector& bulkResidual, bool freezeSet) {
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact update");
  Teuchos::TimeMonitor scope(*timer);
  // The tangent part of the rows waits for condensedTangent() (the last
  // update of a step needs none), unless pairs are chained: a chained
  // pair's update moves earlier pairs' rows (PairChaining::take / restore).
  const bool anyChained = chaining_->anyChained();
  updatePairs(freezeSet, [&](std::size_t p, bool updateSet) {
    if (!chaining_->chained(p)) return pairs_[p]->update(u, bulkResidual, updateSet, contributions_, !anyChained);
    // Slave nodes that are master nodes of earlier pairs (PairChaining.hpp).
    ContactContributions taken = chaining_->take(p, contributions_, *map_);
    ContactContributions mine;
    const auto summary = pairs_[p]->update(u, *PairChaining::residualFor(bulkResidual, taken), updateSet, mine);
    PairChaining::restore(std::move(taken), mine, *map_);
    append(contributions_, mine);
    return summary;
  });
  const bool local = !contributions_.transform.empty() || !contributions_.tangentTransform.empty() || !contributions_.contactStiffness.empty() ||
                     !contributions_.constraint.empty() || !contributions_.contactResidual.empty() ||
                     !contributions_.constraintResidual.empty();
  contributes_ = anyRank(*map_->getComm(), local);
  transform_ = Teuchos::null;
  if (!contributes_) return;
  static const auto matrices = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact matrices from triplets");
  Teuchos::TimeMonitor matricesScope(*matrices);
  // T - I: only rows of the interface (the identity part is never formed).
  transform_ = linalg::matrixFromTriplets(contributions_.transform, map_);

}

void ContactModel::condenseResidual(Vector& residual) const {
  COULOMB_CHECK(!saddlePoint(), "condenseResidual in the saddle-point form");
  if (!contributes_) return;
  linalg::addEntries(contributions_.contactResidual, residual);
  Vector copy(residual, Teuchos::Copy);
  transform_->apply(copy, residual, Teuchos::NO_TRANS, 1.0, 1.0);  // residual += (T - I) residual
  linalg::addEntries(contributions_.constraintResidual, residual);
}

void ContactModel::subtractPrescribedForces(Vector& reactions) const {
  std::vector<linalg::VectorEntry> negated = contributions_.prescribedForce;
  for (auto& e : negated) e.value = -e.value;
  linalg::addEntries(negated, reactions);
}

Teuchos::RCP<CrsMatrix> ContactModel::condensedTangent(const Teuchos::RCP<CrsMatrix>& bulkTangent) const {
  COULOMB_CHECK(!saddlePoint(), "condensedTangent in the saddle-point form");
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact condensed tangent");
  Teuchos::TimeMonitor scope(*timer);
  {
    // The tangent part of the last update's rows (ContactPair::emitTangent; collective).
    static const auto rowsTimer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact tangent rows");
    Teuchos::TimeMonitor rowsScope(*rowsTimer);
    for (const auto& pair : pairs_)
      if (pair->tangentPending()) pair->emitTangent(contributions_);
  }
  if (!contributes_) return bulkTangent;
  // J = T (K + K_c) + G = K + [K_c + G + (T - I) K + (T - I) K_c]: every term
  // in brackets lives on interface rows only, so the one operation on the
  // size of K is the final sum.
  //
  // (T - I)(K + K_c) is formed here as triplets, without a distributed
  // matrix product: every entry of T - I sits in a column of a slave node's
  // DoF, emitted by the rank that owns that node (ContactPair::update), which
  // also owns the node's rows of K and emitted its rows of K_c.
  std::vector<linalg::MatrixTriplet>& interfaceRows = interfaceRows_;  // its memory kept from the last iterate
  interfaceRows.assign(contributions_.contactStiffness.begin(), contributions_.contactStiffness.end());
  interfaceRows.insert(interfaceRows.end(), contributions_.constraint.begin(), contributions_.constraint.end());
  std::unordered_map<GlobalOrdinal, std::vector<std::pair<GlobalOrdinal, double>>> stiffnessRows;
  for (const auto& t : contributions_.contactStiffness) stiffnessRows[t.row].push_back({t.column, t.value});
  const auto& columns = *bulkTangent->getColMap();
  // Row by row of T - I, the combination of K (+ K_c) rows is summed first
  // (the slave nodes coupled to one master row share most of their
  // columns, so each column is emitted once per row): densely over K's local
  // columns, with a list of the touched ones; K_c columns outside K's
  // column map in a small hash map.
  std::map<GlobalOrdinal, std::vector<std::pair<GlobalOrdinal, double>>> transformRows;
  std::vector<linalg::MatrixTriplet> routed;
  if (transformedSlaves_) {
    // Quad8 / Tri6 slave rows combine the K rows of neighbouring nodes
    // (SlaveTransform.hpp), which another rank may own: every coefficient
    // goes to the owner of its column (route by column: swap, route, swap).
    for (const auto* part : {&contributions_.transform, &contributions_.tangentTransform})
      for (const auto& t : *part) routed.push_back({t.column, t.row, t.value});
    routed = linalg::onRowOwners(routed, *map_);
    for (auto& t : routed) std::swap(t.row, t.column);
  }
  const std::vector<const std::vector<linalg::MatrixTriplet>*> parts =
      transformedSlaves_ ? std::vector<const std::vector<linalg::MatrixTriplet>*>{&routed}
                         : std::vector<const std::vector<linalg::MatrixTriplet>*>{&contributions_.transform,
                                                                                  &contributions_.tangentTransform};
  for (const auto* part : parts)
    for (const auto& t : *part) transformRows[t.row].push_back({t.column, t.value});
  std::vector<double> dense(transformRows.empty() ? 0 : columns.getNodeNumElements(), 0.0);
  std::vector<char> touched(dense.size(), 0);
  std::vector<LocalOrdinal> touchedList;
  std::unordered_map<GlobalOrdinal, double> outside;
  auto accumulate = [&](LocalOrdinal c, double value) {
    if (!touched[c]) {
      touched[c] = 1;
      touchedList.push_back(c);
    }
    dense[c] += value;
  };
  for (const auto& [targetRow, terms] : transformRows) {
    for (const auto& [column, coefficient] : terms) {
      const LocalOrdinal row = map_->getLocalElement(column);
      COULOMB_CHECK(row != Teuchos::OrdinalTraits<LocalOrdinal>::invalid(),
                      "a condensation coefficient refers to a DoF this rank does not own");
      Teuchos::ArrayView<const LocalOrdinal> indices;
      Teuchos::ArrayView<const double> values;
      bulkTangent->getLocalRowView(row, indices, values);
      for (int k = 0; k < indices.size(); ++k) accumulate(indices[k], coefficient * values[k]);
      const auto contact = stiffnessRows.find(column);
      if (contact == stiffnessRows.end()) continue;
      for (const auto& [c, value] : contact->second) {
        const LocalOrdinal local = columns.getLocalElement(c);
        if (local == Teuchos::OrdinalTraits<LocalOrdinal>::invalid()) outside[c] += coefficient * value;
        else accumulate(local, coefficient * value);
      }
    }
    for (LocalOrdinal c : touchedList) {
      interfaceRows.push_back({targetRow, columns.getGlobalElement(c), dense[c]});
      dense[c] = 0.0;
      touched[c] = 0;
    }
    touchedList.clear();
    for (const auto& [column, value] : outside) interfaceRows.push_back({targetRow, column, value});
    outside.clear();
  }
  static const auto addTimer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact K + interface rows");
  Teuchos::TimeMonitor addScope(*addTimer);
  return tangentSum_.add(*bulkTangent, interfaceRows);
}

void ContactModel::updateSaddlePoint(const Vector& x, const Vector& u, bool freezeSet) {
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact update");
  Teuchos::TimeMonitor scope(*timer);
  // z of each pair's owned slave nodes, in the order of saddlePointMap().
  const auto data = x.getData(0);
  std::size_t next = map_->getNodeNumElements();
  std::vector<std::vector<std::array<double, 3>>> z(pairs_.size());
  for (std::size_t p = 0; p < pairs_.size(); ++p)
    for (std::size_t i = 0; i < pairs_[p]->interface().ownedSlaveNodes().size(); ++i) {
      std::array<double, 3> value{};
      for (int c = 0; c < dim_; ++c) value[c] = data[next++];
      z[p].push_back(value);
    }
  updatePairs(freezeSet, [&](std::size_t p, bool updateSet) {
    return pairs_[p]->updateSaddlePoint(u, z[p], updateSet, contributions_);
  });
  contributes_ = true;
  transform_ = Teuchos::null;
}

void ContactModel::displacementPart(const Vector& x, Vector& u) {
  const auto from = x.getData(0);
  auto to = u.getDataNonConst(0);
  std::copy(from.begin(), from.begin() + to.size(), to.begin());
}

void ContactModel::setDisplacementPart(const Vector& u, Vector& x) {
  const auto from = u.getData(0);
  auto to = x.getDataNonConst(0);
  std::copy(from.begin(), from.end(), to.begin());
}

void ContactModel::saddlePointResidual(const Vector& bulkResidual, Vector& f) const {
  f.putScalar(0.0);
  setDisplacementPart(bulkResidual, f);
  linalg::addEntries(contributions_.contactResidual, f);
  linalg::addEntries(contributions_.multipliers.residual, f);
}

Teuchos::RCP<CrsMatrix> ContactModel::saddlePointTangent(const CrsMatrix& bulkTangent) const {
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact saddle-point tangent");
  Teuchos::TimeMonitor scope(*timer);
  // A checking path: K is copied as triplets into a fresh matrix on the
  // extended map (no reuse, no in-place merge as in condensedTangent).
  const auto& m = contributions_.multipliers;
  std::vector<linalg::MatrixTriplet> triplets = contributions_.contactStiffness;
  triplets.insert(triplets.end(), m.columns.begin(), m.columns.end());
  triplets.insert(triplets.end(), m.rows.begin(), m.rows.end());
  const auto& columns = *bulkTangent.getColMap();
  for (std::size_t i = 0; i < map_->getNodeNumElements(); ++i) {
    Teuchos::ArrayView<const LocalOrdinal> indices;
    Teuchos::ArrayView<const double> values;
    bulkTangent.getLocalRowView(static_cast<LocalOrdinal>(i), indices, values);
    const GlobalOrdinal row = map_->getGlobalElement(static_cast<LocalOrdinal>(i));
    for (int k = 0; k < indices.size(); ++k) triplets.push_back({row, columns.getGlobalElement(indices[k]), values[k]});
  }
  return linalg::matrixFromTriplets(triplets, saddlePointMap_);
}

bool ContactModel::converged() const {
  if (!summary_.activeSet.unchanged()) return false;
  // (4.78) on the contact rows, or the seed's increment and mixed criteria on the force increments.
  return summary_.criteriaMet(settings_);
}

std::string ContactModel::unmetCriteria() const {
  const ContactIterationSummary& s = summary_;
  const ContactSettings& t = settings_;
  std::ostringstream out;
  out << std::setprecision(3);
  auto separate = [&out] {
    if (out.tellp() > 0) out << ", ";
  };
  if (!s.activeSet.unchanged()) {
    separate();
    out << "the active set (" << s.activeSet.changed + s.activeSet.stickSlipChanged
        << " slave nodes changed state at the last iterate)";
  }
  // The groups of (4.78), or their force increments (Increment, Mixed criteria).
  const char* measure = t.criterion != ConvergenceCriterion::Residual ? "change of the " : "";
  for (const auto& c : s.criteria(t)) {
    if (c.value <= c.limit) continue;
    separate();
    out << "the " << measure << c.name << " (" << c.value << " > " << c.limit << ")";
  }
  return out.str();
}

std::vector<std::string> ContactModel::nodalFieldNames() const {
  std::vector<std::string> names = {"contact_pressure", "contact_gap", "contact_weighted_gap", "contact_area",
                                    "contact_state",    "contact_augmented_pressure"};
  for (int c = 0; c < dim_; ++c) names.push_back(std::string("contact_normal_") + kComponents[c]);
  for (int c = 0; c < dim_; ++c) names.push_back(std::string("contact_multiplier_") + kComponents[c]);
  if (anyFrictional())
    for (const char* field : {"contact_tangential_traction_", "contact_weighted_slip_", "contact_slip_",
                              "contact_augmented_traction_"})
      for (int c = 0; c < dim_; ++c) names.push_back(std::string(field) + kComponents[c]);
  return names;
}

void ContactModel::nodalFields(const Teuchos::RCP<const Map>& ownedNodeMap, MultiVector& fields) const {
  fields.putScalar(0.0);
  auto view = fields.get2dViewNonConst();
  for (const auto& pair : pairs_)
    for (const auto& o : pair->nodeOutput()) {
      const LocalOrdinal i = ownedNodeMap->getLocalElement(o.node);
      if (i == Teuchos::OrdinalTraits<LocalOrdinal>::invalid()) continue;
      // The order of nodalFieldNames().
      view[0][i] = o.pressure;
      view[1][i] = o.gap;
      view[2][i] = o.weightedGap;
      view[3][i] = o.area;
      view[4][i] = static_cast<double>(static_cast<int>(o.state));
      view[5][i] = o.augmentedPressure;
      constexpr int vectors = 6;
      for (int c = 0; c < dim_; ++c) {
        view[vectors + c][i] = o.normal[c];
        view[vectors + dim_ + c][i] = o.multiplier[c];
        if (anyFrictional()) {
          view[vectors + 2 * dim_ + c][i] = o.tangentialTraction[c];
          view[vectors + 3 * dim_ + c][i] = o.weightedSlip[c];
          view[vectors + 4 * dim_ + c][i] = o.slip[c];
          view[vectors + 5 * dim_ + c][i] = o.augmentedTraction[c];
        }
      }
    }
}

namespace {

bool hasUniformCoefficient(const ContactPairSettings& s) {
  return s.friction.type == FrictionLawType::Coulomb && s.frictionCoefficientField.empty();
}

}  // namespace

std::vector<std::string> ContactModel::globalNames() const {
  std::vector<std::string> names;
  for (const auto& pair : pairs_) {
    for (int c = 0; c < dim_; ++c) names.push_back("contact_force_" + pair->settings().name + "_" + kComponents[c]);
    names.push_back("contact_active_nodes_" + pair->settings().name);
    if (pair->frictional()) {
      names.push_back("contact_normal_force_" + pair->settings().name);
      names.push_back("contact_tangential_force_" + pair->settings().name);
      names.push_back("contact_stick_nodes_" + pair->settings().name);
      // mu beside Q/P (scripts/plot_contact.py draws it): uniform Coulomb only.
      if (hasUniformCoefficient(pair->settings())) names.push_back("contact_friction_coefficient_" + pair->settings().name);
    }
  }
  return names;
}

std::vector<double> ContactModel::globals() const {
  std::vector<double> values;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const auto& s = pairSummaries_[p];
    for (int c = 0; c < dim_; ++c) values.push_back(s.slaveForce[c]);
    values.push_back(static_cast<double>(s.activeSet.active));
    if (pairs_[p]->frictional()) {
      double normal2 = 0, tangential2 = 0;
      for (int c = 0; c < 3; ++c) {
        normal2 += s.normalForce[c] * s.normalForce[c];
        tangential2 += s.tangentialForce[c] * s.tangentialForce[c];
      }
      values.push_back(std::sqrt(normal2));
      values.push_back(std::sqrt(tangential2));
      values.push_back(static_cast<double>(s.activeSet.stick));
      if (hasUniformCoefficient(pairs_[p]->settings())) values.push_back(pairs_[p]->settings().friction.coefficient);
    }
  }
  return values;
}

}  // namespace coulomb::contact
