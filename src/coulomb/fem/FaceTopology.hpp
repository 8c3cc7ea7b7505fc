#pragma once
/// @file FaceTopology.hpp
/// @brief Exodus side numbering of the bulk cells: which local nodes form side s.
///
/// Sides are 0-based here (Exodus side number minus one). Face nodes are returned in
/// the Exodus order, which for a positively oriented cell makes the right-hand-rule
/// normal point out of the cell (2D: edge a->b has outward normal (dy, -dx)). Sides
/// of quadratic cells list the linear side's corners first, then the node on each
/// corner-to-corner edge in turn, then (HEX27) the face centre: the node order of
/// the face's own reference shape (LINE3, TRI6, QUAD8, QUAD9).
#include <array>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::fem {

/// @brief Topology of side `side` (0-based) of a cell; throws coulomb::Error on a bad side.
mesh::FaceType faceType(mesh::CellType cell, int side);

/// @brief Local (0-based) cell nodes of side `side` (0-based), outward-oriented; returns the
/// node count (unused entries are set to -1). Throws coulomb::Error on a bad side.
int faceLocalNodes(mesh::CellType cell, int side, std::array<int, mesh::kMaxFaceNodes>& localNodes);

}  // namespace coulomb::fem
