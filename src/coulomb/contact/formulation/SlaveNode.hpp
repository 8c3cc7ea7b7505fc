#pragma once
/// @file SlaveNode.hpp
/// @brief What a formulation (Formulation.hpp) sees of one owned slave node
/// at an update: its state (written by the formulation) and the geometry the
/// pair measured (read only).
#include <array>
#include <cstddef>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/interface/MortarPass.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"

namespace coulomb::contact {

/// @brief The state of one owned slave node (ContactPair keeps one per node
/// and a copy at the step start).
struct SlaveNodeState {
  ContactState state = ContactState::Inactive;
  double lambdaN = 0;   ///< normal multiplier lambda_n (traction / k, <= 0 in compression)
  double pressure = 0;  ///< contact pressure -k lambda_n (>= 0 in compression)
  std::array<double, 3> traction{};       ///< contact traction on the slave, k lambda (frictional pairs)
  /// The augmented values the state rule judged (the seed's
  /// AUGMENTED_NORMAL_CONTACT_PRESSURE and AUGMENTED_TANGENT_CONTACT_PRESSURE):
  /// -lambdā_n = -(k lambda_n + eps_n g~ / D), >= 0 where the rule closes
  /// the node (an open node: -eps_n × its gap); lambdā_tau (frictional pairs;
  /// penalty: the trial traction t*). MPC: the reaction alone.
  double augmentedPressure = 0;
  std::array<double, 3> augmentedTraction{};
  std::array<double, 3> weightedSlip{};   ///< weighted slip of the step w (seed sign, 4.69b)
  std::array<double, 3> slipIncrement{};  ///< -w / D: the slip of the step, the slave relative to the master
  /// Unit slip direction of the node's slip rows at the last iterate (zero
  /// unless slipping): FrictionalNodeInput::previousDirection.
  std::array<double, 3> slipDirection{};
};

/// @brief One owned slave node at an update. Stage 1 (decide) has the values
/// only; stage 2 (emit) the derivatives too, for the nodes the formulation
/// asked for (Formulation::needsDerivatives).
struct SlaveNode {
  std::size_t index = 0;  ///< in ContactInterface::ownedSlaveNodes()
  int slave = 0;          ///< in ContactInterface::slaveNodes()
  long long node = -1;    ///< global node number
  /// D, g~, M (values); null when no master is in reach (D_j not above
  /// round-off): the node is then open, and decide() is not called.
  const NodalMortarEntry* mortar = nullptr;
  const NodalNormal* normal = nullptr;  ///< n (values)
  /// The same with their derivatives (stage 2, nodes differentiated); else null.
  const NodalMortarEntry* mortarDerivative = nullptr;
  const NodalNormal* normalDerivative = nullptr;
  std::array<bool, 3> prescribed{};  ///< Dirichlet components of the node
  /// Prescribed components that move the slave relative to the master (not a
  /// plane that a coupled master node has prescribed too): FrictionalNodeInput::driven.
  std::array<bool, 3> driven{};
  std::array<double, 3> residual{};  ///< bulk residual r_j (zero on prescribed components; condensed forms)
  std::array<double, 3> slip{};      ///< weighted slip w_j (frictional pairs)
  /// dw_c / dx (frictional pairs, stage 2); else null.
  const std::array<DerivativeRow, 3>* slipDerivative = nullptr;
  std::array<double, 3> multiplier{};  ///< saddle-point form: the unknown z_j
  double epsN = 0;                     ///< eps_n of the node
  double frictionCoefficient = 0;      ///< mu of the node (frictional pairs)
  std::array<double, 3> lastStepSlip{};  ///< converged weighted slip of the last step (slipping nodes)
  SlaveNodeState* state = nullptr;             ///< now (the formulation writes it)
  const SlaveNodeState* stepStart = nullptr;   ///< at the step start
};

}  // namespace coulomb::contact
