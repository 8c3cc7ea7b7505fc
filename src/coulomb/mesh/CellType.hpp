#pragma once
/// @file CellType.hpp
/// @brief The bulk element topologies Coulomb supports and their face topologies.
#include <string>

namespace coulomb::mesh {

/// Bulk cells (2D: QUAD4, TRI3 in the x-y plane; 3D: HEX8, TET4).
enum class CellType { Quad4, Tri3, Hex8, Tet4 };

/// Boundary faces of cells (2D edges are Line2).
enum class FaceType { Line2, Tri3, Quad4 };

constexpr int numNodes(CellType t) {
  return t == CellType::Quad4 ? 4 : t == CellType::Tri3 ? 3 : t == CellType::Hex8 ? 8 : 4;
}
constexpr int spatialDimension(CellType t) {
  return (t == CellType::Quad4 || t == CellType::Tri3) ? 2 : 3;
}
constexpr int numFaces(CellType t) {
  return t == CellType::Quad4 ? 4 : t == CellType::Tri3 ? 3 : t == CellType::Hex8 ? 6 : 4;
}
constexpr int numNodes(FaceType t) { return t == FaceType::Line2 ? 2 : t == FaceType::Tri3 ? 3 : 4; }

std::string toString(CellType t);

}  // namespace coulomb::mesh
