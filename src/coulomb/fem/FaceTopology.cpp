/// @file FaceTopology.cpp
/// @brief Exodus side-to-node tables (SEACAS convention, 1-based in the comments).
#include "coulomb/fem/FaceTopology.hpp"

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
  }
  return mesh::FaceType::Line2;
}

int faceLocalNodes(mesh::CellType cell, int side, std::array<int, 4>& localNodes) {
  requireSide(cell, side);
  localNodes.fill(-1);
  const int* nodes = nullptr;
  int count = 0;
  switch (cell) {
    case mesh::CellType::Quad4: nodes = kQuad4[side], count = 2; break;
    case mesh::CellType::Tri3: nodes = kTri3[side], count = 2; break;
    case mesh::CellType::Hex8: nodes = kHex8[side], count = 4; break;
    case mesh::CellType::Tet4: nodes = kTet4[side], count = 3; break;
  }
  for (int i = 0; i < count; ++i) localNodes[i] = nodes[i];
  return count;
}

}  // namespace coulomb::fem
