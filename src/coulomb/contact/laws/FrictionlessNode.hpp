#pragma once
/// @file FrictionlessNode.hpp
/// @brief Kernel: the state of one slave node of a frictionless condensed
/// pair (ALM or MPC) and its normal multiplier, recovered from the bulk
/// residual (dual mortar, D diagonal; CondensationFrame.hpp):
///   lambda_n = a . r_F / (k t D |n_F|)       (equilibrium of the a-row),
/// recovered only when the node was active at the previous iterate (else its
/// rows held plain equilibrium and lambda_n = 0). Rules (ActiveSet.hpp):
/// ALM almContactState (4.73/4.74), MPC mpcContactState. A node whose free
/// components hardly see its normal (CondensationFrame::usable false) stays
/// open. Fixed-size arrays, no Tpetra, no MPI.
#include <array>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/laws/CondensationFrame.hpp"

namespace coulomb::contact {

struct FrictionlessParameters {
  double k = 1.0;          ///< ALM scale factor
  double epsN = 1.0;       ///< normal penalty eps_n of the node
  double thickness = 1.0;  ///< t (2D thickness, 1 in 3D)
  double touchingGap = 0;  ///< closer surfaces count as closed (almContactState)
  bool multiPointConstraint = false;  ///< MPC rule (no penalty)
};

template <int dim>
struct FrictionlessNodeInput {
  std::array<double, dim> residual{};  ///< bulk residual r_j [force] (prescribed components unused)
  std::array<double, dim> normal{};    ///< unit nodal normal n_j
  std::array<bool, dim> prescribed{};  ///< Dirichlet components
  double D = 0.0;                      ///< D_j > 0
  double gap = 0.0;                    ///< weighted gap g~_j
};

template <int dim>
struct FrictionlessNodeState {
  ContactState state = ContactState::Inactive;  ///< Slip (in contact) or Inactive
  /// Recovered (0 unless the node was active): the caller zeroes it when
  /// the node ends open (a frozen set may keep a node the rule opens).
  double lambdaN = 0.0;
  /// lambdā_n = k lambda_n + eps_n g~ / D the rule judged (ALM, 4.73);
  /// MPC: the reaction k lambda_n (no penalty).
  double augmentedNormal = 0.0;
  CondensationFrame<dim> frame;
};

/// @brief The rule's state of the node (before a frozen set keeps the
/// previous one: nextState) and its recovered lambda_n.
template <int dim>
FrictionlessNodeState<dim> frictionlessState(const FrictionlessNodeInput<dim>& in, ContactState previous,
                                             const FrictionlessParameters& p);

extern template FrictionlessNodeState<2> frictionlessState<2>(const FrictionlessNodeInput<2>&, ContactState,
                                                             const FrictionlessParameters&);
extern template FrictionlessNodeState<3> frictionlessState<3>(const FrictionlessNodeInput<3>&, ContactState,
                                                             const FrictionlessParameters&);

}  // namespace coulomb::contact
