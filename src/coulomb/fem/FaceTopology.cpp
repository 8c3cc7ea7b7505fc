/// @file FaceTopology.cpp
/// @brief Exodus side-to-node tables (SEACAS convention, 1-based in the comments).
#include "coulomb/fem/FaceTopology.hpp"

#include <algorithm>
#include <iterator>

#include "coulomb/core/Error.hpp"

namespace coulomb::fem {
namespace {

// QUAD4 sides: 1:(1,2) 2:(2,3) 3:(3,4) 4:(4,1)
constexpr int kQuad4[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
// TRI3 sides: 1:(1,2) 2:(2,3) 3:(3,1)
constexpr int kTri3[3][2] = {{0, 1}, {1, 2}, {2, 0}};
// HEX8 sides: 1:(1,2,6,5) 2:(2,3,7,6) 3:(3,4,8,7) 4:(4,1,5,8) 5:(1,4,3,2) 6:(5,6,7,8)
constexpr int kHex8[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {0, 3, 2, 1}, {4, 5, 6, 7}};
// TET4 sides: 1:(1,2,4) 2:(2,3,4) 3:(1,4,3) 4:(1,3,2)
constexpr int kTet4[4][3] = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};

/// The nodes of one side of a quadratic cell, in face order (see the header).
struct QuadraticSide {
  int count = 0;
  std::array<int, mesh::kMaxFaceNodes> nodes{};
};

/// The node of a quadratic cell whose corner set (mesh::nodeCorners) is `corners`.
int nodeOn(mesh::CellType cell, std::array<int, 4> corners, int count) {
  std::sort(corners.begin(), corners.begin() + count);
  for (int a = mesh::numCorners(cell); a < mesh::numNodes(cell); ++a) {
    mesh::NodeCorners c = mesh::nodeCorners(cell, a);
    std::sort(c.corners.begin(), c.corners.begin() + c.count);
    if (c.count == count && std::equal(corners.begin(), corners.begin() + count, c.corners.begin())) return a;
  }
  return -1;
}

/// Sides of a quadratic cell, derived once from the linear side table and the
/// corner sets of the higher-order nodes (one source for where they sit).
QuadraticSide deriveSide(mesh::CellType cell, int side) {
  QuadraticSide result;
  std::array<int, mesh::kMaxFaceNodes> corners{};
  const mesh::CellType linear = mesh::linearType(cell);
  const int n = faceLocalNodes(linear, side, corners);
  for (int i = 0; i < n; ++i) result.nodes[result.count++] = corners[i];
  const int edges = n == 2 ? 1 : n;  // a 2D side is one edge
  for (int i = 0; i < edges; ++i) result.nodes[result.count++] = nodeOn(cell, {corners[i], corners[(i + 1) % n]}, 2);
  if (n == 4) {  // a HEX27 face has its centre, a HEX20 face has none
    const int centre = nodeOn(cell, {corners[0], corners[1], corners[2], corners[3]}, 4);
    if (centre >= 0) result.nodes[result.count++] = centre;
  }
  for (int i = 0; i < result.count; ++i)
    COULOMB_CHECK(result.nodes[i] >= 0, "side " << side + 1 << " of a " << mesh::toString(cell) << " has no node " << i);
  return result;
}

const QuadraticSide& quadraticSide(mesh::CellType cell, int side) {
  using mesh::CellType;
  static const auto tables = [] {
    constexpr CellType kTypes[] = {CellType::Quad8, CellType::Quad9, CellType::Tri6,
                                   CellType::Hex20, CellType::Hex27, CellType::Tet10};
    std::array<std::array<QuadraticSide, 6>, std::size(kTypes)> t{};
    for (std::size_t k = 0; k < std::size(kTypes); ++k)
      for (int s = 0; s < mesh::numFaces(kTypes[k]); ++s) t[k][s] = deriveSide(kTypes[k], s);
    return t;
  }();
  switch (cell) {
    case CellType::Quad8: return tables[0][side];
    case CellType::Quad9: return tables[1][side];
    case CellType::Tri6: return tables[2][side];
    case CellType::Hex20: return tables[3][side];
    case CellType::Hex27: return tables[4][side];
    case CellType::Tet10: return tables[5][side];
    default: break;
  }
  throw InternalError("quadraticSide: " + mesh::toString(cell) + " is not a quadratic cell");
}

void requireSide(mesh::CellType cell, int side) {
  COULOMB_REQUIRE(side >= 0 && side < mesh::numFaces(cell),
                  "side " << side + 1 << " does not exist on a " << mesh::toString(cell) << " cell (it has "
                          << mesh::numFaces(cell) << " sides, numbered from 1)");
}

}  // namespace

mesh::FaceType faceType(mesh::CellType cell, int side) {
  requireSide(cell, side);
  switch (cell) {
    case mesh::CellType::Quad4:
    case mesh::CellType::Tri3: return mesh::FaceType::Line2;
    case mesh::CellType::Hex8: return mesh::FaceType::Quad4;
    case mesh::CellType::Tet4: return mesh::FaceType::Tri3;
    case mesh::CellType::Quad8:
    case mesh::CellType::Quad9:
    case mesh::CellType::Tri6: return mesh::FaceType::Line3;
    case mesh::CellType::Hex20: return mesh::FaceType::Quad8;
    case mesh::CellType::Hex27: return mesh::FaceType::Quad9;
    case mesh::CellType::Tet10: return mesh::FaceType::Tri6;
  }
  return mesh::FaceType::Line2;
}

int faceLocalNodes(mesh::CellType cell, int side, std::array<int, mesh::kMaxFaceNodes>& localNodes) {
  requireSide(cell, side);
  localNodes.fill(-1);
  if (mesh::isQuadratic(cell)) {
    const QuadraticSide& q = quadraticSide(cell, side);
    std::copy(q.nodes.begin(), q.nodes.begin() + q.count, localNodes.begin());
    return q.count;
  }
  const int* nodes = nullptr;
  int count = 0;
  switch (cell) {
    case mesh::CellType::Quad4: nodes = kQuad4[side], count = 2; break;
    case mesh::CellType::Tri3: nodes = kTri3[side], count = 2; break;
    case mesh::CellType::Hex8: nodes = kHex8[side], count = 4; break;
    case mesh::CellType::Tet4: nodes = kTet4[side], count = 3; break;
    default: throw InternalError("faceLocalNodes: unhandled cell type " + mesh::toString(cell));
  }
  for (int i = 0; i < count; ++i) localNodes[i] = nodes[i];
  return count;
}

}  // namespace coulomb::fem
