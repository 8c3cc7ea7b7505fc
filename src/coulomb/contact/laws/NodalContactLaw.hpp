#pragma once
/// @file NodalContactLaw.hpp
/// @brief Nodal kernels of frictionless contact for one slave node j: the ALM
/// multiplier residual of the "components" formulation (vector multiplier,
/// seed 4.72a/b with mu = 0), the contact forces on the displacement rows, and
/// their derivatives (the penalty forces: FrictionalNode.hpp's return map).
/// Small fixed-size kernels, dim = 2 or 3; no Tpetra, no MPI.
///
/// Units and signs (see also ActiveSet.hpp):
///   g~_j   weighted gap (MortarPass, > 0 open), g_j = g~_j / D_j nodal gap;
///   lambda_j nodal traction coefficient (not area-weighted); the physical
///          traction is k lambda_j, lambda_n = n.lambda_j <= 0 in compression;
///   eps_n, eps_tau physical penalties (pressure / length);
///   c_n = D_j k^2 / eps_n,  c_tau = D_j k^2 / eps_tau;  P = I - n n^T.
///
/// The nodal ALM functional is D_j × (4.60a) with g = g~_j / D_j, plus the
/// frictionless tangential part (4.60b with mu = 0, i.e. always "slip" with zero
/// threshold, and the gap-zone line):
///   L_j = k lambda_n g~_j + eps_n g~_j^2 / (2 D_j)   (Active:   D_j (lambdā_n g - eps_n g^2/2))
///         - c_n lambda_n^2 / 2                      (Inactive: D_j (-k^2 lambda_n^2 / (2 eps_n)))
///         - c_tau |P lambda|^2 / 2                  (both states, mu = 0)
/// The multiplier residual implemented is its derivative with respect to lambda_j
/// (the variational form 4.62 with mu = 0):
///   Active   : r = k g~_j n - c_tau P lambda
///   Inactive : r = -c_n (n.lambda) n - c_tau P lambda
/// Relation to (4.72b): the Active line is (4.72b) first line with mu = 0
/// (k n (-n.(D x^1 - M x^2)) = k g~ n; tangential part -k^2/eps P lambda, with
/// eps_tau as in 4.62 where 4.72b prints eps_n); the Inactive line is (4.72b)
/// third line with the opposite overall sign and the nodal penalty
/// eps^_j = eps/D_j. Both have the same roots; the sign chosen here makes r
/// continuous across the switch lambdā_n = 0 (k g~ = -c_n lambda_n there), so the
/// residual norm does not jump when a node changes state, and makes the
/// lambda-lambda block symmetric negative semi-definite (saddle point).
///
/// Contact forces (the components system 4.72a): the forces ACTING ON the bodies
/// (external loads, to be subtracted from the residual r_u = f_int - f_ext):
///   slave node j : f_j  = k D_j lambda_j,
///   master node l: f_l  = -k M_jl lambda_j.
/// With lambda_n < 0 (compression) f_j = -k D_j |lambda_n| n points away from the
/// master (n points from the slave towards the master), and f_l pushes the master
/// along +n: compression pushes the bodies apart. For a matching interface
/// (M_jl = D_j delta_jl) f_j + f_l = 0 (momentum conservation). These are also
/// -dL_j/dx for the coupling term k lambda.(M x^2 - D x^1) (D, M frozen).
/// Sign note: (4.72a) shows K and +k D^T (slave rows), -k M^T (master rows) in
/// one Jacobian, i.e. r_u = f_int - f_ext + k D lambda: a slave force -k D lambda,
/// which would be attractive with the seed's own contact zone lambdā_n <= 0
/// (4.60a, 4.74); (4.72a) is consistent with the opposite convention
/// (lambda_n >= 0 in compression). We keep lambda_n <= 0 and take the force signs
/// from the functional: with r_u = f_int - f_ext - f, the lambda-columns of the
/// displacement rows are -k D_j I (slave) and +k M_jl I (master).
///
#include <array>

#include "coulomb/contact/laws/ActiveSet.hpp"

namespace coulomb::contact {

template <int dim>
using NVec = std::array<double, dim>;
/// Row-major dim × dim matrix: m[i][c] = d out_i / d in_c.
template <int dim>
using NMat = std::array<std::array<double, dim>, dim>;

/// @brief Parameters of the ALM law.
struct AlmParameters {
  double k = 1.0;       ///< scale factor k > 0
  double epsN = 1.0;    ///< normal penalty eps_n > 0 (pressure / length)
  double epsTau = 1.0;  ///< tangential penalty eps_tau > 0 (pressure / length)
};

/// @brief Inputs of one slave node j.
template <int dim>
struct AlmNodeInput {
  NVec<dim> lambda{};  ///< lambda_j (nodal traction coefficient)
  NVec<dim> normal{};  ///< unit nodal normal n_j
  double gap = 0.0;    ///< weighted gap g~_j
  double D = 0.0;      ///< D_j > 0
};

/// @brief Residual r_lambda_j and its derivatives.
template <int dim>
struct AlmNodeResidual {
  NVec<dim> r{};         ///< r_lambda_j
  NMat<dim> dLambda{};   ///< d r_i / d lambda_c
  NVec<dim> dGap{};      ///< d r_i / d g~
  NMat<dim> dNormal{};   ///< d r_i / d n_c (n treated as free: chain with dn/du)
  NVec<dim> dD{};        ///< d r_i / d D_j
};

/// @brief ALM frictionless multiplier residual of node j in the given state
/// (formula in the file comment). Throws coulomb::InternalError for D <= 0 or
/// non-positive parameters.
template <int dim>
AlmNodeResidual<dim> almResidual(const AlmNodeInput<dim>& in, const AlmParameters& p, ContactState state);

/// @brief Default normal penalty eps_n = factor × E / h (pressure / length).
/// Reason: E/h is the stiffness per unit area of a layer of the body one element
/// (h) thick, so the penetration under a contact pressure p is about (p/E) h, a
/// fraction p/E of an element — small for stiff-enough contact, while the
/// penalty term stays of the order of the element stiffness (no extra
/// ill-conditioning). Use a larger factor (10–100) for less penetration with
/// pure penalty; the ALM removes the penetration anyway. Requires E, h, factor > 0.
double defaultPenalty(double E, double h, double factor = 1.0);

#define COULOMB_NODAL_LAW_EXTERN(DIM)                                                                        \
  extern template AlmNodeResidual<DIM> almResidual<DIM>(const AlmNodeInput<DIM>&, const AlmParameters&,     \
                                                        ContactState);
COULOMB_NODAL_LAW_EXTERN(2)
COULOMB_NODAL_LAW_EXTERN(3)
#undef COULOMB_NODAL_LAW_EXTERN

}  // namespace coulomb::contact
