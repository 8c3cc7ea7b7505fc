#pragma once
/// @file ContactPair.hpp
/// @brief One contact pair at run time: its interface, search, nodal normals,
/// mortar pass, the state of its owned slave nodes (active set, normal
/// multiplier), and its contributions to the condensed Newton system.
///
/// The system (docs/architecture.md, "Contact in the Newton system"):
///   F(u) = T (r(u) - f_c) + g,       J = T (K + K_c) + G,
/// r, K the bulk residual and tangent, f_c the contact forces acting on the
/// bodies, K_c = -d f_c / d u, and for ALM pairs
///   T = I + (row recombination of CondensationFrame, and the master rows
///       += M_jl n_j,c / (D_j |n_F|) × the a-row of slave node j),
///   g, G  = the scaled weighted gap sign ε_n t g~_j and its derivative, in
///           the gap slot of each active slave node,
/// so that the multipliers never appear: T f_c = 0 identically for ALM (the
/// condensation of the dual multipliers, D diagonal), and lambda_n is
/// recovered from the slave rows of the bulk residual,
///   lambda_n,j = a_j . r_{j,F} / (k t D_j |n_F|)   (equilibrium of the a-row).
/// Penalty pairs: T = I, f_c = the penalty forces of NodalContactLaw.
/// t is the 2D thickness (1 in 3D): contact forces scale like the bulk.
///
/// Prescribed DoFs keep their identity rows (nothing is added to them) and
/// are left out as columns (the bulk tangent zeroes those columns too).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "coulomb/contact/ActiveSet.hpp"
#include "coulomb/contact/ContactInterface.hpp"
#include "coulomb/contact/ContactSearch.hpp"
#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/contact/FrictionalNode.hpp"
#include "coulomb/contact/MortarPass.hpp"
#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"

namespace coulomb::contact {

/// @brief The uncondensed (u, lambda_n) Newton system of the active ALM
/// nodes, for checking the condensation: lambda_n of slave node j is the DoF
/// dim × (number of mesh nodes) + j, owned by the node's owner.
///   [K + K_c   C] [du]     [r - f_c]
///   [  G_s     0] [dl] = - [  g_s  ]
struct SaddlePointContributions {
  std::vector<linalg::MatrixTriplet> columns;  ///< C = -d f_c / d lambda_n
  std::vector<linalg::MatrixTriplet> rows;     ///< G_s = d (eps_n t g~) / du
  std::vector<linalg::VectorEntry> gap;        ///< g_s = eps_n t g~
  std::vector<linalg::VectorEntry> force;      ///< -f_c with the current lambda_n
};

/// @brief The Newton system with the multipliers as unknowns (deck
/// `Contact/System Form` = Saddle Point; ContactPairSaddlePoint.cpp): per
/// slave node j a vector unknown z_j = (k / eps_n) lambda_j (a length, so that
/// its columns t eps_n D_j are of the size of the stiffness), and the rows
/// R_j = (eps_n t / k) r_lambda_j of NodalContactLaw (4.72b, components form):
///   [K + K_c   C] [du]     [r - f_c]
///   [  R_u   R_z] [dz] = - [  R    ]
struct MultiplierBlock {
  std::vector<linalg::MatrixTriplet> columns;  ///< C = -d f_c / d z (displacement rows)
  std::vector<linalg::MatrixTriplet> rows;     ///< d R / d (u, z) (multiplier rows)
  std::vector<linalg::VectorEntry> residual;   ///< R (multiplier rows)
};

/// @brief Contributions of one or more pairs to the condensed system.
struct ContactContributions {
  std::vector<linalg::MatrixTriplet> transform;   ///< T - I
  /// Added to T - I for the tangent only: frictional rows are nonlinear in
  /// the bulk residual r (their value is in constraintResidual, their
  /// derivative with respect to r combines rows of K here).
  std::vector<linalg::MatrixTriplet> tangentTransform;
  std::vector<linalg::MatrixTriplet> constraint;  ///< G
  std::vector<linalg::VectorEntry> constraintResidual;  ///< g
  std::vector<linalg::MatrixTriplet> contactStiffness;  ///< K_c
  std::vector<linalg::VectorEntry> contactResidual;     ///< -f_c (penalty pairs)
  /// f_c on prescribed DoFs (interface nodes on a Dirichlet set): not in the
  /// system (those rows are u - u_bar), carried by the support
  /// (ContactModel::subtractPrescribedForces).
  std::vector<linalg::VectorEntry> prescribedForce;
  SaddlePointContributions saddle;                      ///< ALM pairs, uncondensed form
  MultiplierBlock multipliers;  ///< System Form = Saddle Point (then transform etc. stay empty)
};

/// @brief Per-update figures of one pair, summed over ranks.
struct PairIterationSummary {
  ActiveSetSummary activeSet;
  double normalResidual2 = 0;  ///< sum of (eps_n t g~_j)^2 over active ALM nodes
  double contactForce2 = 0;    ///< sum of |f_j|^2 over active slave nodes
  double stickResidual2 = 0;   ///< sum of the squared stick rows (frictional pairs)
  double slipResidual2 = 0;    ///< sum of the squared slip rows (frictional pairs)
  double tangentialForce2 = 0;  ///< sum of |tangential part of f_j|^2 over active slave nodes (frictional pairs)
  std::array<double, 3> slaveForce{};  ///< total contact force on the slave body
  std::array<double, 3> normalForce{};  ///< its normal part, sum of the nodal normal forces
  std::array<double, 3> tangentialForce{};  ///< its tangential part
  /// Nodes whose frozen state (simplified semi-smooth Newton) disagrees with
  /// the update rule at this iterate; 0 when the set was updated.
  long long violations = 0;
  /// A hash of every slave node's state (the same on every rank and for any
  /// partition): equal sets have equal signatures (ActiveSetCycle).
  std::uint64_t setSignature = 0;
};

class ContactPair {
public:
  /// Collective. The materials of `model` give the automatic penalty
  /// (AutomaticPenalty.hpp) and the slave block's 2D thickness (1 in 3D).
  ContactPair(const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedDofMap, const ContactPairSettings& settings,
              const fem::ModelSettings& model);
  ~ContactPair();

  const ContactPairSettings& settings() const { return settings_; }
  const ContactInterface& interface() const { return *interface_; }

  /// A new load step: the next update searches; the state is saved for restoreStep().
  void beginStep();
  /// The step failed (cutback): back to the state saved by beginStep().
  void restoreStep();

  /// Collective: contact quantities at displacement `u` (owned map) with bulk
  /// residual `bulkResidual` (same map; used to recover lambda_n), active-set
  /// update when `updateSet`, and the contributions appended to `out`.
  /// Throws coulomb::Error (every rank) when a node penetrates deeper than
  /// the search radius.
  PairIterationSummary update(const Vector& u, const Vector& bulkResidual, bool updateSet,
                              ContactContributions& out);

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
  /// Collective: the candidate search at x_, widening the radius when slave
  /// nodes lie inside the master beyond it (SearchResult::unpairedDepth).
  void search();
  void searchAndIntegrate(const Vector& u);
  void differentiateActive();
  /// The derivative pass for the owned slave nodes flagged (ownedSlaveNodes() order).
  void differentiate(const std::vector<char>& ownedFlags);
  /// update() for frictional pairs (ContactPairFriction.cpp).
  PairIterationSummary updateFrictional(const Vector& bulkResidual, bool updateSet, ContactContributions& out);
  /// The same for the penalty formulation (forces, no condensation).
  PairIterationSummary updatePenaltyFrictional(bool updateSet, ContactContributions& out);
  /// Weighted slip w_j of the step (seed sign) and, when `derivative` is
  /// given, dw_c / dx as three rows.
  std::array<double, 3> weightedSlip(const NodalMortarEntry& entry, std::array<DerivativeRow, 3>* derivative) const;
  /// The message when an active node penetrates deeper than the search radius, else "".
  /// A message when an active node penetrates deeper than the search radius
  /// (empty otherwise); records the depth for widenSearchRadius().
  std::string penetrationFailure(long long node, double gap, double D);
  /// Collective: after a pass over the nodes, a penetration deeper than the
  /// search radius on any rank widens the radius to twice the deepest one
  /// for every later search of the run (the iterate is then rejected by the
  /// caller's failure, and the step retried with the wider search).
  void widenSearchRadius();
  /// Stores the new state of owned node i (friction: an open node has no slip,
  /// and it is marked when it opens) and counts it into the summary.
  void settleState(std::size_t i, ContactState state, ContactState previous, PairIterationSummary& summary);
  /// Surfaces within this length count as touching (closed): 1e-12 of the
  /// slave face size, 1000 times the round-off of coordinates 1000 faces
  /// from the origin (almContactState); the tension it lets an active node
  /// keep, eps_n × 1e-12 h ~ 1e-12 E, is far below the contact tolerances.
  double touchingGap() const { return 1e-12 * faceSize_; }
  /// The kernel parameters of a frictional pair (setNodeParameters adds the node's).
  FrictionalParameters frictionalParameters() const;
  /// Owned node i's (global `node`) eps_n, eps_tau and friction coefficient into p.
  void setNodeParameters(FrictionalParameters& p, std::size_t i, long long node) const;
  /// Sums the summary over ranks.
  void reduceSummary(PairIterationSummary& summary) const;
  GlobalOrdinal dofRow(long long node, int c) const { return static_cast<GlobalOrdinal>(dim_ * node + c); }
  bool isPrescribed(long long node, int c) const;

  const mesh::Mesh& mesh_;
  Teuchos::RCP<const Map> dofMap_;
  ContactPairSettings settings_;
  std::unique_ptr<ContactInterface> interface_;
  std::unique_ptr<InterfaceGather> gather_;
  int dim_;
  double k_ = 1, thickness_ = 1, radius_ = 0, minimumD_ = 0;
  /// eps_n per owned slave node (ownedSlaveNodes() order): the deck's
  /// `Penalty`, or the automatic one (AutomaticPenalty.hpp).
  std::vector<double> penalty_;
  double faceSize_ = 1;    ///< h, the mean slave face size
  double referenceD_ = 1;  ///< h^(dim-1): the scale of D_j
  GlobalOrdinal multiplierBlockOffset_ = 0;  ///< saddle-point form: first global index of z
  GlobalOrdinal multiplierOffset_ = 0;  ///< first global index of the lambda_n DoFs (saddle-point form)
  /// prescribed_[i][c]: component c of interface node i is a Dirichlet DoF.
  std::vector<std::array<bool, 3>> prescribed_;
  bool searched_ = false;
  double deepest_ = 0.0;         ///< this pass: deepest penetration beyond the radius (this rank)
  double widenedRadius_ = 0.0;   ///< the search radius never goes below this (widenSearchRadius)
  SearchResult search_;
  std::vector<std::string> notes_;    ///< console notes not yet taken (takeNotes)
  InterfaceConfiguration x_;          ///< current interface coordinates (last update)
  std::vector<NodalNormal> normals_;  ///< by slave node index, values
  NodalMortarQuantities mortar_;      ///< owned slave nodes, values
  /// The same with derivatives, for the active nodes (stage 2 of update()).
  std::vector<NodalNormal> normalDerivatives_;
  NodalMortarQuantities mortarDerivatives_;
  // State of the owned slave nodes (ownedSlaveNodes() order).
  std::vector<ContactState> state_, stepStartState_;
  std::vector<double> lambdaN_, stepStartLambdaN_;
  std::vector<double> pressure_;
  // Friction: the mortar operators and interface coordinates of the last
  // converged state (D^t, M^t, x^t of 4.69), per owned node the traction,
  // the weighted slip of the step and the slip accumulated over the steps.
  NodalMortarQuantities stepStartMortar_;
  InterfaceConfiguration stepStartX_;
  int steps_ = 0;
  std::vector<std::array<double, 3>> traction_, stepStartTraction_, weightedSlip_, slipIncrement_,
      stepStartAccumulatedSlip_;
  /// The weighted slip of the last converged step (the slip direction of
  /// Slip Reset Frequency < 0); kept through a restoreStep().
  std::vector<std::array<double, 3>> lastStepSlip_;
  /// The unit slip direction of each slipping node's rows at the last
  /// iterate (FrictionalNodeInput::previousDirection), and at the step start.
  std::vector<std::array<double, 3>> slipDirection_, stepStartSlipDirection_;
  bool restored_ = false;  ///< restoreStep() ran since the last beginStep()
};

}  // namespace coulomb::contact
