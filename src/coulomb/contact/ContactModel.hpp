#pragma once
/// @file ContactModel.hpp
/// @brief All contact pairs of a run and the condensed Newton system they
/// make with the bulk (ContactPair.hpp gives the formulas):
///   F(u) = T (r - f_c) + g,   J = T (K + K_c) + G.
/// The model evaluator calls update() at each new iterate (after the bulk
/// residual), then condenseResidual() and, for the tangent,
/// condensedTangent(). The state (active set, multipliers) is a function of
/// the iterates seen so far in the step.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "coulomb/contact/ActiveSetCycle.hpp"
#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/contact/PairChaining.hpp"
#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/core/TpetraTypes.hpp"

namespace coulomb::contact {

/// @brief What the last update found, summed over pairs and ranks.
struct ContactIterationSummary {
  ActiveSetSummary activeSet;
  double normalResidual = 0;  ///< ||eps_n t g~|| over active ALM nodes [force]
  double contactForce = 0;    ///< ||f_j|| over active slave nodes [force]
  double stickResidual = 0;   ///< ||stick rows|| (frictional pairs) [force]
  double slipResidual = 0;    ///< ||slip rows|| (frictional pairs) [force]
  double tangentialForce = 0;  ///< ||tangential parts of f_j|| over active slave nodes [force]
  bool frictional = false;    ///< some pair has friction (the stick/slip columns are printed)
  /// ||change of the nodal contact forces since the last update|| by group
  /// (normal, stick, slip) [force]: PairIterationSummary::normalIncrement2.
  double normalIncrement = 0, stickIncrement = 0, slipIncrement = 0;
  /// One test of a group: met when value <= limit.
  struct Criterion {
    const char* name;
    double value, limit;
  };
  /// The tests in effect (ContactSettings::criterion): the normal group, and
  /// the stick and slip groups unless the tangential forces are negligible
  /// against the contact forces (at most the tangential / normal ratio:
  /// nearly frictionless contact, the seed's normal-tangent ratio; their
  /// rows stay in the residual test). Residual: the rows of (4.78);
  /// Increment, Mixed: the change of the nodal contact forces by group.
  std::vector<Criterion> criteria(const ContactSettings& s) const {
    const bool increments = s.criterion != ConvergenceCriterion::Residual;
    std::vector<Criterion> out{{"normal contact rows", increments ? normalIncrement : normalResidual,
                                s.normalRelativeTolerance * contactForce + s.normalAbsoluteTolerance}};
    if (tangentialForce <= s.tangentNormalRatio * contactForce) return out;
    out.push_back({"stick rows", increments ? stickIncrement : stickResidual,
                   s.stickRelativeTolerance * contactForce + s.stickAbsoluteTolerance});
    out.push_back({"slip rows", increments ? slipIncrement : slipResidual,
                   s.slipRelativeTolerance * contactForce + s.slipAbsoluteTolerance});
    return out;
  }
  /// Every test of criteria() met.
  bool criteriaMet(const ContactSettings& s) const {
    for (const Criterion& c : criteria(s))
      if (c.value > c.limit) return false;
    return true;
  }
};

class ContactModel {
public:
  /// Collective; throws coulomb::Error naming the pair on bad sets. Pairs
  /// whose slave surfaces share nodes are joined into one pair named "a+b"
  /// (PairMerging.hpp): pairs() and the output name that one.
  ContactModel(const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedDofMap, const ContactSettings& settings,
               const fem::ModelSettings& model);
  ~ContactModel();

  bool empty() const { return pairs_.empty(); }
  const ContactSettings& settings() const { return settings_; }
  const std::vector<std::unique_ptr<ContactPair>>& pairs() const { return pairs_; }
  /// True when some pair has friction.
  bool anyFrictional() const;
  /// True when some pair is ALM or frictional: the tangent is not symmetric.
  bool needsNonsymmetricSolver() const;

  /// A sub-step of deck step `deckStep` (1-based) begins / failed (ContactPair).
  void beginStep(int deckStep);
  void restoreStep();
  /// Collective, after a converged step at time `time`: throws coulomb::Error
  /// (on every rank) naming the first pair with 'Ensure Contact' that has no
  /// active slave node.
  void checkContact(double time) const;

  /// Collective: contact state at `u` with bulk residual `bulkResidual`,
  /// contributions stored for the two calls below. `freezeSet`: keep the
  /// active set whatever the semi-smooth Newton mode says (derivative checks).
  void update(const Vector& u, const Vector& bulkResidual, bool freezeSet = false);
  /// residual := T (residual - f_c) + g   (residual: the bulk residual of the same u).
  void condenseResidual(Vector& residual) const;
  /// Collective: reactions -= the contact forces that the last update put on
  /// prescribed DoFs (ContactContributions::prescribedForce). The bulk
  /// reaction f_int - f_ext of a prescribed DoF of an interface node is the
  /// support's force plus the contact force acting there (which the system
  /// leaves out: those rows are u - u_bar); after this call it is the
  /// support's force alone, e.g. a pusher's including the friction of its
  /// slave nodes. Condensed and penalty forms; a no-op without such forces.
  void subtractPrescribedForces(Vector& reactions) const;
  /// J = T (K + K_c) + G as a matrix that the next call may overwrite in place
  /// (same pattern: the values are replaced); K unchanged; K itself when no pair contributes.
  Teuchos::RCP<CrsMatrix> condensedTangent(const Teuchos::RCP<CrsMatrix>& bulkTangent) const;
  /// The last condensed tangent (null before the first): the model
  /// evaluator assembles the next K straight into it when the assembler
  /// accepts it, and condensedTangent() then adds the interface rows in
  /// place — K never has a matrix of its own (hertz3d_r2: 39 MB less at the peak).
  Teuchos::RCP<CrsMatrix> tangentStorage() const { return tangentSum_.last(); }
  /// The storage holds many couplings the contact no longer has (a sliding
  /// contact leaves them as zeros, as the pattern only grows in place): more
  /// than twice the interface triplets of the last iterate (the ones not
  /// negligible, linalg::MatrixSum) beyond K's. Local.
  bool tangentStorageStale() const { return tangentSum_.grownBeyond(2.0); }
  /// The storage turned back into the K of the last condensedTangent() call
  /// (linalg::MatrixSum::restoreBase): for a constant K (linear elasticity)
  /// the model evaluator uses it instead of assembling K again. False when
  /// there is no storage yet or the storage lacks an entry of K (then partly
  /// rewritten: K must be assembled into it or apart). Local.
  bool restoreBulkTangent() const { return tangentSum_.restoreBase(); }
  /// Successful restoreBulkTangent() calls (tests).
  int bulkTangentRestores() const { return tangentSum_.restores(); }

  /// `Contact/System Form` = Saddle Point: the multipliers are Newton
  /// unknowns (MultiplierBlock in ContactPair.hpp) instead of being condensed.
  bool saddlePoint() const { return settings_.systemForm == ContactSystemForm::SaddlePoint; }
  /// The unknowns of the saddle-point form: the owned displacement DoFs (the
  /// DoF map's, in its order, so a displacement vector is the leading part of
  /// the local data) then the owned multiplier DoFs. Null when condensed.
  const Teuchos::RCP<const Map>& saddlePointMap() const { return saddlePointMap_; }
  /// Saddle-point form: u := the displacement part of x (its leading local
  /// entries), and the reverse (x's multiplier part untouched). No communication.
  static void displacementPart(const Vector& x, Vector& u);
  static void setDisplacementPart(const Vector& u, Vector& x);
  /// Collective, saddle-point form: the contact state at x = (u, z), `u` its
  /// displacement part (on the DoF map).
  void updateSaddlePoint(const Vector& x, const Vector& u, bool freezeSet = false);
  /// Saddle-point form: f := (r - f_c, R) on saddlePointMap(), r the bulk residual at u.
  void saddlePointResidual(const Vector& bulkResidual, Vector& f) const;
  /// Saddle-point form: the tangent [K + K_c, C; dR/du, dR/dz] as a new matrix.
  Teuchos::RCP<CrsMatrix> saddlePointTangent(const CrsMatrix& bulkTangent) const;

  /// The contributions of the last update (the saddle-point form included).
  const ContactContributions& contributions() const { return contributions_; }
  const ContactIterationSummary& lastSummary() const { return summary_; }
  /// Per pair (pairs() order), the figures of the last update.
  const std::vector<PairIterationSummary>& pairSummaries() const { return pairSummaries_; }
  /// Converged: active set unchanged at the last update and the normal test met.
  bool converged() const;
  /// Which contact criteria the last update did not meet, for the message
  /// of a step that ran out of iterations ("the active set (2 nodes changed
  /// state), the slip rows (||.|| = 3e-2 > 1e-4)"); empty when all are met.
  std::string unmetCriteria() const;
  /// The sets of this step's iterates cycle (ActiveSetCycle): its period, or 0.
  int cyclePeriod() const { return cycle_.period(); }
  /// What cycles, for the console (empty when cyclePeriod() is 0).
  std::string cycleDescription() const { return cycle_.describe(); }

  /// Owned-node fields for output, in nodalFieldNames() order.
  std::vector<std::string> nodalFieldNames() const;
  void nodalFields(const Teuchos::RCP<const Map>& ownedNodeMap, MultiVector& fields) const;
  /// Per pair: contact force on the slave body (dim components) and the active node count.
  std::vector<std::string> globalNames() const;
  std::vector<double> globals() const;

private:
  /// The loop over pairs of update() and updateSaddlePoint(): `updatePair(p, updateSet)`.
  template <class UpdatePair>
  void updatePairs(bool freezeSet, UpdatePair&& updatePair);

  ContactSettings settings_;
  /// The order of the condensed updates and the rows of slave nodes that
  /// are other pairs' master nodes (null in the saddle-point form).
  std::unique_ptr<PairChaining> chaining_;
  /// A pair has Quad8 / Tri6 slave faces: condensation coefficients may
  /// refer to other ranks' rows of K (condensedTangent routes them).
  bool transformedSlaves_ = false;
  Teuchos::RCP<const Map> saddlePointMap_;
  int dim_;
  Teuchos::RCP<const Map> map_;
  std::vector<std::unique_ptr<ContactPair>> pairs_;
  std::vector<PairIterationSummary> pairSummaries_;
  ContactIterationSummary summary_;
  int updatesInStep_ = 0;
  ActiveSetCycle cycle_;  ///< the sets of this step's iterates
  Teuchos::RCP<CrsMatrix> transform_;  ///< T - I (for the residual)
  /// The last update's rows; condensedTangent() appends their tangent part
  /// when an update deferred it (ContactPair::emitTangent), hence mutable.
  mutable ContactContributions contributions_;
  mutable std::vector<linalg::MatrixTriplet> interfaceRows_;  ///< condensedTangent's rows, memory reused per iterate
  mutable linalg::MatrixSum tangentSum_;  ///< J = K + [...] with buffers (and J itself) reused per iterate
  bool contributes_ = false;  ///< some rank has transform or stiffness entries
};

}  // namespace coulomb::contact
