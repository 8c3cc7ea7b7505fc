#pragma once
/// @file AutomaticPenalty.hpp
/// @brief The automatic normal penalty of a contact pair, one value per slave
/// node: eps_n,j = factor × E_j / h_j (issue 15, item 8; the seed's nodal
/// INITIAL_PENALTY).
///
/// E_j per node: a slave surface over several materials has no single
/// modulus. h_j depends on the formulation (PenaltySize):
///  - Penalty: the node's own faces. eps_n is then part of the answer (the
///    penetration p / eps_n), which should be the same fraction p / E of the
///    local element everywhere (ContactPairs.AutomaticPenaltyFollowsTheLocalFaceSize).
///  - ALM and MPC: the pair's mean face size, as the seed's default: eps_n
///    only weighs the gap in the active-set test and scales the gap rows, the
///    answer does not depend on it (tests/regression/penalty_independence.cmake),
///    and the local size cost iterations on a slab refined along the track
///    (docs/architecture.md, "Automatic penalty per node", has the figures).
/// A pure kernel on plain data (no MPI, no mesh): ContactPair fills the faces.

#include <array>
#include <vector>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::contact {

/// Which face size h_j a node's penalty takes (see above).
enum class PenaltySize { LocalFaces, PairMean };

/// One slave face as the automatic penalty sees it.
struct PenaltyFace {
  int numNodes = 0;                        ///< 2, 3 or 4
  std::array<int, mesh::kMaxFaceNodes> nodes{};  ///< node indices (0 … numNodes of the result - 1)
  double diameter = 0;                     ///< largest distance between two of its nodes
  double modulus = 0;                      ///< Young's modulus of its element
};

/// The mean diameter of `faces` (0 for none): the pair's face size h.
double meanFaceDiameter(const std::vector<PenaltyFace>& faces);

/// @brief eps_n = factor × E / h (pressure / length): E / h is the stiffness
/// per unit area of a layer of the body one element (h) thick, so a contact
/// pressure p penetrates about (p / E) h, a fraction p / E of an element,
/// while the penalty term stays of the order of the element stiffness (no
/// extra ill-conditioning). Requires E, h, factor > 0 (InternalError).
double defaultPenalty(double E, double h, double factor = 1.0);

/// @brief eps_n,j = factor × E_j / h_j for nodes 0 … numNodes - 1, with h_j
/// the mean diameter of the faces at node j (LocalFaces) or of all faces
/// (PairMean), and E_j = min(E_s,j, E_master),
/// E_s,j the largest modulus of the faces at j (the softer side governs the
/// series of the two bodies' element layers; a node between a stiff and a
/// soft slave element takes the stiff one, as a pair's single value did).
/// When one of the two is not positive, the other. A node on no face gets 0.
/// @throws coulomb::Error when a face at a node has a non-positive diameter
/// or modulus, or factor ≤ 0 (defaultPenalty).
std::vector<double> automaticNodalPenalty(const std::vector<PenaltyFace>& faces, int numNodes, double masterModulus,
                                          double factor, PenaltySize size);

}  // namespace coulomb::contact
