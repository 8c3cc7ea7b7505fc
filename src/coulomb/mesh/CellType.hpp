#pragma once
/// @file CellType.hpp
/// @brief The bulk element topologies Coulomb supports and their face topologies.
///
/// Node order is the Exodus II one (SEACAS): corners first, then one node per
/// edge (its midpoint in the reference element), then for the 27-node hex and
/// the 9-node quad the centre (HEX27: the cell centre, then the face centres).
#include <array>
#include <string>

namespace coulomb::mesh {

/// Bulk cells (2D in the x-y plane: QUAD4, TRI3, QUAD8, QUAD9, TRI6;
/// 3D: HEX8, TET4, HEX20, HEX27, TET10).
enum class CellType { Quad4, Tri3, Hex8, Tet4, Quad8, Quad9, Tri6, Hex20, Hex27, Tet10 };

/// Boundary faces of cells (2D edges are Line2 / Line3).
enum class FaceType { Line2, Tri3, Quad4, Line3, Tri6, Quad8, Quad9 };

/// Most nodes of any face (QUAD9).
constexpr int kMaxFaceNodes = 9;

constexpr int numNodes(CellType t) {
  switch (t) {
    case CellType::Quad4: return 4;
    case CellType::Tri3: return 3;
    case CellType::Hex8: return 8;
    case CellType::Tet4: return 4;
    case CellType::Quad8: return 8;
    case CellType::Quad9: return 9;
    case CellType::Tri6: return 6;
    case CellType::Hex20: return 20;
    case CellType::Hex27: return 27;
    case CellType::Tet10: return 10;
  }
  return 0;
}

/// The linear cell with the same corners (a linear cell is its own).
constexpr CellType linearType(CellType t) {
  switch (t) {
    case CellType::Quad8:
    case CellType::Quad9: return CellType::Quad4;
    case CellType::Tri6: return CellType::Tri3;
    case CellType::Hex20:
    case CellType::Hex27: return CellType::Hex8;
    case CellType::Tet10: return CellType::Tet4;
    default: return t;
  }
}
constexpr bool isQuadratic(CellType t) { return linearType(t) != t; }
/// Number of corner nodes (they lead the node list).
constexpr int numCorners(CellType t) { return numNodes(linearType(t)); }

constexpr int spatialDimension(CellType t) {
  const CellType l = linearType(t);
  return (l == CellType::Quad4 || l == CellType::Tri3) ? 2 : 3;
}
constexpr int numFaces(CellType t) {
  switch (linearType(t)) {
    case CellType::Quad4: return 4;
    case CellType::Tri3: return 3;
    case CellType::Hex8: return 6;
    default: return 4;
  }
}
constexpr int numNodes(FaceType t) {
  switch (t) {
    case FaceType::Line2: return 2;
    case FaceType::Tri3: return 3;
    case FaceType::Quad4: return 4;
    case FaceType::Line3: return 3;
    case FaceType::Tri6: return 6;
    case FaceType::Quad8: return 8;
    case FaceType::Quad9: return 9;
  }
  return 0;
}
/// Number of corner nodes of a face (they lead its node list).
constexpr int numCorners(FaceType t) {
  switch (t) {
    case FaceType::Line2:
    case FaceType::Line3: return 2;
    case FaceType::Tri3:
    case FaceType::Tri6: return 3;
    default: return 4;
  }
}
constexpr bool isQuadratic(FaceType t) {
  return t != FaceType::Line2 && t != FaceType::Tri3 && t != FaceType::Quad4;
}

/// @brief The corners whose reference-element mean is node `a` of a cell:
/// a corner is its own, an edge node the edge's two ends, a face centre the
/// face's four corners, the HEX27/QUAD9 cell centre all corners.
///
/// Why: one description of where the higher-order nodes sit, from which the
/// readers derive node permutations (gmsh's order, flipped cells) by
/// matching corner sets instead of by hand-written tables.
struct NodeCorners {
  int count = 0;
  std::array<int, 8> corners{};
};
NodeCorners nodeCorners(CellType t, int a);

std::string toString(CellType t);
std::string toString(FaceType t);

}  // namespace coulomb::mesh
