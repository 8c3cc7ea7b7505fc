#pragma once
/// @file GmshNodeOrder.hpp
/// @brief Node orders of the cells gmsh writes, as Exodus wants them: gmsh's
/// order of the TET10, HEX20 and HEX27 higher-order nodes, the permutation
/// that turns a cell inside out, and the nodes on a quadratic cell's side.
///
/// Why a file of its own: every table here is derived from one description,
/// mesh::nodeCorners (which corners each node sits between), by matching
/// corner sets, so that no permutation is written out by hand twice.
#include <vector>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::io {

/// @brief The permutation p (new node i = old node p[i]) of a cell's nodes
/// that moves its corners by `corners` (new corner i = old corner corners[i]):
/// each higher-order node goes where the image of its corner set is.
std::vector<int> cornerPermutation(mesh::CellType type, const std::vector<int>& corners);

/// @brief Node permutation that reverses a cell's orientation (corners
/// mirrored, higher-order nodes following their corners).
std::vector<int> flipPermutation(mesh::CellType type);

/// @brief Exodus node i of a gmsh cell of this type is gmsh node
/// gmshToExodus(type)[i]. gmsh numbers corners as Exodus does but the
/// higher-order nodes of TET10, HEX20 and HEX27 differently (gmsh manual,
/// "Node ordering"); the other types map to themselves.
std::vector<int> gmshToExodus(mesh::CellType type);

/// @brief Sides of a quadratic cell as node sets: each linear side's corners
/// (`linear`, one list per side), then every higher-order node whose corners
/// all lie on that side (edge nodes, the HEX27 face centre), in node order.
std::vector<std::vector<int>> quadraticSides(mesh::CellType type, const std::vector<std::vector<int>>& linear);

}  // namespace coulomb::io
