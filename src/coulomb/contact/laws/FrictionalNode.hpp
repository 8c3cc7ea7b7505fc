#pragma once
/// @file FrictionalNode.hpp
/// @brief Kernel: the condensed rows of one active frictional slave node j
/// (ALM, vector multiplier condensed out; seed 4.62, 4.72b, 4.75-4.77, 4.79)
/// and its stick/slip decision. Fixed-size arrays, no Tpetra, no MPI.
///
/// The formulas (docs/architecture.md, "Contact in the Newton system" and
/// "Frictional contact"): the multiplier recovered from the bulk residual r
/// in the frame of CondensationFrame (a = n_F/|n_F|, tangents b_s),
///   lambda_n = a.r_F / (k t D |n_F|),   beta_s = b_s.r_F / (k t D),
///   lambda   = lambda_n n + sum_s beta_s b_s   (no beta without a law),
/// and the node's free rows replaced by
///   gap slot        : sign eps_n t g~
///   tangent slot s  : stick  -eps_n t (b_s . w)      (no slip, 4.72b st; the
///                                                     sign: a positive diagonal)
///                     slip   b_s.r_F - t D Θ d_s     (traction on the cone, 4.72b sl)
/// with w the weighted slip (seed sign of 4.69b: the master relative to the
/// slave), Θ the law's threshold at lambdā_n = k lambda_n + eps_n g~ / D,
/// and d the unit direction of lambdā_tau = k beta + alpha eps_tau (b.w) / D,
/// so that at a slip solution k beta = Θ d and w ∥ d (the semi-smooth Newton
/// form of the NCP 4.79). A frictionless law is the slip branch with Θ = 0.
/// Driven directions (a tangential component prescribed, the slave moved
/// relative to the master) cannot be condensed: their traction is explicit,
/// the penalty return map (4.71a) on the step's history, its force on the
/// support and the master (docs/architecture.md, "Driven directions").
/// The master rows receive the recovered force k t M_jl lambda (the caller).
///
/// Inputs of the derivatives, in this order: r (dim), n (dim), w (dim), D, g~.
#include <array>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/laws/FrictionLaw.hpp"

namespace coulomb::contact {

/// @brief Parameters of a frictional ALM pair.
struct FrictionalParameters {
  double k = 1.0;                  ///< ALM scale factor
  double epsN = 1.0;               ///< normal penalty eps_n [pressure/length]
  double epsTau = 1.0;             ///< tangential penalty eps_tau = kappa eps_n
  double thickness = 1.0;          ///< t (2D thickness, 1 in 3D)
  double slipAugmentation = 1.0;   ///< alpha > 0
  double slipThreshold = 0.02;     ///< hysteresis of the slip -> stick transition (stickSlipState)
  /// A closing node whose weighted slip is at most roundOffSlip × D (a
  /// length: the round-off of the coordinates) sticks (frictionalState).
  double roundOffSlip = 0.0;
  /// Surfaces closer than this length count as touching, i.e. closed
  /// (frictionalState; almContactState says why).
  double touchingGap = 0.0;
  FrictionLaw law;
  /// MPC: the same rows (ties), states without penalty: the normal decision
  /// and the threshold from the reaction k lambda_n of a tied node (the gap
  /// of an untied one), the stick -> slip test on the reaction |k beta|.
  bool multiPointConstraint = false;
  /// The slip rows take the direction of the node's slip in the last
  /// converged step (FrictionalNodeInput::lastSlip, its tangential part), fixed
  /// for the step — the seed's slip_step_reset_frequency < 0, tangents from
  /// the weighted slip at the step start — instead of the augmented
  /// multiplier's; the augmented one where that slip is zero.
  bool slipDirectionFromSlip = false;
  /// The seed's FrictionalPureSlip: an active node is always on the slip
  /// branch, its direction that of its weighted slip w (the augmented
  /// multiplier's where w is zero).
  bool pureSlip = false;
};

/// Number of inputs of the derivatives: r, n, w (dim each), D, g~.
template <int dim>
inline constexpr int kFrictionalInputs = 3 * dim + 2;

/// @brief One slave node's data (values).
template <int dim>
struct FrictionalNodeInput {
  std::array<double, dim> residual{};  ///< bulk residual r_j at the node [force]
  std::array<double, dim> normal{};    ///< unit nodal normal n_j
  std::array<double, dim> slip{};      ///< weighted slip increment w_j (seed sign)
  double D = 0.0;                      ///< D_j > 0
  double gap = 0.0;                    ///< weighted gap g~_j
  std::array<bool, dim> prescribed{};  ///< Dirichlet components of the node
  /// Prescribed components that move the slave relative to the master (a
  /// pusher, a clamp; not a symmetry plane that the master shares, where the
  /// relative motion across the plane is zero): they carry friction too, as
  /// an explicit traction (the driven directions, see below).
  std::array<bool, dim> driven{};
  std::array<double, dim> oldTraction{};  ///< contact traction k lambda of the last converged step (driven directions)
  std::array<double, dim> lastSlip{};  ///< weighted slip of the last converged step (slipDirectionFromSlip)
  /// Unit slip direction d of the node's slip rows at the previous iterate
  /// (FrictionalNodeRows::direction; zero when it did not slip): a slipping
  /// node that slid against it is set to stick (frictionalState).
  std::array<double, dim> previousDirection{};
};

/// @brief The nodal quantities of the state decision and the output.
template <int dim>
struct FrictionalNodeState {
  ContactState state = ContactState::Inactive;
  double lambdaN = 0.0;          ///< recovered normal multiplier (0 unless recovered)
  double augmentedNormal = 0.0;  ///< lambdā_n
  double threshold = 0.0;        ///< Θ(lambdā_n)
  double tangentNorm = 0.0;      ///< |lambdā_tau| used by the rule
  std::array<double, dim> augmentedTangent{};  ///< lambdā_tau used by the rule (world components)
  std::array<double, dim> traction{};  ///< recovered contact traction on the slave, k lambda
};

/// @brief The update rule (4.73-4.77) for node `in` whose state at the
/// previous iterate was `previous`. The multiplier is recovered from the
/// residual only when `previous` is active (otherwise the node's rows held
/// plain equilibrium and lambda = 0); a node that closes is judged on its
/// augmented values from the stick side (Stick if its slip is at the
/// round-off, FrictionalParameters::roundOffSlip).
/// A slipping node that slid against the direction of its slip rows
/// (`previousDirection`) so far that lambdā_tau points against it sticks
/// instead of slipping the other way (FrictionalNode.cpp, slipReversed: the
/// stick/slip 2-cycle of a stiff punch). A node whose free components hardly
/// see its normal (CondensationFrame::usable false) stays Inactive.
template <int dim>
FrictionalNodeState<dim> frictionalState(const FrictionalNodeInput<dim>& in, ContactState previous,
                                         const FrictionalParameters& p);

/// @brief The condensed rows of an active node (state Slip or
/// Stick) and the recovered multiplier, with derivatives.
template <int dim>
struct FrictionalNodeRows {
  bool usable = false;
  std::array<double, dim> rows{};  ///< row value per component slot (prescribed slots: 0)
  std::array<double, dim> lambda{};  ///< recovered multiplier lambda_j (traction / k)
  std::array<double, dim> direction{};  ///< unit slip direction d of the slip rows (zero when sticking)
  /// d rows[c] / d input[i], d lambda[c] / d input[i]; inputs ordered r, n, w, D, g~.
  std::array<std::array<double, kFrictionalInputs<dim>>, dim> dRows{}, dLambda{};
};

template <int dim>
FrictionalNodeRows<dim> frictionalRows(const FrictionalNodeInput<dim>& in, ContactState state,
                                       const FrictionalParameters& p);

// ---------------------------------------------------------------------------
// Penalty friction (seed 4.71a with a return map): no multipliers; the
// traction on the slave is
//   normal      p = eps_n <-g~> / D                       (as frictionless penalty)
//   tangential  trial t* = P t_old + eps_tau w / D         (P = I - n n^T; t_old the
//               converged tangential traction of the last step, w the weighted slip)
//               stick: t = t*;  slip: t = Θ t* / |t*|, Θ = the law's threshold at
//               lambdā_n = -p
// and the force acting on the slave node is f = t D (-p n + t) (t: 2D thickness);
// the master nodes get -(M_jl / D) f. The history t_old makes a sticking
// contact keep its traction from step to step (the slip w restarts each step).

/// Inputs of the penalty force derivatives, in this order: n (dim), w (dim), D, g~.
template <int dim>
inline constexpr int kPenaltyFrictionalInputs = 2 * dim + 2;

template <int dim>
struct PenaltyFrictionalInput {
  std::array<double, dim> normal{};
  std::array<double, dim> slip{};             ///< weighted slip of the step w (seed sign)
  std::array<double, dim> oldTraction{};      ///< converged tangential traction of the last step
  double D = 0.0;
  double gap = 0.0;
};

template <int dim>
struct PenaltyFrictionalForce {
  std::array<double, dim> force{};      ///< force acting on the slave node
  std::array<double, dim> traction{};   ///< tangential traction t
  std::array<double, dim> trial{};      ///< trial t* of the return map (the augmented tangential traction)
  double pressure = 0.0;                ///< p
  /// d force[c] / d input[i]; inputs ordered n, w, D, g~.
  std::array<std::array<double, kPenaltyFrictionalInputs<dim>>, dim> dForce{};
};

/// @brief Penalty rule: Inactive when g~ > 0; else Stick when |t*| <= Θ
/// (hysteresis as stickSlipState for a node already slipping), Slip otherwise.
template <int dim>
ContactState penaltyFrictionalState(const PenaltyFrictionalInput<dim>& in, ContactState previous,
                                    const FrictionalParameters& p);

/// @brief The force of an active penalty node in `state` (Slip or Stick).
template <int dim>
PenaltyFrictionalForce<dim> penaltyFrictionalForce(const PenaltyFrictionalInput<dim>& in, ContactState state,
                                                   const FrictionalParameters& p);

#define COULOMB_FRICTIONAL_NODE_EXTERN(DIM)                                                                  \
  extern template FrictionalNodeState<DIM> frictionalState<DIM>(const FrictionalNodeInput<DIM>&, ContactState, \
                                                                const FrictionalParameters&);                \
  extern template FrictionalNodeRows<DIM> frictionalRows<DIM>(const FrictionalNodeInput<DIM>&, ContactState,  \
                                                              const FrictionalParameters&);               \
  extern template ContactState penaltyFrictionalState<DIM>(const PenaltyFrictionalInput<DIM>&, ContactState,  \
                                                           const FrictionalParameters&);                    \
  extern template PenaltyFrictionalForce<DIM> penaltyFrictionalForce<DIM>(const PenaltyFrictionalInput<DIM>&, \
                                                                          ContactState, const FrictionalParameters&);
COULOMB_FRICTIONAL_NODE_EXTERN(2)
COULOMB_FRICTIONAL_NODE_EXTERN(3)
#undef COULOMB_FRICTIONAL_NODE_EXTERN

}  // namespace coulomb::contact
