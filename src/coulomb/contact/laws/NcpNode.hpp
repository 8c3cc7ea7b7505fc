#pragma once
/// @file NcpNode.hpp
/// @brief Kernel: the nodal rows of the Lagrange multiplier method with
/// nonlinear complementarity functions (seed 4.79; Popp, Gitterle, Hüeber),
/// multipliers kept as unknowns (no penalty in the solution, only in the
/// complementarity parameters c_n, c_tau). Fixed-size arrays, no Tpetra, no MPI.
///
/// Conventions as everywhere in contact/ (ActiveSet.hpp, FrictionalNode.hpp):
/// traction on the slave t = k lambda, normal multiplier lambda_n = n.lambda
/// <= 0 in compression, pressure p = -k lambda_n; g = g~/D the nodal gap
/// (> 0 open); w the weighted slip increment of the step (seed sign of
/// 4.69b: the motion of the master relative to the slave, D × length), so a
/// sliding slave is dragged along +w: the Coulomb traction t_tau is parallel
/// to +w_tau (P = I - n n^T, t_tau = P t, w_tau = P w).
///
/// Normal NCP (frictionless part; the same zone as the ALM rule 4.73/4.74):
///   C_n = p - max(0, p - c_n g)          active when p - c_n g > 0
///       active: c_n g (the gap closes);  inactive: p (the multiplier vanishes).
/// Tangential NCP (4.79), with the augmented tangent a = t_tau + c_tau w_tau / D
/// and the law's threshold Θ = frictionThreshold(law, -(p - c_n g)) (Coulomb:
/// mu (p - c_n g)): (4.79) is max(Θ, |a|) t_tau - Θ a = 0; divided by
/// max(Θ, |a|) (the same roots, continuous, a traction like C_n):
///   stick (|a| <= Θ):  C_tau = -c_tau w_tau / D        (no slip)
///   slip  (|a| >  Θ):  C_tau = t_tau - Θ a / |a|       (on the cone, along the slip)
///   frictionless law, or an inactive node: C_tau = t_tau.
/// At |a| = Θ the two branches agree. The node's residual vector is
/// R = C_n n + C_tau (normal part C_n, tangential part C_tau) [pressure].
///
/// Derivative inputs, in this order: lambda (dim), n (dim), w (dim), D, g~.
#include <array>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/laws/FrictionLaw.hpp"

namespace coulomb::contact {

struct NcpParameters {
  double k = 1.0;          ///< scale factor: t = k lambda
  double cN = 1.0;         ///< normal complementarity parameter c_n > 0 [pressure/length]
  double cTau = 1.0;       ///< tangential complementarity parameter c_tau > 0 [pressure/length]
  double touchingGap = 0;  ///< surfaces closer than this length count as closed (almContactState)
  double slipThreshold = 0;  ///< hysteresis of slip -> stick (stickSlipState)
  FrictionLaw law;         ///< None: frictionless (C_tau = t_tau)
};

template <int dim>
inline constexpr int kNcpInputs = 3 * dim + 2;

template <int dim>
struct NcpNodeInput {
  std::array<double, dim> lambda{};  ///< nodal multiplier lambda_j (traction / k)
  std::array<double, dim> normal{};  ///< unit nodal normal n_j
  std::array<double, dim> slip{};    ///< weighted slip increment w_j (seed sign); zero when frictionless
  double D = 0.0;                    ///< D_j > 0
  double gap = 0.0;                  ///< weighted gap g~_j
};

/// @brief The state of the node's NCP branches: Inactive when
/// almContactState(lambda_n, g~, D, k, c_n, touchingGap) says open; else
/// stickSlipState(|a|, Θ, previous, slipThreshold) (Stick or Slip; the
/// hysteresis for a node whose `previous` state was Slip); a frictionless
/// law is always Slip when active. Throws InternalError for D <= 0 or
/// non-positive k, c_n, c_tau.
template <int dim>
ContactState ncpState(const NcpNodeInput<dim>& in, ContactState previous, const NcpParameters& p);

template <int dim>
struct NcpNodeRows {
  std::array<double, dim> r{};  ///< R = C_n n + C_tau
  /// d r[c] / d input[i]; inputs ordered lambda, n, w, D, g~.
  std::array<std::array<double, kNcpInputs<dim>>, dim> dr{};
  double augmentedNormal = 0;           ///< k lambda_n + c_n g~ / D
  std::array<double, dim> augmentedTangent{};  ///< a
};

/// @brief The rows of the branch `state` (from ncpState), with derivatives
/// (Sacado). Throws InternalError for the parameters ncpState rejects.
template <int dim>
NcpNodeRows<dim> ncpRows(const NcpNodeInput<dim>& in, ContactState state, const NcpParameters& p);

#define COULOMB_NCP_NODE_EXTERN(DIM)                                                                       \
  extern template ContactState ncpState<DIM>(const NcpNodeInput<DIM>&, ContactState, const NcpParameters&); \
  extern template NcpNodeRows<DIM> ncpRows<DIM>(const NcpNodeInput<DIM>&, ContactState, const NcpParameters&);
COULOMB_NCP_NODE_EXTERN(2)
COULOMB_NCP_NODE_EXTERN(3)
#undef COULOMB_NCP_NODE_EXTERN

}  // namespace coulomb::contact
