#pragma once
/// @file ContactContributions.hpp
/// @brief What the contact pairs add to the Newton system at an iterate
/// (ContactPair.hpp has the formulas) and the figures of an update.
#include <array>
#include <cstdint>
#include <vector>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"

namespace coulomb::contact {

/// @brief The Newton system with the multipliers as unknowns (deck
/// `Contact/System Form` = Saddle Point; formulation/LagrangeNcp.cpp): per
/// slave node j a vector unknown z_j = (k / c_n) lambda_j (a length, so that
/// its columns t c_n D_j are of the size of the stiffness), and the rows
/// R_j = t D_j C_j of the NCP functions (4.79, laws/NcpNode.hpp):
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
  MultiplierBlock multipliers;  ///< System Form = Saddle Point (then transform etc. stay empty)
};

/// Empties every list, keeping their memory: the next iterate's lists are
/// of about the same size, and growing fresh ones costs reallocation and
/// first-touch page faults (a fifth of a frictional QUAD8 iterate).
inline void clear(ContactContributions& c) {
  for (auto* list : {&c.transform, &c.tangentTransform, &c.constraint, &c.contactStiffness, &c.multipliers.columns,
                     &c.multipliers.rows})
    list->clear();
  for (auto* list : {&c.constraintResidual, &c.contactResidual, &c.prescribedForce, &c.multipliers.residual})
    list->clear();
}

/// to += from (every list).
inline void append(ContactContributions& to, const ContactContributions& from) {
  auto add = [](auto& a, const auto& b) { a.insert(a.end(), b.begin(), b.end()); };
  add(to.transform, from.transform);
  add(to.tangentTransform, from.tangentTransform);
  add(to.constraint, from.constraint);
  add(to.constraintResidual, from.constraintResidual);
  add(to.contactStiffness, from.contactStiffness);
  add(to.contactResidual, from.contactResidual);
  add(to.prescribedForce, from.prescribedForce);
  add(to.multipliers.columns, from.multipliers.columns);
  add(to.multipliers.rows, from.multipliers.rows);
  add(to.multipliers.residual, from.multipliers.residual);
}

/// @brief Per-update figures of one pair, summed over ranks.
struct PairIterationSummary {
  ActiveSetSummary activeSet;
  double normalResidual2 = 0;  ///< sum of (eps_n t g~_j)^2 over active ALM nodes
  double contactForce2 = 0;    ///< sum of |f_j|^2 over active slave nodes
  double stickResidual2 = 0;   ///< sum of the squared stick rows (frictional pairs)
  double slipResidual2 = 0;    ///< sum of the squared slip rows (frictional pairs)
  double tangentialForce2 = 0;  ///< sum of |tangential part of f_j|^2 over active slave nodes (frictional pairs)
  /// The change of the nodal contact forces since the last update, by group
  /// (Contact/Convergence Criterion = Increment, Mixed): sums over active
  /// nodes of (t D_j Δp_j)^2, and of |t D_j Δt_tau,j|^2 over sticking and
  /// over slipping nodes.
  double normalIncrement2 = 0, stickIncrement2 = 0, slipIncrement2 = 0;
  std::array<double, 3> slaveForce{};  ///< total contact force on the slave body
  std::array<double, 3> normalForce{};  ///< its normal part, sum of the nodal normal forces
  std::array<double, 3> tangentialForce{};  ///< its tangential part
  /// Nodes whose frozen state (simplified semi-smooth Newton) disagrees with
  /// the update rule at this iterate; 0 when the set was updated.
  long long violations = 0;
  /// A hash of every slave node's state (the same on every rank and for any
  /// partition): equal sets have equal signatures (ActiveSetCycle).
  std::uint64_t setSignature = 0;
  /// Every summed value, for the sums over ranks and pairs (`Summary`: this
  /// type, const or not).
  template <class Summary>
  static auto sums(Summary& s) {
    return std::array{&s.normalResidual2,  &s.contactForce2,     &s.stickResidual2,    &s.slipResidual2,
                      &s.tangentialForce2, &s.normalIncrement2,  &s.stickIncrement2,   &s.slipIncrement2,
                      &s.slaveForce[0],    &s.slaveForce[1],     &s.slaveForce[2],     &s.normalForce[0],
                      &s.normalForce[1],   &s.normalForce[2],    &s.tangentialForce[0], &s.tangentialForce[1],
                      &s.tangentialForce[2]};
  }
  /// Adds another part's sums, counts and violations (not the signature).
  PairIterationSummary& operator+=(const PairIterationSummary& other) {
    const auto to = sums(*this);
    const auto from = sums(other);
    for (std::size_t i = 0; i < to.size(); ++i) *to[i] += *from[i];
    activeSet += other.activeSet;
    violations += other.violations;
    return *this;
  }
  /// Adds the force `force` on a slave node, of normal part `normalPart`
  /// (the rest is tangential), to the totals and norms.
  template <std::size_t N>
  void addSlaveForce(const std::array<double, N>& force, const std::array<double, N>& normalPart) {
    for (std::size_t c = 0; c < N; ++c) {
      slaveForce[c] += force[c];
      normalForce[c] += normalPart[c];
      tangentialForce[c] += force[c] - normalPart[c];
      contactForce2 += force[c] * force[c];
      tangentialForce2 += (force[c] - normalPart[c]) * (force[c] - normalPart[c]);
    }
  }
};

}  // namespace coulomb::contact
