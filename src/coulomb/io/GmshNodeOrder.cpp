/// @file GmshNodeOrder.cpp
/// @brief Node permutations of quadratic cells, derived from mesh::nodeCorners.
#include "coulomb/io/GmshNodeOrder.hpp"

#include <algorithm>

namespace coulomb::io {

using mesh::CellType;

namespace {

/// Sorted corner set of node `a` of a cell (mesh::nodeCorners).
std::vector<int> sortedCorners(const mesh::NodeCorners& c) {
  std::vector<int> v(c.corners.begin(), c.corners.begin() + c.count);
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

std::vector<int> cornerPermutation(CellType type, const std::vector<int>& corners) {
  const int n = mesh::numNodes(type), nc = mesh::numCorners(type);
  std::vector<int> p(corners);
  for (int a = nc; a < n; ++a) {  // new node a: its corners (new numbers), as old numbers
    mesh::NodeCorners want = mesh::nodeCorners(type, a);
    for (int k = 0; k < want.count; ++k) want.corners[k] = corners[static_cast<std::size_t>(want.corners[k])];
    const std::vector<int> key = sortedCorners(want);
    int found = -1;
    for (int b = nc; b < n && found < 0; ++b)
      if (sortedCorners(mesh::nodeCorners(type, b)) == key) found = b;
    p.push_back(found);
  }
  return p;
}

std::vector<int> flipPermutation(CellType type) {
  static const std::vector<int> tri{0, 2, 1}, quad{0, 3, 2, 1}, tet{0, 2, 1, 3}, hex{0, 3, 2, 1, 4, 7, 6, 5};
  switch (mesh::linearType(type)) {
    case CellType::Tri3: return cornerPermutation(type, tri);
    case CellType::Quad4: return cornerPermutation(type, quad);
    case CellType::Tet4: return cornerPermutation(type, tet);
    default: break;
  }
  return cornerPermutation(type, hex);
}

std::vector<int> gmshToExodus(CellType type) {
  using Set = std::vector<int>;
  static const std::vector<Set> kTet10{{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  static const std::vector<Set> kHex{{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7},
                                     {4, 5}, {4, 7}, {5, 6}, {6, 7},
                                     // HEX27 only: face centres, then the cell centre
                                     {0, 1, 2, 3}, {0, 1, 4, 5}, {0, 3, 4, 7}, {1, 2, 5, 6}, {2, 3, 6, 7},
                                     {4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}};
  const int n = mesh::numNodes(type), nc = mesh::numCorners(type);
  std::vector<int> p(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) p[static_cast<std::size_t>(i)] = i;
  const std::vector<Set>* table = type == CellType::Tet10 ? &kTet10
                                  : (type == CellType::Hex20 || type == CellType::Hex27) ? &kHex
                                                                                         : nullptr;
  if (!table) return p;  // TRI6, QUAD8, QUAD9: the Exodus order
  for (int a = nc; a < n; ++a) {
    const Set key = sortedCorners(mesh::nodeCorners(type, a));
    for (int g = 0; g < n - nc; ++g) {
      Set s = (*table)[static_cast<std::size_t>(g)];
      std::sort(s.begin(), s.end());
      if (s == key) p[static_cast<std::size_t>(a)] = nc + g;
    }
  }
  return p;
}

std::vector<std::vector<int>> quadraticSides(CellType type, const std::vector<std::vector<int>>& linear) {
  std::vector<std::vector<int>> sides;
  for (const auto& corners : linear) {
    std::vector<int> side(corners);
    for (int a = mesh::numCorners(type); a < mesh::numNodes(type); ++a) {
      const mesh::NodeCorners c = mesh::nodeCorners(type, a);
      bool on = true;
      for (int k = 0; k < c.count && on; ++k)
        on = std::find(corners.begin(), corners.end(), c.corners[k]) != corners.end();
      if (on) side.push_back(a);
    }
    sides.push_back(std::move(side));
  }
  return sides;
}

}  // namespace coulomb::io
