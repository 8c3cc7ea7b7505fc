#pragma once
/// @file GlobalMesh.hpp
/// @brief The whole mesh as read from an Exodus II file, before partitioning.
///
/// Every rank holds one copy (see docs/architecture.md, "Mesh distribution"):
/// node and element numbers are 0-based versions of the Exodus numbers, so
/// Exodus node 17 is node 16 here and global DoF 3*16+c in 3D.
#include <string>
#include <vector>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::mesh {

/// @brief An element block: one cell type, connectivity in Exodus node order.
struct ElementBlock {
  std::string name;  ///< Exodus block name ("" if unnamed; then addressed as "block_<id>")
  int id = 0;        ///< Exodus block id
  CellType cellType = CellType::Hex8;
  /// 0-based global node numbers, numNodes(cellType) per element
  std::vector<long long> connectivity;
  /// 0-based global element number of this block's first element
  long long firstElement = 0;
  long long numElements() const {
    return static_cast<long long>(connectivity.size()) / numNodes(cellType);
  }
};

/// @brief A named set of nodes (0-based global node numbers).
struct NodeSet {
  std::string name;
  int id = 0;
  std::vector<long long> nodes;
};

/// @brief A named set of element sides: (global element, 0-based local side
/// in Exodus side numbering) pairs.
struct SideSet {
  std::string name;
  int id = 0;
  std::vector<long long> elements;  ///< 0-based global element numbers
  std::vector<int> sides;           ///< 0-based local side numbers (Exodus side - 1)
};

/// @brief The full mesh: coordinates (dimension per node, interleaved),
/// blocks, node sets, side sets.
struct GlobalMesh {
  int dimension = 3;
  std::vector<double> coordinates;  ///< x0 y0 [z0] x1 y1 [z1] ...
  std::vector<ElementBlock> blocks;
  std::vector<NodeSet> nodeSets;
  std::vector<SideSet> sideSets;

  long long numNodes() const { return static_cast<long long>(coordinates.size()) / dimension; }
  long long numElements() const;
};

/// Name under which a block, node set or side set is addressed in a deck:
/// its Exodus name, or "<kind>_<id>" when the file gives none.
std::string displayName(const std::string& name, const char* kind, int id);

}  // namespace coulomb::mesh
