#pragma once
/// @file ContactPair.hpp
/// @brief One contact pair at run time: its interface, search, nodal normals,
/// mortar pass, the state of its owned slave nodes (active set, normal
/// multiplier), and its contributions to the condensed Newton system.
///
/// The system (docs/architecture.md, "Contact in the Newton system"):
///   F(u) = T (r(u) - f_c) + g,       J = T (K + K_c) + G,
/// r, K the bulk residual and tangent, f_c the contact forces on the bodies,
/// K_c = -d f_c / d u; condensed pairs (ALM, MPC) replace the free rows of
/// each active slave node (T - I) by its contact conditions and put the
/// recovered force on the master rows (g, G), so the multipliers never
/// appear; penalty pairs have T = I. Prescribed DoFs keep their identity
/// rows and are left out as columns (the bulk tangent zeroes them too).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/ContactContributions.hpp"
#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"
#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/contact/interface/MortarPass.hpp"
#include "coulomb/contact/interface/SharpEdges.hpp"
#include "coulomb/contact/SlaveTransform.hpp"
#include "coulomb/contact/formulation/Formulation.hpp"
#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"

namespace coulomb::contact {

class ContactPair {
public:
  /// Collective. The materials of `model` give the automatic penalty
  /// (AutomaticPenalty.hpp) and the slave block's 2D thickness (1 in 3D);
  /// the settings and `form` the formulation (makeFormulation).
  ContactPair(const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedDofMap, const ContactPairSettings& settings,
              const fem::ModelSettings& model, ContactSystemForm form);
  ~ContactPair();

  const ContactPairSettings& settings() const { return settings_; }
  const ContactInterface& interface() const { return *interface_; }
  /// The slave surface has Quad8 / Tri6 faces (SlaveTransform.hpp).
  bool transformedSlaves() const { return slaveTransform_->active(); }

  /// A new (sub-)step of deck step `deckStep` (1-based; StepController::nominalStep):
  /// the next update searches; the state is saved for restoreStep().
  void beginStep(int deckStep);
  /// The step failed (cutback): back to the state saved by beginStep().
  void restoreStep();

  /// Collective: contact quantities at displacement `u` (owned map) with bulk
  /// residual `bulkResidual` (same map; used to recover lambda_n), active-set
  /// update when `updateSet`, and the contributions appended to `out`.
  /// Throws coulomb::Error (every rank) when a node penetrates deeper than
  /// the search radius. `deferTangent`: the residual part of the rows alone;
  /// emitTangent() adds the tangent part when the tangent is asked for (the
  /// last update of a step, Newton's converged iterate, needs none: there
  /// the derivative pass is a fifth of a quadratic contact's time).
  PairIterationSummary update(const Vector& u, const Vector& bulkResidual, bool updateSet,
                              ContactContributions& out, bool deferTangent = false);
  /// Collective: the tangent part of the last update's rows (made with
  /// deferTangent), appended to `out`, at the same state.
  void emitTangent(ContactContributions& out);
  /// The last update deferred its tangent part and emitTangent() has not run.
  bool tangentPending() const { return tangentPending_; }

  /// Saddle-point form: this pair's multiplier unknowns z_j are the global
  /// DoFs first + dim × (index in slaveNodes()) + component.
  void setMultiplierOffset(GlobalOrdinal first) { multiplierBlockOffset_ = first; }
  GlobalOrdinal multiplierDof(int slaveIndex, int c) const {
    return multiplierBlockOffset_ + static_cast<GlobalOrdinal>(dim_ * slaveIndex + c);
  }
  /// update() of the saddle-point form (MultiplierBlock): `z` holds the
  /// multiplier unknowns of the owned slave nodes (ownedSlaveNodes() order);
  /// the active set follows (4.74) with lambda = (eps_n / k) z.
  PairIterationSummary updateSaddlePoint(const Vector& u, const std::vector<std::array<double, 3>>& z, bool updateSet,
                                         ContactContributions& out);

  /// Per owned slave node (ContactInterface::ownedSlaveNodes() order).
  struct NodeOutput {
    long long node = -1;
    double pressure = 0, weightedGap = 0, gap = 0;
    /// D_j: the mortar weight of the node, its share of the slave surface
    /// in contact with the master (current configuration; force = D_j x traction).
    double area = 0;
    double penalty = 0;  ///< eps_n of the node
    /// SlaveNodeState::augmentedPressure, augmentedTraction (tangential, frictional pairs).
    double augmentedPressure = 0;
    std::array<double, 3> augmentedTraction{};
    std::array<double, 3> normal{}, multiplier{};
    /// Frictional pairs: tangential traction on the slave, weighted slip
    /// increment of the step (seed sign, 4.69b), accumulated slip of the
    /// slave relative to the master (length).
    std::array<double, 3> tangentialTraction{}, weightedSlip{}, slip{};
    ContactState state = ContactState::Inactive;
  };
  std::vector<NodeOutput> nodeOutput() const;

  /// Console notes of this pair since the last call (identical on every rank),
  /// e.g. a search radius widened for bodies that overlap.
  std::vector<std::string> takeNotes();

  /// Friction law, stick/slip state and slip of this pair (FrictionalNode.hpp).
  bool frictional() const { return settings_.frictional(); }

private:
  /// Collective: the candidate search (searchCandidates), then the faces
  /// that make the normals of sharp slave nodes (SharpEdges.hpp).
  void search();
  /// Collective: the candidate search at x_, widening the radius when slave
  /// nodes lie inside the master beyond it (SearchResult::unpairedDepth).
  void searchCandidates();
  /// The slave nodes whose normals computeNodalNormals needs on this rank:
  /// those of the integrated faces and the owned ones (increasing).
  std::vector<int> neededSlaveNodes() const;
  void searchAndIntegrate(const Vector& u);
  /// searchAndIntegrate at x_ (the search when due, the normals, D, M, g~).
  void integrateCurrentConfiguration();
  /// The weight of the objective slip form of entry's node at x_ from its
  /// coverage, the deviation |D_j - S_j| / S_j (S_j its D_j under a covering
  /// master, nodalSupportMeasures, support_): 1 up to 2.5e-4 (its support lies
  /// on the master), 0 from 1e-3 (partly off it), smooth between; and its
  /// derivative d weight / dx where it is neither 0 nor 1 (entry with
  /// derivatives; ContactPairSlip.cpp).
  double objectiveWeight(const NodalMortarEntry& entry, DerivativeRow* derivative) const;
  /// S_j of a node with an entry in mortar_ (support_).
  double supportMeasure(long long node) const;
  /// Whether entry's node (of mortar_) is a contact node at x_: D_j above the
  /// round-off (minimumD_) and at least 5 % of S_j. The dual basis
  /// is biorthogonal on the whole support only (Cichosz and Bischoff 2011):
  /// on a support mostly off the master, g~_j / D_j is a mean of the gap
  /// with large negative weights, no gap (sliding_sphere_3d on HEX20: a node
  /// 0.8 mm outside the die's rim, 2 mm below it, 0.5 % covered, had
  /// g~ / D = -7.9 mm and entered and left the set at every iterate).
  bool contactWeight(const NodalMortarEntry& entry) const;
  /// The derivative pass for the owned slave nodes flagged (ownedSlaveNodes() order).
  void differentiate(const std::vector<char>& ownedFlags);
  /// The one loop over the owned slave nodes (after searchAndIntegrate):
  /// stage 1 the formulation decides each node's state from the values,
  /// stage 2 it emits each node's rows with the derivatives. `bulkResidual`
  /// for the condensed forms, `z` for the saddle-point form (else null).
  PairIterationSummary updateNodes(const Vector* bulkResidual, const std::vector<std::array<double, 3>>* z,
                                   bool updateSet, bool deferTangent, ContactContributions& out);
  /// Stage 2 of updateNodes (and emitTangent): each owned node's rows of the
  /// parts asked for (RowSink::residualPart, tangentPart; the tangent part
  /// runs the derivative pass for derivativeFlags_), then the transformed
  /// slave rows (SlaveTransform::toSystemRows, `condensed` with the
  /// residual part; `residual(node, c)` the bulk residual there).
  void emitRows(bool residualPart, bool tangentPart, bool condensed, ContactContributions& out,
                PairIterationSummary& summary, const std::function<double(long long, int)>& residual);
  /// Owned node i as the formulation sees it; `derivatives`: with the
  /// derivative pass's entries (stage 2, when it differentiated the node).
  SlaveNode slaveNode(std::size_t i, bool derivatives);
  /// Weighted slip w_j of the step (seed sign) and, when `derivative` is
  /// given, dw_c / dx as three rows (ContactPairSlip.cpp).
  std::array<double, 3> weightedSlip(const NodalMortarEntry& entry, std::array<DerivativeRow, 3>* derivative) const;
  /// A message when an active node penetrates deeper than the search radius
  /// (empty otherwise); records the depth for widenSearchRadius().
  std::string penetrationFailure(long long node, double gap, double D);
  /// Collective: after a pass over the nodes, a penetration deeper than the
  /// search radius on any rank widens the radius to twice the deepest one
  /// for every later search of the run (the iterate is then rejected by the
  /// caller's failure, and the step retried with the wider search).
  void widenSearchRadius();
  /// Sums the summary over ranks.
  void reduceSummary(PairIterationSummary& summary) const;
  /// The force increments of the summary (PairIterationSummary::normalIncrement2
  /// etc.) from the node states `before` this update to nodes_.
  void addForceIncrements(const std::vector<SlaveNodeState>& before, PairIterationSummary& summary) const;

  const mesh::Mesh& mesh_;
  Teuchos::RCP<const Map> dofMap_;
  ContactPairSettings settings_;
  std::unique_ptr<ContactInterface> interface_;
  std::unique_ptr<InterfaceGather> gather_;
  /// Quad8 / Tri6 slave faces: their transformed rows (SlaveTransform.hpp).
  std::unique_ptr<SlaveTransform> slaveTransform_;
  int dim_;
  PairConstants constants_;
  std::unique_ptr<Formulation> formulation_;
  double radius_ = 0, minimumD_ = 0;
  /// eps_n per owned slave node (ownedSlaveNodes() order): the deck's
  /// `Penalty`, or the automatic one (AutomaticPenalty.hpp).
  std::vector<double> penalty_;
  GlobalOrdinal multiplierBlockOffset_ = 0;  ///< saddle-point form: first global index of z
  /// prescribed_[i][c]: component c of interface node i is a Dirichlet DoF.
  std::vector<std::array<bool, 3>> prescribed_;
  bool searched_ = false;
  double deepest_ = 0.0;         ///< this pass: deepest penetration beyond the radius (this rank)
  double widenedRadius_ = 0.0;   ///< the search radius never goes below this (widenSearchRadius)
  long long droppedSelfLinks_ = 0;  ///< self contact: links without roles at the last search (a note when it changes)
  /// The slave faces this rank integrates (indices into slaveFaces()): those
  /// of its elements, or after balancing (Interface Distribution).
  std::vector<int> integratedFaces_;
  SearchResult search_;
  /// At the last search: the faces whose normals make each sharp slave
  /// node's normal (SharpEdges.hpp); and whether the console had the note
  /// on the first search that found sharp nodes.
  SlaveNormalFaces normalFaces_;
  bool sharpEdgesNoted_ = false;
  std::vector<std::string> notes_;    ///< console notes not yet taken (takeNotes)
  InterfaceConfiguration x_;          ///< current interface coordinates (last update)
  std::vector<NodalNormal> normals_;  ///< by slave node index, values
  NodalMortarQuantities mortar_;      ///< owned slave nodes, values
  /// Per mortar_ entry: its D_j under a covering master at x_ (nodalSupportMeasures).
  std::vector<double> support_;
  /// The same with derivatives, for the nodes stage 2 needs.
  std::vector<NodalNormal> normalDerivatives_;
  NodalMortarQuantities mortarDerivatives_;
  /// The owned slave nodes (ownedSlaveNodes() order): now and at the step start.
  std::vector<SlaveNodeState> nodes_, stepStart_;
  // Friction: the mortar operators and interface coordinates of the last
  // converged state (D^t, M^t, x^t of 4.69) and per owned node the slip
  // accumulated over the steps before this one.
  NodalMortarQuantities stepStartMortar_;
  InterfaceConfiguration stepStartX_;
  /// Per stepStartMortar_ entry: objectiveWeight at the step start (the
  /// objective slip needs the support on the master then, weightedSlip).
  std::vector<double> stepStartWeight_;
  std::vector<double> stepStartSupport_;  ///< support_ of stepStartMortar_
  std::vector<std::array<double, 3>> accumulatedSlip_;
  /// The weighted slip of the last converged step (the slip direction of
  /// Slip Reset Frequency < 0); kept through a restoreStep().
  std::vector<std::array<double, 3>> lastStepSlip_;
  bool restored_ = false;  ///< restoreStep() ran since the last beginStep()
  /// Stage 1's results for stage 2 (ownedSlaveNodes() order): which nodes
  /// the derivative pass covers, each node's (transformed) bulk residual and
  /// multiplier unknowns; and whether the tangent part is still to come.
  std::vector<char> derivativeFlags_;
  std::vector<std::array<double, 3>> nodeResidual_, nodeMultiplier_;
  bool tangentPending_ = false;
};

}  // namespace coulomb::contact
