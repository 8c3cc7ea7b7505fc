#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/contact/interface/InterfaceBalance.hpp"
#include "coulomb/contact/interface/NodalSupport.hpp"
#include "coulomb/contact/interface/SelfContactRoles.hpp"
#include "coulomb/contact/interface/SharpEdges.hpp"
#include "coulomb/contact/SlaveTransform.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/laws/AutomaticPenalty.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::contact {

namespace {

/// The slave faces as the automatic penalty sees them (diameter in the
/// reference configuration, the Young's modulus of the element), the
/// master's contact modulus (the largest E of the blocks carrying master
/// faces; AutomaticPenalty.hpp takes the softer side per node) and the
/// thickness of the first slave face's block.
struct PenaltyInput {
  std::vector<PenaltyFace> slaveFaces;
  double masterModulus = 0, thickness = 1;
};

PenaltyInput penaltyInput(const mesh::Mesh& mesh, const ContactInterface& contact, const fem::ModelSettings& model,
                          const std::string& what) {
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
  if (mesh.dimension() == 2) {
    // One thickness per pair: its forces are t D lambda (a slave surface may
    // span blocks: a side set list, or joined pairs).
    const auto& first = global.blocks[mesh.blockOfElement(contact.slaveFaces().front().element)];
    in.thickness = materialOf(contact.slaveFaces().front().element).thickness;
    for (const auto& face : contact.slaveFaces()) {
      const auto& block = global.blocks[mesh.blockOfElement(face.element)];
      COULOMB_REQUIRE(materialOf(face.element).thickness == in.thickness,
                      what << ": the slave surface spans blocks '" << mesh::displayName(first.name, "block", first.id)
                           << "' and '" << mesh::displayName(block.name, "block", block.id)
                           << "' of different thickness; give them one thickness or one pair each");
    }
  }

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
                         const ContactPairSettings& settings, const fem::ModelSettings& model, ContactSystemForm form)
    : mesh_(mesh), dofMap_(ownedDofMap), settings_(settings), dim_(mesh.dimension()) {
  const std::string what = "Contact/Pairs/" + settings.name;
  interface_ = std::make_unique<ContactInterface>(mesh, settings.slave, settings.master, what,
                                                  model.axisymmetric(mesh.dimension()));
  gather_ = std::make_unique<InterfaceGather>(*interface_, ownedDofMap);
  integratedFaces_ = interface_->ownedSlaveFaces();
  const PenaltyInput penalty = penaltyInput(mesh, *interface_, model, what);
  const double h = meanFaceDiameter(penalty.slaveFaces);
  constants_.settings = &settings_;
  constants_.k = settings.scaleFactor;
  constants_.thickness = penalty.thickness;
  constants_.faceSize = h;
  constants_.referenceD = std::pow(h, dim_ - 1);
  formulation_ = makeFormulation(dim_, constants_, form);
  minimumD_ = 1e-8 * std::pow(h, dim_ - 1);

  prescribed_.assign(interface_->interfaceNodes().size(), {false, false, false});
  for (const auto& condition : model.dirichlet) {
    const auto& set = mesh.global().nodeSets[mesh.nodeSetIndex(condition.nodeSet, "Dirichlet Conditions/" + condition.name)];
    for (long long node : set.nodes) {
      const int i = interface_->interfaceNodeIndex(node);
      if (i < 0) continue;
      for (int c : condition.components) prescribed_[i][c] = true;
    }
  }
  slaveTransform_ = std::make_unique<SlaveTransform>(*interface_, prescribed_, what);
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
  nodes_.assign(owned, SlaveNodeState{});
  accumulatedSlip_.assign(owned, {0.0, 0.0, 0.0});
  lastStepSlip_ = accumulatedSlip_;
  // The objective slip (4.69b) of the first step needs D^t, M^t of the
  // initial configuration: integrated here, beginStep(1) keeps them.
  if (frictional() && settings_.slipMeasure == SlipMeasure::Objective) {
    x_ = referenceConfiguration(*interface_);
    integrateCurrentConfiguration();
  }
  beginStep(1);
  if (!settings.mergedFrom.empty()) {
    std::string names;
    for (const auto& name : settings.mergedFrom) names += (names.empty() ? "'" : ", '") + name + "'";
    notes_.push_back("pairs " + names + " share slave nodes: they are solved as one pair '" + settings.name +
                     "' (one multiplier per node and direction)");
  }
}

ContactPair::~ContactPair() = default;


void ContactPair::beginStep(int deckStep) {
  searched_ = false;
  // The last update was at the converged state of the previous step: its
  // operators and coordinates are the D^t, M^t, x^t of the slip (4.69).
  stepStartMortar_ = mortar_;
  stepStartX_ = x_.x.empty() ? referenceConfiguration(*interface_) : x_;
  stepStartSupport_ = support_;
  stepStartWeight_.clear();
  if (settings_.slipMeasure == SlipMeasure::Objective)
    for (const auto& entry : stepStartMortar_.entries) stepStartWeight_.push_back(objectiveWeight(entry, nullptr));
  // The direction of Slip Reset Frequency < 0: the converged slip of the
  // nodes that slipped (a sticking node's slip is round-off, an open one's
  // its approach); a retry keeps that of the converged step.
  if (!restored_)
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      lastStepSlip_[i] =
          nodes_[i].state == ContactState::Slip ? nodes_[i].weightedSlip : std::array<double, 3>{0.0, 0.0, 0.0};
  restored_ = false;
  // Slip reset policy: slipping nodes start the step as stick every n-th deck step.
  const bool reset = frictional() && resetsSlip(settings_.slipResetFrequency, deckStep);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    auto& node = nodes_[i];
    for (int c = 0; c < 3; ++c) accumulatedSlip_[i][c] += node.slipIncrement[c];
    node.slipIncrement = node.weightedSlip = {0.0, 0.0, 0.0};
    if (reset && node.state == ContactState::Slip) node.state = ContactState::Stick;
    if (node.state != ContactState::Slip) node.slipDirection = {0.0, 0.0, 0.0};
  }
  stepStart_ = nodes_;
}

void ContactPair::restoreStep() {
  // The retry calls beginStep() again: it must see the converged state of
  // the previous step, not the failed iterate (the slip's Dᵗ, Mᵗ, xᵗ).
  nodes_ = stepStart_;
  mortar_ = stepStartMortar_;
  support_ = stepStartSupport_;
  x_ = stepStartX_;
  searched_ = false;
  restored_ = true;
  tangentPending_ = false;
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

void ContactPair::search() {
  // Its own counter: the number of calls shows Search Every Iteration at work.
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: contact search");
  Teuchos::TimeMonitor scope(*timer);
  searchCandidates();
  std::string failure;
  const std::vector<int> needed = neededSlaveNodes();
  try {
    normalFaces_ = chooseSlaveNormalFaces(*interface_, x_, settings_.featureAngle, radius_, &needed);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  // Counted on the owned nodes (each on one rank), summed.
  std::vector<char> owned(interface_->slaveNodes().size(), 0);
  for (int i : interface_->ownedSlaveNodes()) owned[static_cast<std::size_t>(i)] = 1;
  std::array<long long, 2> local{0, 0}, global{0, 0};
  for (long long node : normalFaces_.sharpNodes) local[0] += owned[interface_->slaveNodeIndex(node)];
  for (long long node : normalFaces_.facingNodes) local[1] += owned[interface_->slaveNodeIndex(node)];
  Teuchos::reduceAll(*interface_->comm(), Teuchos::REDUCE_SUM, 2, local.data(), global.data());
  // Once a run: the counts change as the bodies deform and contact spreads.
  if (!sharpEdgesNoted_ && global[0] > 0) {
    std::ostringstream note;
    note << "Contact/Pairs/" << settings_.name << ": " << global[0]
         << " slave nodes on sharp edges (faces more than 'Feature Angle' = " << settings_.featureAngle
         << " degrees apart); " << global[1] << " of them take the normal of the side facing the master";
    notes_.push_back(note.str());
    sharpEdgesNoted_ = true;
  }
}

std::vector<int> ContactPair::neededSlaveNodes() const {
  std::vector<int> needed = slaveNodesOfFaces(*interface_, integratedFaces_);
  needed.insert(needed.end(), interface_->ownedSlaveNodes().begin(), interface_->ownedSlaveNodes().end());
  std::sort(needed.begin(), needed.end());
  needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
  return needed;
}

void ContactPair::searchCandidates() {
  const double facing = facingNormalDot(settings_.featureAngle);
  // Each stage on every rank, then one agreed error if any rank failed.
  auto collectively = [&](const auto& stage) {
    std::string failure;
    try {
      stage();
    } catch (const Error& e) {
      failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
    }
    throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  };
  collectively([&] {
    radius_ = std::max(defaultSearchRadius(*interface_, x_, settings_.searchRadiusFactor), widenedRadius_);
    search_ = searchContactPairs(*interface_, x_, radius_, integratedFaces_, facing);
  });
  if (settings_.distribution == InterfaceDistribution::Balanced && interface_->comm()->getSize() > 1) {
    // The faces go where their candidates balance the work; search them
    // there (cheaper than sending the candidate lists along).
    integratedFaces_ = balancedSlaveFaces(*interface_, integratedFaces_, search_);
    collectively([&] { search_ = searchContactPairs(*interface_, x_, radius_, integratedFaces_, facing); });
  }
  SelfContactRoles selfRoles;
  // Roles from the step start and now (SelfContactRoles.hpp); the
  // constructor's first search, before any step, is at the reference
  // configuration.
  if (interface_->selfContact())
    collectively([&] {
      selfRoles = restrictToSelfContactRoles(*interface_, stepStartX_.x.empty() ? x_ : stepStartX_, x_, search_);
    });
  if (interface_->selfContact()) {
    // Every rank decided the same roles (SelfContactRoles.hpp).
    if (selfRoles.droppedLinks > 0 && selfRoles.droppedLinks != droppedSelfLinks_) {
      std::ostringstream note;
      note << "Contact/Pairs/" << settings_.name << ": " << selfRoles.droppedLinks
           << " pairs of facing faces of the self-contact surface could not be given slave and master roles "
              "(a contact region folding onto itself, or an odd loop of regions) and are left out";
      notes_.push_back(note.str());
    }
    droppedSelfLinks_ = selfRoles.droppedLinks;
    // Quad8 / Tri6 faces: the slave role's faces alone are transformed.
    std::vector<char> slaveRole(selfRoles.role.size());
    for (std::size_t f = 0; f < slaveRole.size(); ++f) slaveRole[f] = selfRoles.role[f] == SelfContactRole::Slave;
    slaveTransform_->useSlaveFaces(slaveRole);
    return;  // every node lies on its own surface: no depth check behind a nearest face
  }
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
  search_ = searchContactPairs(*interface_, x_, radius_, integratedFaces_, facing);
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
  integrateCurrentConfiguration();
}

void ContactPair::integrateCurrentConfiguration() {
  std::string failure;
  NodalMortarQuantities local;
  if (!searched_ || settings_.searchEveryIteration) {
    search();
    searched_ = true;
  }
  try {
    const std::vector<int> needed = neededSlaveNodes();
    normals_ = computeNodalNormals(*interface_, x_, false, &needed, &normalFaces_);
    local = integrateMortarPass(*interface_, x_, normals_, search_, false);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  mortar_ = sumToOwners(*interface_, local);
  try {
    support_ = nodalSupportMeasures(*interface_, x_, mortar_.entries);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
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
    normalDerivatives_ = computeNodalNormals(*interface_, x_, true, &needed, &normalFaces_);
    partial = integrateMortarPass(*interface_, x_, normalDerivatives_, subset, true);
  } catch (const Error& e) {
    failure = std::string("Contact/Pairs/") + settings_.name + ": " + e.what();
  }
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  mortarDerivatives_ = sumToOwners(*interface_, partial);
}

SlaveNode ContactPair::slaveNode(std::size_t i, bool derivatives) {
  SlaveNode n;
  n.index = i;
  n.slave = interface_->ownedSlaveNodes()[i];
  n.node = interface_->slaveNodes()[n.slave];
  const NodalMortarEntry* entry = mortar_.find(n.node);
  n.mortar = entry != nullptr && contactWeight(*entry) ? entry : nullptr;
  n.normal = &normals_[n.slave];
  if (derivatives) {
    n.mortarDerivative = mortarDerivatives_.find(n.node);
    n.normalDerivative = &normalDerivatives_[n.slave];
  }
  n.prescribed = prescribed_[interface_->interfaceNodeIndex(n.node)];
  // A prescribed component is driven (it moves the slave relative to the
  // master, FrictionalNodeInput::driven) unless a master node coupled to the
  // slave node has it prescribed too: then it is a plane both bodies share (a
  // symmetry plane), across which nothing slides; the mortar slip there is
  // one-sided (the node's support ends at the plane) and must not be read as
  // a slip.
  const NodalMortarEntry* coupling = derivatives && n.mortarDerivative ? n.mortarDerivative : n.mortar;
  for (int c = 0; c < dim_ && coupling != nullptr; ++c) {
    if (!n.prescribed[c]) continue;
    bool shared = false;
    for (const auto& [master, Mjl] : coupling->M) shared = shared || isPrescribedDof(*interface_, prescribed_, master, c);
    n.driven[c] = !shared;
  }
  n.epsN = penalty_[i];
  n.frictionCoefficient = settings_.frictionCoefficient(n.node);
  n.lastStepSlip = lastStepSlip_[i];
  n.state = &nodes_[i];
  n.stepStart = &stepStart_[i];
  return n;
}

PairIterationSummary ContactPair::updateNodes(const Vector* bulkResidual, const std::vector<std::array<double, 3>>* z,
                                              bool updateSet, bool deferTangent, ContactContributions& out) {
  tangentPending_ = false;
  const bool slip = formulation_->usesSlip();
  const auto& map = *dofMap_;
  Teuchos::ArrayRCP<const double> r;
  if (bulkResidual != nullptr) r = bulkResidual->getData(0);
  // The node's bulk residual (zero on prescribed components) and z.
  // Quad8 / Tri6 slave faces: the transformed residual r~_j = sum_k T_kj r_k
  // (SlaveTransform.hpp), from the residual of every interface node.
  std::vector<double> gathered;
  if (slaveTransform_->active() && bulkResidual != nullptr) gathered = gather_->gatherValues(*bulkResidual);
  auto complete = [&](SlaveNode& n) {
    for (int c = 0; c < dim_ && bulkResidual != nullptr; ++c) {
      if (n.prescribed[c]) continue;
      if (gathered.empty()) {
        n.residual[c] = r[map.getLocalElement(static_cast<GlobalOrdinal>(dim_ * n.node + c))];
        continue;
      }
      n.residual[c] = 0.0;
      for (const auto& term : slaveTransform_->rowTerms(n.slave)) {
        const int i = interface_->interfaceNodeIndex(interface_->slaveNodes()[term.slave]);
        if (!prescribed_[i][c]) n.residual[c] += term.coefficient * gathered[static_cast<std::size_t>(i) * dim_ + c];
      }
    }
    if (z != nullptr) n.multiplier = (*z)[n.index];
  };
  const std::size_t owned = nodes_.size();
  COULOMB_CHECK(z == nullptr || z->size() == owned, "one multiplier per owned slave node");

  // Stage 1 (values): the new states.
  const std::vector<SlaveNodeState> previousStates = nodes_;
  PairIterationSummary summary;
  std::string failure;
  std::vector<char>& flags = derivativeFlags_;
  flags.assign(owned, 0);
  nodeResidual_.assign(owned, {0.0, 0.0, 0.0});
  nodeMultiplier_.assign(owned, {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < owned; ++i) {
    SlaveNode n = slaveNode(i, false);
    complete(n);
    nodeResidual_[i] = n.residual;
    nodeMultiplier_[i] = n.multiplier;
    SlaveNodeState& node = nodes_[i];
    const ContactState previous = node.state;
    ContactState state = ContactState::Inactive;
    if (n.mortar != nullptr) {
      if (slip) {
        n.slip = node.weightedSlip = weightedSlip(*n.mortar, nullptr);
        for (int c = 0; c < 3; ++c) node.slipIncrement[c] = -n.slip[c] / n.mortar->D;  // the slave relative to the master
      }
      state = formulation_->decide(n, previous, updateSet, summary);
      if (isActive(state)) {
        std::string deep = penetrationFailure(n.node, n.mortar->gap, n.mortar->D);
        if (failure.empty()) failure = std::move(deep);
      }
    } else {
      node.lambdaN = node.pressure = node.augmentedPressure = 0.0;
      node.traction = node.augmentedTraction = {0.0, 0.0, 0.0};
    }
    if (!isActive(state)) node.weightedSlip = node.slipIncrement = {0.0, 0.0, 0.0};  // an open node does not slip
    if (state != ContactState::Slip) node.slipDirection = {0.0, 0.0, 0.0};      // stage 2 sets it for the slipping ones
    node.state = state;
    countState(summary.activeSet, state, previous);
    flags[i] = formulation_->needsDerivatives(n) ? 1 : 0;
  }
  widenSearchRadius();
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  // Stage 2: the rows, the tangent's now or when it is asked for (emitTangent).
  const bool condensed = z == nullptr && (settings_.formulation == ContactFormulation::ALM ||
                                          settings_.formulation == ContactFormulation::MPC);
  emitRows(true, !deferTangent, condensed, out, summary, [&](long long node, int c) {
    return r[map.getLocalElement(static_cast<GlobalOrdinal>(dim_ * node + c))];
  });
  tangentPending_ = deferTangent;
  addForceIncrements(previousStates, summary);
  reduceSummary(summary);
  return summary;
}

void ContactPair::emitRows(bool residualPart, bool tangentPart, bool condensed, ContactContributions& out,
                           PairIterationSummary& summary, const std::function<double(long long, int)>& residual) {
  const bool slip = formulation_->usesSlip();
  // The derivatives (Sacado): only the faces around the flagged nodes — the
  // rest of a large slave surface costs the values pass alone.
  if (tangentPart) differentiate(derivativeFlags_);
  RowSink sink(out, *interface_, prescribed_, multiplierBlockOffset_);
  sink.residualPart = residualPart;
  sink.tangentPart = tangentPart;
  const SlaveTransform::Marks before(out);  // where this pair's entries begin
  std::array<DerivativeRow, 3> dw;
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    SlaveNode n = slaveNode(i, tangentPart && derivativeFlags_[i] != 0);
    n.residual = nodeResidual_[i];
    n.multiplier = nodeMultiplier_[i];
    if (slip && n.mortarDerivative != nullptr) {
      n.slip = weightedSlip(*n.mortarDerivative, &dw);
      n.slipDerivative = &dw;
    } else if (slip && derivativeFlags_[i] != 0) {
      n.slip = nodes_[i].weightedSlip;  // stage 1's, from the values
    }
    formulation_->emit(n, sink, summary);
  }
  // T - I of the rows the pair kept (condensed) belongs to the residual part.
  if (slaveTransform_->active())
    slaveTransform_->toSystemRows(out, before, condensed && residualPart, interface_->ownedSlaveNodes(), residual);
}

void ContactPair::emitTangent(ContactContributions& out) {
  COULOMB_CHECK(tangentPending_, "emitTangent without an update that deferred its tangent");
  PairIterationSummary figures;  // counted by the update's residual part
  emitRows(false, true, false, out, figures, [](long long, int) -> double {
    throw Error("emitTangent: the residual part is the update's");
  });
  tangentPending_ = false;
}

PairIterationSummary ContactPair::update(const Vector& u, const Vector& bulkResidual, bool updateSet,
                                         ContactContributions& out, bool deferTangent) {
  COULOMB_CHECK(!formulation_->needsMultipliers(), "update() of a pair in the saddle-point form");
  searchAndIntegrate(u);
  return updateNodes(&bulkResidual, nullptr, updateSet, deferTangent, out);
}

PairIterationSummary ContactPair::updateSaddlePoint(const Vector& u, const std::vector<std::array<double, 3>>& z,
                                                    bool updateSet, ContactContributions& out) {
  COULOMB_CHECK(formulation_->needsMultipliers(), "updateSaddlePoint() of a pair in the condensed form");
  searchAndIntegrate(u);
  return updateNodes(nullptr, &z, updateSet, false, out);
}

}  // namespace coulomb::contact
