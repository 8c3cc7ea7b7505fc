#pragma once
/// @file ExodusReader.hpp
/// @brief Reads an Exodus II mesh file into a GlobalMesh.
///
/// Why a thin reader of our own instead of SEACAS/Ioss: Trilinos 13.2 on
/// Debian ships without SEACAS, while the plain exodusII C library
/// (libexodusii-dev, 6.02) is available and reads every mesh we use (netCDF-3
/// and netCDF-4 files, 32- or 64-bit ids and connectivity). The exodusII
/// headers stay in the .cpp so that including this file costs nothing.
#include <string>

#include "coulomb/core/MemoryBudget.hpp"
#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::io {

/// @brief Reads coordinates, element blocks, node sets and side sets (with
/// their names) of the Exodus II file @p path.
///
/// - Node and element numbers become 0-based; elements are numbered globally
///   across blocks in the order the file stores the blocks
///   (ElementBlock::firstElement), as Exodus itself numbers them.
/// - Accepted element types (case-insensitive, as Exodus writers spell them):
///   QUAD/QUAD4 and TRI/TRI3/TRIANGLE in 2D files, HEX/HEX8/HEXAHEDRON and
///   TET/TET4/TETRA/TETRA4 in 3D files, with the matching number of nodes
///   per element. Anything else (HEX20, SHELL4, BEAM, a 2D type in a 3D file
///   ...) throws coulomb::Error naming the file, the block and the type.
/// - Side numbers become 0-based (Exodus side - 1); node set distribution
///   factors, attributes, maps and results in the file are ignored.
///
/// @throws coulomb::Error naming @p path when the file is missing, is not an
/// Exodus file, or holds something Coulomb cannot use, or when the counts
/// of its header need more memory than @p budget gives
/// (meshMemoryProblem: a damaged header or a mesh too large for the
/// machine; checked before anything is allocated).
mesh::GlobalMesh readExodus(const std::string& path, const MemoryBudget& budget);

/// @brief readExodus for one process: the budget is this machine's
/// available memory (availableMemoryBytes).
mesh::GlobalMesh readExodus(const std::string& path);

/// @brief Parses an Exodus element type name (case-insensitive) with its
/// number of nodes per element; returns false if Coulomb does not support it.
/// Exposed for the tests and for error messages elsewhere.
bool parseExodusElementType(const std::string& type, int nodesPerElement, mesh::CellType& cellType);

}  // namespace coulomb::io
