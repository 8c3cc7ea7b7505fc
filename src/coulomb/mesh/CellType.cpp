/// @file CellType.cpp
/// @brief Names of the cell types and where their higher-order nodes sit.
#include "coulomb/mesh/CellType.hpp"

#include "coulomb/core/Error.hpp"

namespace coulomb::mesh {
namespace {

// Edges of the linear cells in the Exodus order of their edge nodes (0-based
// corners; SEACAS Ioss edge tables): QUAD8/9 nodes 4..7, TRI6 3..5,
// HEX20/27 8..19, TET10 4..9.
constexpr int kQuadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
constexpr int kTriEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kHexEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                  {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
// HEX27 nodes 21..26: centres of the faces z = -1, z = +1, x = -1, x = +1,
// y = -1, y = +1 of the reference cube (node 20 is the cell centre).
constexpr int kHexFaceCentres[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3},
                                       {1, 2, 6, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}};

NodeCorners edge(const int (&e)[2]) { return {2, {e[0], e[1]}}; }

NodeCorners all(int n) {
  NodeCorners c{n, {}};
  for (int i = 0; i < n; ++i) c.corners[i] = i;
  return c;
}

}  // namespace

NodeCorners nodeCorners(CellType t, int a) {
  COULOMB_REQUIRE(a >= 0 && a < numNodes(t), "nodeCorners: node " << a << " of a " << toString(t) << " cell");
  const int corners = numCorners(t);
  if (a < corners) return {1, {a}};
  const int k = a - corners;  // index among the higher-order nodes
  switch (linearType(t)) {
    case CellType::Quad4: return k < 4 ? edge(kQuadEdges[k]) : all(4);
    case CellType::Tri3: return edge(kTriEdges[k]);
    case CellType::Tet4: return edge(kTetEdges[k]);
    default: break;
  }
  if (k < 12) return edge(kHexEdges[k]);
  if (k == 12) return all(8);
  const int* f = kHexFaceCentres[k - 13];
  return {4, {f[0], f[1], f[2], f[3]}};
}

std::string toString(CellType t) {
  switch (t) {
    case CellType::Quad4: return "QUAD4";
    case CellType::Tri3: return "TRI3";
    case CellType::Hex8: return "HEX8";
    case CellType::Tet4: return "TET4";
    case CellType::Quad8: return "QUAD8";
    case CellType::Quad9: return "QUAD9";
    case CellType::Tri6: return "TRI6";
    case CellType::Hex20: return "HEX20";
    case CellType::Hex27: return "HEX27";
    case CellType::Tet10: return "TET10";
  }
  return "unknown";
}

std::string toString(FaceType t) {
  switch (t) {
    case FaceType::Line2: return "LINE2";
    case FaceType::Tri3: return "TRI3";
    case FaceType::Quad4: return "QUAD4";
    case FaceType::Line3: return "LINE3";
    case FaceType::Tri6: return "TRI6";
    case FaceType::Quad8: return "QUAD8";
    case FaceType::Quad9: return "QUAD9";
  }
  return "unknown";
}

}  // namespace coulomb::mesh
