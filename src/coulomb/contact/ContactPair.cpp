#include "coulomb/contact/ContactPair.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/AutomaticPenalty.hpp"
#include "coulomb/contact/CondensationFrame.hpp"
#include "coulomb/contact/NodalContactLaw.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::contact {

namespace {

/// CondensationFrame of either dimension, widened to 3 components.
struct Frame {
  bool usable = false;
  int numFree = 0;
  std::array<int, 3> free{};
  int gapSlot = -1;
  double gapRowSign = 1, normFree = 0;
  std::array<double, 3> a{};
  std::array<std::array<double, 3>, 3> b{};
};

template <int dim>
Frame widen(const std::array<double, 3>& n3, const std::array<bool, 3>& prescribed3) {
  std::array<double, dim> n{};
  std::array<bool, dim> prescribed{};
  for (int c = 0; c < dim; ++c) {
    n[c] = n3[c];
    prescribed[c] = prescribed3[c];
  }
  const auto f = condensationFrame<dim>(n, prescribed);
  Frame out;
  out.usable = f.usable;
  out.numFree = f.numFree;
  for (int i = 0; i < f.numFree; ++i) out.free[i] = f.free[i];
  out.gapSlot = f.gapSlot;
  out.gapRowSign = f.gapRowSign;
  out.normFree = f.normFree;
  for (int c = 0; c < dim; ++c) {
    out.a[c] = f.a[c];
    for (int s = 0; s < dim; ++s) out.b[s][c] = f.b[s][c];
  }
  return out;
}

Frame frameOf(int dim, const std::array<double, 3>& n, const std::array<bool, 3>& prescribed) {
  return dim == 2 ? widen<2>(n, prescribed) : widen<3>(n, prescribed);
}

/// The slave faces as the automatic penalty sees them (diameter in the
/// reference configuration, the Young's modulus of the element), the
/// master's contact modulus and the thickness of the first slave face's
/// block. The master modulus is the largest E of the blocks carrying master
/// faces; a node's contact modulus is the softer side's, min(E_s,j, E_m)
/// (AutomaticPenalty.hpp): a node's gap meets one element layer of each body
/// in series, which the softer one governs (within a factor 2). The larger
/// of the two instead (before) made a stiff die on a soft slab (E ratio 10)
/// ten times stiffer in its gap rows than the slab under them: each
/// iterate's gap error of a fraction of the slab's compliance opened most of
/// a sliding zone (tests/zoo/sliding_cylinder_2d: 5.1 Newton iterations per
/// slide increment against 3.1; the harmonic mean, twice as stiff here,
/// 3.9). The ALM answer does not depend on it
/// (tests/regression/penalty_independence.cmake); what does — a pure
/// penalty's penetration, the regularised stick of a driven direction — is
/// unchanged for like materials.
struct PenaltyInput {
  std::vector<PenaltyFace> slaveFaces;
  double masterModulus = 0, thickness = 1;
};

PenaltyInput penaltyInput(const mesh::Mesh& mesh, const ContactInterface& contact, const fem::ModelSettings& model) {
  PenaltyInput in;
  const auto& global = mesh.global();
  auto materialOf = [&](long long element) -> const fem::MaterialParameters& {
    const auto& block = global.blocks[mesh.blockOfElement(element)];
    const std::string name = mesh::displayName(block.name, "block", block.id);
    const auto it = model.blockMaterials.find(name);
    COULOMB_REQUIRE(it != model.blockMaterials.end(), "deck: element block '" << name << "' has no material");
    return it->second;
  };
  for (const auto& face : contact.masterFaces())
    in.masterModulus = std::max(in.masterModulus, materialOf(face.element).youngsModulus);
  if (mesh.dimension() == 2) in.thickness = materialOf(contact.slaveFaces().front().element).thickness;

  const auto x = referenceConfiguration(contact);
  const int dim = contact.dimension();
  for (const auto& face : contact.slaveFaces()) {
    PenaltyFace f;
    f.numNodes = face.numNodes;
    f.modulus = materialOf(face.element).youngsModulus;
    for (int a = 0; a < face.numNodes; ++a) {
      f.nodes[a] = face.interfaceIndex[a];
      for (int b = a + 1; b < face.numNodes; ++b) {
        double d2 = 0;
        for (int c = 0; c < dim; ++c) {
          const double d = x.point(face.interfaceIndex[a])[c] - x.point(face.interfaceIndex[b])[c];
          d2 += d * d;
        }
        f.diameter = std::max(f.diameter, std::sqrt(d2));
      }
    }
    in.slaveFaces.push_back(f);
  }
  return in;
}

}  // namespace

ContactPair::ContactPair(const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedDofMap,
                         const ContactPairSettings& settings, const fem::ModelSettings& model)
    : mesh_(mesh), dofMap_(ownedDofMap), settings_(settings), dim_(mesh.dimension()) {
  const std::string what = "Contact/Pairs/" + settings.name;
  interface_ = std::make_unique<ContactInterface>(mesh, settings.slave, settings.master, what);
  gather_ = std::make_unique<InterfaceGather>(*interface_, ownedDofMap);
  const PenaltyInput penalty = penaltyInput(mesh, *interface_, model);
  thickness_ = penalty.thickness;
  const double h = meanFaceDiameter(penalty.slaveFaces);
  k_ = settings.scaleFactor;
  multiplierOffset_ = static_cast<GlobalOrdinal>(dim_) * mesh.global().numNodes();
  minimumD_ = 1e-8 * std::pow(h, dim_ - 1);
  faceSize_ = h;
  referenceD_ = std::pow(h, dim_ - 1);

  prescribed_.assign(interface_->interfaceNodes().size(), {false, false, false});
  for (const auto& condition : model.dirichlet) {
    const auto& set = mesh.global().nodeSets[mesh.nodeSetIndex(condition.nodeSet, "Dirichlet Conditions/" + condition.name)];
    for (long long node : set.nodes) {
      const int i = interface_->interfaceNodeIndex(node);
      if (i < 0) continue;
      for (int c : condition.components) prescribed_[i][c] = true;
    }
  }
  const std::size_t owned = interface_->ownedSlaveNodes().size();
  // eps_n per owned slave node: the deck's value, or the automatic one.
  penalty_.assign(owned, settings.penalty);
  if (settings.penalty <= 0) {
    const auto automatic = automaticNodalPenalty(
        penalty.slaveFaces, static_cast<int>(interface_->interfaceNodes().size()), penalty.masterModulus,
        settings.penaltyFactor,
        settings.formulation == ContactFormulation::Penalty ? PenaltySize::LocalFaces : PenaltySize::PairMean);
    for (std::size_t i = 0; i < owned; ++i)
      penalty_[i] = automatic[interface_->interfaceNodeIndex(interface_->slaveNodes()[interface_->ownedSlaveNodes()[i]])];
  }
  state_.assign(owned, ContactState::Inactive);
  lambdaN_.assign(owned, 0.0);
  pressure_.assign(owned, 0.0);
  traction_.assign(owned, {0.0, 0.0, 0.0});
  weightedSlip_ = slipIncrement_ = stepStartAccumulatedSlip_ = stepStartTraction_ = lastStepSlip_ = traction_;
  slipDirection_ = stepStartSlipDirection_ = traction_;
  beginStep();
}

ContactPair::~ContactPair() = default;

void ContactPair::beginStep() {
  searched_ = false;
  // The last update was at the converged state of the previous step: its
  // operators and coordinates are the D^t, M^t, x^t of the slip (4.69).
  stepStartMortar_ = mortar_;
  stepStartX_ = x_.x.empty() ? referenceConfiguration(*interface_) : x_;
  // The direction of Slip Reset Frequency < 0: the converged slip of the
  // nodes that slipped (a sticking node's slip is round-off, an open one's
  // its approach); a retry keeps that of the converged step.
  if (!restored_)
    for (std::size_t i = 0; i < state_.size(); ++i)
      lastStepSlip_[i] = state_[i] == kSlip ? weightedSlip_[i] : std::array<double, 3>{0.0, 0.0, 0.0};
  restored_ = false;
  for (std::size_t i = 0; i < state_.size(); ++i) {
    for (int c = 0; c < 3; ++c) stepStartAccumulatedSlip_[i][c] += slipIncrement_[i][c];
    slipIncrement_[i] = weightedSlip_[i] = {0.0, 0.0, 0.0};
  }
  stepStartTraction_ = traction_;
  // Slip reset policy: slipping nodes start the step as stick every n-th step.
  const int n = settings_.slipResetFrequency;
  if (frictional() && n > 0 && steps_ % n == 0)
    for (auto& state : state_)
      if (state == kSlip) state = ContactState::Stick;
  for (std::size_t i = 0; i < state_.size(); ++i)
    if (state_[i] != kSlip) slipDirection_[i] = {0.0, 0.0, 0.0};
  stepStartSlipDirection_ = slipDirection_;
  ++steps_;
  stepStartState_ = state_;
  stepStartLambdaN_ = lambdaN_;
}

void ContactPair::restoreStep() {
  state_ = stepStartState_;
  lambdaN_ = stepStartLambdaN_;
  for (std::size_t i = 0; i < state_.size(); ++i) slipIncrement_[i] = weightedSlip_[i] = {0.0, 0.0, 0.0};
  // The retry calls beginStep() again: it must see the converged state of
  // the previous step, not the failed iterate (the slip's Dᵗ, Mᵗ, xᵗ).
  mortar_ = stepStartMortar_;
  x_ = stepStartX_;
  traction_ = stepStartTraction_;
  slipDirection_ = stepStartSlipDirection_;
  --steps_;
  searched_ = false;
  restored_ = true;
}

std::string ContactPair::penetrationFailure(long long node, double gap, double D) {
  if (gap / D >= -radius_) return "";
  deepest_ = std::max(deepest_, -gap / D);
  std::ostringstream message;
  message << "Contact/Pairs/" << settings_.name << ": slave node " << node + 1 << " penetrates the master by "
          << -gap / D << ", more than the search radius " << radius_ << ": the search radius is widened";
  return message.str();
}

void ContactPair::widenSearchRadius() {
  double deepest = 0.0;
  Teuchos::reduceAll(*interface_->comm(), Teuchos::REDUCE_MAX, deepest_, Teuchos::outArg(deepest));
  deepest_ = 0.0;
  if (deepest > 0.0) widenedRadius_ = std::max(widenedRadius_, 2.0 * deepest);
}

bool ContactPair::isPrescribed(long long node, int c) const {
  const int i = interface_->interfaceNodeIndex(node);
  return i >= 0 && prescribed_[i][c];
}

void ContactPair::search() {
  std::string failure;
  try {
    radius_ = std::max(defaultSearchRadius(*interface_, x_, settings_.searchRadiusFactor), widenedRadius_);
    search_ = searchContactPairs(*interface_, x_, radius_);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  // Slave nodes inside the master beyond the radius (bodies that overlap):
  // widen the radius to twice the deepest and search again, at once.
  const auto& comm = *interface_->comm();
  double depth = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, search_.unpairedDepth, Teuchos::outArg(depth));
  if (!(depth > 0.0) || 2.0 * depth <= radius_) return;
  long long node = search_.unpairedDepth == depth ? search_.unpairedNode : -1, deepestNode = -1;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, node, Teuchos::outArg(deepestNode));
  std::ostringstream note;
  note << "Contact/Pairs/" << settings_.name << ": slave node " << deepestNode + 1 << " lies " << depth
       << " inside the master, beyond the search radius " << radius_ << ": the radius is widened to " << 2.0 * depth;
  notes_.push_back(note.str());
  widenedRadius_ = std::max(widenedRadius_, 2.0 * depth);
  radius_ = widenedRadius_;
  search_ = searchContactPairs(*interface_, x_, radius_);
}

std::vector<std::string> ContactPair::takeNotes() {
  std::vector<std::string> notes;
  notes.swap(notes_);
  return notes;
}

void ContactPair::searchAndIntegrate(const Vector& u) {
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact search and mortar values");
  Teuchos::TimeMonitor scope(*timer);
  x_ = gather_->gather(u);
  std::string failure;
  NodalMortarQuantities local;
  if (!searched_ || settings_.searchEveryIteration) {
    search();
    searched_ = true;
  }
  try {
    std::vector<int> needed = interface_->slaveNodesOfOwnedFaces();
    needed.insert(needed.end(), interface_->ownedSlaveNodes().begin(), interface_->ownedSlaveNodes().end());
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    normals_ = computeNodalNormals(*interface_, x_, false, &needed);
    local = integrateMortarPass(*interface_, x_, normals_, search_, false);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  mortar_ = sumToOwners(*interface_, local);
}

void ContactPair::differentiateActive() {
  std::vector<char> flags(state_.size(), 0);
  for (std::size_t i = 0; i < state_.size(); ++i) flags[i] = isActive(state_[i]) ? 1 : 0;
  differentiate(flags);
}

void ContactPair::differentiate(const std::vector<char>& ownedFlags) {
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact mortar derivatives");
  Teuchos::TimeMonitor scope(*timer);
  // Which slave nodes are flagged anywhere: one flag per slave node, max over ranks.
  const auto& slaveNodes = interface_->slaveNodes();
  const auto& owned = interface_->ownedSlaveNodes();
  std::vector<int> local(slaveNodes.size(), 0), active(slaveNodes.size(), 0);
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (ownedFlags[i]) local[owned[i]] = 1;
  Teuchos::reduceAll(*interface_->comm(), Teuchos::REDUCE_MAX, static_cast<int>(local.size()), local.data(),
                     active.data());
  // The searched slave faces with a flagged node: all the faces of a flagged
  // node are there (its D, M, g~ derivatives are complete), no others.
  SearchResult subset;
  subset.radius = search_.radius;
  std::vector<int> needed(owned.begin(), owned.end());
  for (std::size_t k = 0; k < search_.slaveFaces.size(); ++k) {
    const ContactFace& face = interface_->slaveFaces()[search_.slaveFaces[k]];
    bool any = false;
    for (int a = 0; a < face.numNodes; ++a) any = any || active[interface_->slaveNodeIndex(face.nodes[a])];
    if (!any) continue;
    subset.slaveFaces.push_back(search_.slaveFaces[k]);
    subset.candidates.push_back(search_.candidates[k]);
    for (int a = 0; a < face.numNodes; ++a) needed.push_back(interface_->slaveNodeIndex(face.nodes[a]));
  }
  std::sort(needed.begin(), needed.end());
  needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
  std::string failure;
  NodalMortarQuantities partial;
  partial.dimension = dim_;
  partial.withDerivatives = true;
  try {
    normalDerivatives_ = computeNodalNormals(*interface_, x_, true, &needed);
    partial = integrateMortarPass(*interface_, x_, normalDerivatives_, subset, true);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  mortarDerivatives_ = sumToOwners(*interface_, partial);
}

PairIterationSummary ContactPair::update(const Vector& u, const Vector& bulkResidual, bool updateSet,
                                         ContactContributions& out) {
  // Stage 1 (values): search, normals, D, M, g~ of every slave node; the new
  // active set. Stage 2 (derivatives, Sacado): only the faces around active
  // nodes — the rest of a large slave surface costs a plain double pass.
  searchAndIntegrate(u);
  if (frictional()) return updateFrictional(bulkResidual, updateSet, out);
  // ALM and MPC share the condensed rows (the MPC's ties); they differ in the state rule.
  const bool alm = settings_.formulation != ContactFormulation::Penalty;
  const bool mpc = settings_.formulation == ContactFormulation::MPC;
  const auto r = bulkResidual.getData(0);
  const auto& map = *dofMap_;
  auto row = [this](long long node, int c) { return dofRow(node, c); };
  PairIterationSummary summary;
  std::string failure;
  const auto& slaveNodes = interface_->slaveNodes();
  const auto& owned = interface_->ownedSlaveNodes();
  const double t = thickness_;

  for (std::size_t i = 0; i < owned.size(); ++i) {
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const ContactState previous = state_[i];
    const NodalMortarEntry* entry = mortar_.find(node);
    if (entry == nullptr || entry->D <= minimumD_) {
      state_[i] = ContactState::Inactive;
      lambdaN_[i] = pressure_[i] = 0;
      countState(summary.activeSet, state_[i], previous);
      continue;
    }
    const double D = entry->D, gap = entry->gap;
    const auto& n = normals_[s].n;
    const Frame frame = frameOf(dim_, n, prescribed_[interface_->interfaceNodeIndex(node)]);

    double lambdaN = 0;
    ContactState state = previous;
    if (alm) {
      if (previous == ContactState::Active && frame.usable) {
        double projected = 0;
        for (int f = 0; f < frame.numFree; ++f) {
          const int c = frame.free[f];
          projected += frame.a[c] * r[map.getLocalElement(row(node, c))];
        }
        lambdaN = projected / (k_ * t * D * frame.normFree);
      }
      const ContactState rule = !frame.usable ? ContactState::Inactive
                                : mpc       ? mpcContactState(previous == ContactState::Active, lambdaN, gap)
                                            : almContactState(lambdaN, gap, D, k_, penalty_[i], touchingGap());
      state = nextState(rule, previous, updateSet, summary.violations);
      if (!frame.usable) state = ContactState::Inactive;
      if (state == ContactState::Inactive) lambdaN = 0;
    } else {
      state = nextState(penaltyContactState(gap), previous, updateSet, summary.violations);
    }
    state_[i] = state;
    countState(summary.activeSet, state, previous);
    if (state == ContactState::Active) {
      std::string deep = penetrationFailure(node, gap, D);
      if (failure.empty()) failure = std::move(deep);
    }
    if (alm) {
      lambdaN_[i] = lambdaN;
      pressure_[i] = -k_ * lambdaN;
    } else {
      pressure_[i] = state == ContactState::Active ? penalty_[i] * std::max(-gap, 0.0) / D : 0.0;
      lambdaN_[i] = -pressure_[i] / k_;
    }
  }
  widenSearchRadius();
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  differentiateActive();

  for (std::size_t i = 0; i < owned.size(); ++i) {
    if (state_[i] != ContactState::Active) continue;
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const NodalMortarEntry* entry = mortarDerivatives_.find(node);
    if (entry == nullptr) continue;  // cannot happen: the node's faces were differentiated
    const double D = entry->D, gap = entry->gap, lambdaN = lambdaN_[i], epsN = penalty_[i];
    const auto& n = normalDerivatives_[s].n;
    const auto& dn = normalDerivatives_[s].derivative;
    const Frame frame = frameOf(dim_, n, prescribed_[interface_->interfaceNodeIndex(node)]);

    // Slave force f_j acting on the slave body.
    std::array<double, 3> force{};
    for (int c = 0; c < dim_; ++c) force[c] = alm ? k_ * t * D * lambdaN * n[c] : -pressure_[i] * t * D * n[c];
    for (int c = 0; c < dim_; ++c) {
      summary.slaveForce[c] += force[c];
      summary.normalForce[c] += force[c];
      summary.contactForce2 += force[c] * force[c];
    }

    // Derivative rows (d/dx of node, component) with prescribed columns left out.
    auto emitRow = [&](std::vector<linalg::MatrixTriplet>& target, GlobalOrdinal targetRow,
                       const std::map<DofKey, double>& values) {
      for (const auto& [key, value] : values)
        if (!isPrescribed(key.first, key.second) && value != 0.0)
          target.push_back({targetRow, row(key.first, key.second), value});
    };
    auto addScaled = [](std::map<DofKey, double>& to, const DerivativeRow& from, double scale) {
      for (const auto& [key, value] : from) to[key] += scale * value;
    };
    auto addNormal = [&dn](std::map<DofKey, double>& to, int component, double scale) {
      for (const auto& d : dn) to[{d.node, d.component}] += scale * d.dn[component];
    };

    if (alm) {
      // Forces on prescribed DoFs (slave f_j = k t lambda_n D n, master -k t lambda_n M_jl n): the supports'.
      for (int c = 0; c < dim_; ++c) {
        if (isPrescribed(node, c)) out.prescribedForce.push_back({row(node, c), force[c]});
        for (const auto& [master, Mjl] : entry->M)
          if (isPrescribed(master, c)) out.prescribedForce.push_back({row(master, c), -k_ * t * lambdaN * Mjl * n[c]});
      }
      // T - I on the slave rows: the gap slot is emptied, the b rows replace the others.
      out.transform.push_back({row(node, frame.gapSlot), row(node, frame.gapSlot), -1.0});
      for (int f = 0; f < frame.numFree; ++f) {
        const int slot = frame.free[f];
        if (slot == frame.gapSlot) continue;
        out.transform.push_back({row(node, slot), row(node, slot), -1.0});
        for (int g = 0; g < frame.numFree; ++g)
          out.transform.push_back({row(node, slot), row(node, frame.free[g]), frame.b[slot][frame.free[g]]});
      }
      // T - I on the master rows: + M_jl n_c / (D |n_F|) × the a-row of j.
      for (const auto& [master, Mjl] : entry->M)
        for (int c = 0; c < dim_; ++c) {
          if (isPrescribed(master, c)) continue;
          const double scale = Mjl * n[c] / (D * frame.normFree);
          for (int g = 0; g < frame.numFree; ++g)
            out.transform.push_back({row(master, c), row(node, frame.free[g]), scale * frame.a[frame.free[g]]});
        }
      // The gap row: sign eps_n t g~_j and its derivative.
      const double scale = frame.gapRowSign * epsN * t;
      out.constraintResidual.push_back({row(node, frame.gapSlot), scale * gap});
      std::map<DofKey, double> gapRow;
      addScaled(gapRow, entry->dGap, scale);
      emitRow(out.constraint, row(node, frame.gapSlot), gapRow);
      summary.normalResidual2 += (epsN * t * gap) * (epsN * t * gap);
      // The same step as the uncondensed saddle-point system (lambda_n,j a
      // DoF of its own): its column -d f_c / d lambda_n, its row eps_n t g~.
      const GlobalOrdinal multiplier = multiplierOffset_ + node;
      for (int c = 0; c < dim_; ++c) {
        if (!isPrescribed(node, c)) {
          out.saddle.columns.push_back({row(node, c), multiplier, -k_ * t * D * n[c]});
          out.saddle.force.push_back({row(node, c), -k_ * t * D * lambdaN * n[c]});
        }
        for (const auto& [master, Mjl] : entry->M)
          if (!isPrescribed(master, c)) {
            out.saddle.columns.push_back({row(master, c), multiplier, k_ * t * Mjl * n[c]});
            out.saddle.force.push_back({row(master, c), k_ * t * Mjl * lambdaN * n[c]});
          }
      }
      std::map<DofKey, double> saddleRow;
      addScaled(saddleRow, entry->dGap, epsN * t);
      emitRow(out.saddle.rows, multiplier, saddleRow);
      out.saddle.gap.push_back({multiplier, epsN * t * gap});
      // K_c = -d f_c / dx with lambda_n frozen: slave f_j = k t lambda_n D n, master f_l = -k t lambda_n M_jl n.
      if (lambdaN != 0.0) {
        const double kl = k_ * t * lambdaN;
        for (int c = 0; c < dim_; ++c) {
          if (isPrescribed(node, c)) continue;
          std::map<DofKey, double> values;
          addScaled(values, entry->dD, -kl * n[c]);
          addNormal(values, c, -kl * D);
          emitRow(out.contactStiffness, row(node, c), values);
        }
        for (const auto& [master, Mjl] : entry->M)
          for (int c = 0; c < dim_; ++c) {
            if (isPrescribed(master, c)) continue;
            std::map<DofKey, double> values;
            const auto dM = entry->dM.find(master);
            if (dM != entry->dM.end()) addScaled(values, dM->second, kl * n[c]);
            addNormal(values, c, kl * Mjl);
            emitRow(out.contactStiffness, row(master, c), values);
          }
      }
    } else {
      // Penalty (4.71a): residual -f, K_c = -df/dx through g~, n, D and M.
      auto penaltyRows = [&](long long target, const NodalForce<3>& f, const DerivativeRow* dM) {
        for (int c = 0; c < dim_; ++c) {
          if (isPrescribed(target, c)) {
            out.prescribedForce.push_back({row(target, c), t * f.f[c]});
            continue;
          }
          out.contactResidual.push_back({row(target, c), -t * f.f[c]});
          std::map<DofKey, double> values;
          addScaled(values, entry->dGap, -t * f.dGap[c]);
          addScaled(values, entry->dD, -t * f.dD[c]);
          if (dM) addScaled(values, *dM, -t * f.dM[c]);
          for (int m = 0; m < dim_; ++m) addNormal(values, m, -t * f.dNormal[c][m]);
          emitRow(out.contactStiffness, row(target, c), values);
        }
      };
      const NVec<3> n3{n[0], n[1], dim_ == 3 ? n[2] : 0.0};
      penaltyRows(node, penaltySlaveForce<3>(n3, gap, epsN), nullptr);
      for (const auto& [master, Mjl] : entry->M) {
        const auto dM = entry->dM.find(master);
        penaltyRows(master, penaltyMasterForce<3>(n3, gap, D, Mjl, epsN),
                    dM != entry->dM.end() ? &dM->second : nullptr);
      }
    }
  }

  reduceSummary(summary);
  return summary;
}

}  // namespace coulomb::contact
