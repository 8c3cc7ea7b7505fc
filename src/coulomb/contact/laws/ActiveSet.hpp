#pragma once
/// @file ActiveSet.hpp
/// @brief Contact state of one slave node and the active-set update rule of the
/// augmented Lagrangian (ALM) and penalty formulations, frictionless part.
///
/// Conventions:
///  * g~_j is the weighted gap of MortarPass (g~ = -n.(D x^1 - M x^2), > 0 open),
///    D_j the diagonal dual-mortar entry; g_j = g~_j / D_j is the nodal
///    (pointwise) gap, a length.
///  * lambda_j is the nodal coefficient of the multiplier field
///    lambda_h = sum_j Phi_j lambda_j: a traction (NOT weighted by area). The
///    physical contact traction on the slave is k lambda_j, the nodal contact
///    force on the slave is k D_j lambda_j (the weighted, pressure × area,
///    quantity), lambda_n = n_j.lambda_j <= 0 in compression (seed 4.60a), and
///    the contact pressure written to output is p_j = -k lambda_n (>= 0 in
///    compression) = -(n.(k D_j lambda_j)) / D_j.
///  * eps_n is a physical penalty (pressure per length, e.g. defaultPenalty).
///    With the nodal penalty eps^_j = eps_n / D_j the seed's nodal formulas
///    (4.72b, 4.74) hold literally with weighted gaps: k lambda_n + eps^_j g~_j.
///  * Contact forces ACTING ON the bodies (external loads, subtracted from the
///    residual r_u = f_int - f_ext): slave node j f_j = k t D_j lambda_j,
///    master node l f_l = -k t M_jl lambda_j (t the 2D thickness). With
///    lambda_n < 0 f_j points away from the master (n points from the slave
///    towards it): compression pushes the bodies apart, and for a matching
///    interface (M_jl = D_j delta_jl) f_j + f_l = 0. (4.72a) prints the
///    opposite signs (+k D^T on the slave rows), consistent with lambda_n >= 0
///    in compression; with the seed's own zone lambdā_n <= 0 (4.60a, 4.74)
///    that force would attract, so the signs here are those of the
///    functional's coupling term k lambda.(M x^2 - D x^1).
///
/// Update rule (seed 4.73/4.74, ALM): augmented normal multiplier
///   lambdā_n = k n.lambda + eps_n g~_j / D_j ;  active iff lambdā_n <= 0.
/// The contact zone is lambdā_n <= 0 as in (4.60a); (4.73) writes the active set
/// with a strict "< 0": the two differ only at lambdā_n = 0 exactly, where both
/// branches of the rows agree (k lambda_n = -eps_n g~ / D), so the choice is
/// immaterial for the solution; we follow (4.60a).
/// Penalty (4.74): threshold eps_n g~_j, active iff g~_j <= 0.
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace coulomb::contact {

/// @brief Contact state of one slave node; the values are the output codes
/// (contact_state): 0 open, 1 in contact and sliding (every active node of a
/// frictionless pair: the seed's pure slip without friction; the slip branch
/// of a frictional law), 2 in contact and sticking. "In contact" is
/// isActive(), never a comparison with one of the two active states.
enum class ContactState : int { Inactive = 0, Slip = 1, Stick = 2 };

/// Active (sliding or sticking).
inline bool isActive(ContactState state) { return state != ContactState::Inactive; }

/// "Inactive" / "Slip" / "Stick".
const char* toString(ContactState state);
std::ostream& operator<<(std::ostream& out, ContactState state);

/// @brief ALM update rule (4.73/4.74): Active iff the augmented normal
/// multiplier lambdā_n = k lambda_n + eps_n g~ / D (seed 4.59; D > 0) is at
/// most eps_n × `touching`.
/// `touching` (a length, default 0) counts surfaces that touch to within it
/// as closed: surfaces that touch in the mesh have weighted gaps of ±1e-17,
/// whose sign the last bits of the coordinates decide (and with it the
/// first active set, differently in mm and in m). A node kept active by it
/// carries at most eps_n × touching of tension.
ContactState almContactState(double lambdaN, double weightedGap, double D, double k, double epsN,
                             double touching = 0.0);

/// @brief Stick/slip update rule of an active node (seed 4.75-4.77) with the
/// slip hysteresis: `tangentNorm` = |augmented tangential multiplier|
/// (traction), `threshold` = the friction law's threshold (traction, >= 0).
/// A node that slipped at the previous iterate keeps slipping while
/// tangentNorm > (1 - slipThreshold) × threshold; any other node slips when
/// tangentNorm > threshold (1 + 1e-10): a node on the cone to round-off
/// stays stick, so that the rank count cannot decide; with a zero threshold
/// any tangential load slips. Returns Active (= slip) or Stick.
ContactState stickSlipState(double tangentNorm, double threshold, ContactState previous, double slipThreshold);

/// @brief Slip Reset Frequency n (> 0): whether slipping nodes restart as
/// stick in the sub-steps of deck step `deckStep` (1-based): steps 1, 1 + n,
/// 1 + 2n, ... The count is the deck's load steps, so a cutback (or a load
/// knot) that splits a step into sub-steps neither shifts the pattern nor
/// adds resets: every sub-step of a reset step resets, no other does.
/// n <= 0: never.
inline bool resetsSlip(int frequency, int deckStep) { return frequency > 0 && (deckStep - 1) % frequency == 0; }

/// @brief Per-interface summary of an active set.
struct ActiveSetSummary {
  std::size_t nodes = 0;     ///< number of slave nodes
  std::size_t active = 0;    ///< nodes in an active state (sliding or sticking)
  std::size_t inactive = 0;  ///< nodes in the Inactive state
  std::size_t stick = 0;     ///< active nodes that stick (frictional pairs)
  std::size_t changed = 0;   ///< nodes that changed between inactive and active
  std::size_t stickSlipChanged = 0;  ///< active nodes that changed between stick and slip
  /// Converged active and stick/slip sets (Algorithm 3, line 19): no node changed.
  bool unchanged() const { return changed == 0 && stickSlipChanged == 0; }
  /// Adds the counts of another part (e.g. another rank's nodes).
  ActiveSetSummary& operator+=(const ActiveSetSummary& other);
};

/// Counts `state` (now) against `previous` into the summary.
void countState(ActiveSetSummary& summary, ContactState state, ContactState previous);

/// The state of a node at an iterate: the update rule's `rule` when the set
/// is updated; else the frozen `previous` (simplified semi-smooth Newton),
/// a disagreeing rule counted in `violations`.
inline ContactState nextState(ContactState rule, ContactState previous, bool updateSet, long long& violations) {
  if (updateSet) return rule;
  if (rule != previous) ++violations;
  return previous;
}

}  // namespace coulomb::contact
