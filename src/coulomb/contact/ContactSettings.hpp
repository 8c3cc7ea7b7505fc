#pragma once
/// @file ContactSettings.hpp
/// @brief The deck's "Contact" sublist as typed values: the contact pairs
/// (slave and master side sets, formulation, penalty, scale factor,
/// semi-smooth Newton mode, search) and the contact convergence tolerances.
#include <algorithm>
#include <string>
#include <vector>

#include "coulomb/contact/laws/FrictionLaw.hpp"

namespace Teuchos {
class ParameterList;
}

namespace coulomb::contact {

/// ALM: Lagrange multipliers on the slave nodes, condensed (exact
/// non-penetration at convergence). Penalty: displacement only, pressure
/// eps_n <-g~> / D (penetration ~ p / eps_n). MPC: multipoint constraints —
/// the slave node tied to the master by the mortar relation (stick: all
/// directions; slip: the normal one, with the Coulomb force of the recovered
/// reaction), states decided by reactions and gaps without penalty
/// (docs/architecture.md, "MPC"). LMM: Lagrange multipliers as unknowns
/// with the NCP functions of seed 4.79 (System Form = Saddle Point;
/// formulation/LagrangeNcp.cpp).
enum class ContactFormulation { ALM, Penalty, MPC, LMM };

/// Full: the active set is updated at every Newton iteration. Simplified:
/// only at the first two evaluations of a load step (the predictor and the
/// first iterate), then frozen — unless the frozen set violates the update
/// rule at an iterate, which then counts as a change (not converged) and
/// opens two more updates.
enum class SemiSmoothNewton { Full, Simplified };

/// Objective: the weighted slip from the change of the mortar operators
/// (seed 4.69b), frame indifferent; NonObjective: from the displacement
/// increments with the current operators (4.65a), kept for comparison.
enum class SlipMeasure { Objective, NonObjective };

/// Condensed: the dual multipliers are eliminated (D diagonal), the Newton
/// system is displacement-only (the production path). SaddlePoint: the
/// multipliers are unknowns of their own (a vector per slave node, a Tpetra
/// DoF block after the displacements), solved by the direct solver: LMM
/// pairs, and a check of the condensation with ALM frictionless pairs.
enum class ContactSystemForm { Condensed, SaddlePoint };

/// Which rank integrates a slave face (the mortar pass): ElementOwners, the
/// rank of its element; Balanced, the faces redistributed over all ranks by
/// their candidates at every search (contact/interface/InterfaceBalance.hpp).
enum class InterfaceDistribution { ElementOwners, Balanced };

/// @brief One contact pair.
struct ContactPairSettings {
  std::string name;    ///< the deck sublist name (messages, output variable names)
  /// Slave side set (the finer / curved side) and master side set; each may
  /// list several sets separated by commas (ContactInterface).
  std::string slave;
  std::string master;
  /// The deck pairs joined into this one because their slave surfaces share
  /// nodes (PairMerging.hpp); empty for a pair as the deck gave it.
  std::vector<std::string> mergedFrom;
  ContactFormulation formulation = ContactFormulation::ALM;
  double penalty = 0.0;        ///< eps_n [force/length^3]; 0: automatic, penaltyFactor × min(E_slave, E_master) / h (ContactPair.cpp)
  double penaltyFactor = 1.0;  ///< factor of the automatic penalty
  double scaleFactor = 1.0;    ///< k of the ALM (lambda = traction / k)
  SemiSmoothNewton semiSmooth = SemiSmoothNewton::Full;
  bool searchEveryIteration = false;  ///< else once per load step
  double searchRadiusFactor = 1.0;    ///< radius = factor × largest slave face diameter
  /// Faces around a slave node whose normals differ by more than this
  /// [degrees] are across a sharp edge; the node takes the normal of the side
  /// facing the master (SharpEdges.hpp). 180: every normal averages all faces.
  double featureAngle = 60.0;
  InterfaceDistribution distribution = InterfaceDistribution::Balanced;
  // Friction (ALM only; FrictionalNode.hpp).
  FrictionLaw friction;               ///< law and its parameters (None: frictionless)
  double tangentFactor = 1.0;         ///< kappa: eps_tau = kappa eps_n
  double slipThreshold = 0.02;        ///< hysteresis of the slip -> stick transition
  double slipAugmentation = 1.0;      ///< alpha of the augmented tangential multiplier of slipping nodes
  /// Slipping nodes restart as stick every n steps (0: never; < 0: never, and
  /// a slipping node's direction is that of its slip in the last converged step).
  int slipResetFrequency = 1;
  SlipMeasure slipMeasure = SlipMeasure::Objective;
  /// Objective slip only where the operators changed over the step:
  /// |D - Dᵗ| + sum |M - Mᵗ| > operatorThreshold × (D + sum |M|), else the
  /// non-objective one (seed: OPERATOR_THRESHOLD). 0: objective whenever the
  /// operators of the last converged state exist.
  double operatorThreshold = 0.0;
  /// The seed's FrictionalPureSlip: every active node is on the slip branch
  /// and carries the law's threshold against its weighted slip (never
  /// sticks): for contacts that slide everywhere (forming, ironing).
  bool pureSlip = false;
  /// The seed's ensure_contact: a converged step with no active slave node
  /// in this pair stops the run with an error (ContactModel::checkContact).
  bool ensureContact = false;
  /// Coulomb's mu per node from a nodal variable of the mesh file (deck
  /// 'Friction Coefficient Field'; loadFrictionFields fills the values,
  /// indexed by global node); empty: friction.coefficient everywhere.
  std::string frictionCoefficientField;
  std::vector<double> nodalFrictionCoefficients;
  /// A frictional pair: a law with a tangential threshold. Every mu zero —
  /// the pair's, or every value of its nodal field once loaded — is the
  /// seed's automatic pure slip with no friction, i.e. frictionless contact.
  bool frictional() const {
    if (!friction.frictionless()) return true;
    if (frictionCoefficientField.empty()) return false;
    return nodalFrictionCoefficients.empty() ||
           std::any_of(nodalFrictionCoefficients.begin(), nodalFrictionCoefficients.end(),
                       [](double mu) { return mu != 0.0; });
  }
  /// mu of global node `node` (the field's value, else the pair's).
  double frictionCoefficient(long long node) const {
    return nodalFrictionCoefficients.empty() ? friction.coefficient
                                             : nodalFrictionCoefficients[static_cast<std::size_t>(node)];
  }
};

/// How a Newton iterate counts as converged besides an unchanged active set
/// (the seed's criteria, 'Contact/Convergence Criterion'). Residual: the
/// residual ||f|| and the contact rows by group (4.78). Increment: the
/// displacement increment (NOX NormWRMS: |du_i| <= Increment Relative
/// Tolerance |u_i| + Increment Absolute Tolerance in the RMS) and the change
/// of the nodal contact forces by group (normal, stick, slip). Mixed: the
/// residual ||f|| and the force changes by group.
enum class ConvergenceCriterion { Residual, Increment, Mixed };

/// @brief Everything about contact in a deck.
struct ContactSettings {
  std::vector<ContactPairSettings> pairs;
  ContactSystemForm systemForm = ContactSystemForm::Condensed;
  /// Normal constraint residual ||eps_n g~||: converged when below
  /// relativeTolerance × ||contact forces|| + absoluteTolerance.
  double normalRelativeTolerance = 1e-6;
  double normalAbsoluteTolerance = 1e-8;
  /// The same tests for the tangential rows of stick and of slip nodes (4.78).
  double stickRelativeTolerance = 1e-6;
  double stickAbsoluteTolerance = 1e-8;
  double slipRelativeTolerance = 1e-6;
  double slipAbsoluteTolerance = 1e-8;
  /// The stick and slip tests are skipped while ||tangential contact forces||
  /// <= this × ||contact forces|| (tangential forces negligible).
  double tangentNormalRatio = 1e-4;
  ConvergenceCriterion criterion = ConvergenceCriterion::Residual;
  double incrementRelativeTolerance = 1e-6;   ///< Increment: |du| against |u|
  double incrementAbsoluteTolerance = 1e-12;  ///< Increment: [length]
};

/// @brief Valid parameters of "Contact" (added to the deck's list).
void addValidContactParameters(Teuchos::ParameterList& valid);

/// @brief Typed settings of a validated deck (no "Contact" sublist: no pairs).
ContactSettings parseContactSettings(const Teuchos::ParameterList& deck);

/// @brief Reads the nodal friction coefficients of the pairs that name a
/// 'Friction Coefficient Field' from the mesh file (last time step of that
/// nodal variable). Throws coulomb::Error naming the pair, file and variable
/// when the variable is missing or a value is negative.
void loadFrictionFields(ContactSettings& settings, const std::string& meshFile);

const char* toString(ContactFormulation formulation);

}  // namespace coulomb::contact
