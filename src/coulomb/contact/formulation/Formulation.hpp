#pragma once
/// @file Formulation.hpp
/// @brief How a contact pair turns the geometry of its slave nodes into
/// states and Newton-system contributions: one interface, one class per
/// formulation (this folder, one file each), chosen by makeFormulation from
/// the deck. ContactPair owns the geometry (search, normals, mortar values
/// and derivatives, weighted slip) and runs the one loop over its owned
/// slave nodes:
///   stage 1  decide()            per node, from values: the new state
///            needsDerivatives()  which nodes stage 2 differentiates
///   stage 2  emit()              per node, with derivatives: rows into the RowSink
/// docs/architecture.md, "Contact formulations", has the steps to add one.
#include <memory>

#include "coulomb/contact/ContactContributions.hpp"
#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/contact/formulation/RowSink.hpp"
#include "coulomb/contact/formulation/SlaveNode.hpp"

namespace coulomb::contact {

/// @brief What every formulation of a pair knows besides its nodes.
struct PairConstants {
  const ContactPairSettings* settings = nullptr;
  double k = 1;          ///< ALM scale factor
  double thickness = 1;  ///< 2D thickness (1 in 3D): contact forces scale like the bulk
  double faceSize = 1;   ///< h, the mean slave face size
  double referenceD = 1;  ///< h^(dim-1): the scale of D_j
  /// Surfaces within this length count as touching (closed): 1e-12 h, 1000
  /// times the round-off of coordinates 1000 faces from the origin
  /// (almContactState); the tension it lets an active node keep,
  /// eps_n × 1e-12 h ~ 1e-12 E, is far below the contact tolerances.
  double touchingGap() const { return 1e-12 * faceSize; }
};

class Formulation {
public:
  virtual ~Formulation() = default;
  /// The saddle-point form: the nodes' multipliers are Newton unknowns
  /// (ContactPair::updateSaddlePoint gives them).
  virtual bool needsMultipliers() const { return false; }
  /// Frictional forms: the pair computes the weighted slip of each node.
  virtual bool usesSlip() const { return false; }
  /// Stage 1: node `n` (with a master in reach) at the previous iterate's
  /// state `previous`: the state rule's new state, kept frozen when not
  /// `updateSet` (nextState: a disagreement counts in summary.violations);
  /// writes the node's multiplier, pressure and traction into n.state.
  virtual ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                              PairIterationSummary& summary) const = 0;
  /// Whether stage 2 needs the derivatives of node `n` (its state decided).
  virtual bool needsDerivatives(const SlaveNode& n) const { return isActive(n.state->state); }
  /// Stage 2: node `n`'s contributions (every owned node, whatever its
  /// state) and its forces and residuals into `summary`: the parts the sink
  /// asks for (RowSink::residualPart, tangentPart). The tangent part needs
  /// the derivative entries (n.mortarDerivative, n.normalDerivative); the
  /// residual part alone takes the values (n.mortar, n.normal) when they
  /// are null. The summary counts with the residual part only.
  virtual void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const = 0;
};

/// @brief The formulation of a pair of dimension `dim` (2 or 3), from its
/// settings and the system form.
std::unique_ptr<Formulation> makeFormulation(int dim, const PairConstants& constants, ContactSystemForm form);

}  // namespace coulomb::contact
