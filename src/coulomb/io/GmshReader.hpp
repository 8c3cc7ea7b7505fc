#pragma once
/// @file GmshReader.hpp
/// @brief Converts a gmsh .msh file into a GlobalMesh.
///
/// Why: meshes are authored as gmsh .geo scripts (exodus_meshes/) and the
/// solver reads only Exodus II; coulomb_gmsh2exo = readGmsh() + ExodusWriter.
/// gmsh's own library (C++ API, Debian libgmsh-dev) reads the file, so every
/// .msh gmsh writes is read: versions 2.2 and 4.x (4.1 is gmsh's default,
/// what scripts/make_mesh writes), ASCII and binary, any element order.
/// Only files that start with $MeshFormat (or msh 1's $NOD) are handed to
/// it: gmsh would run anything else as a .geo script. gmsh's library is
/// process-wide state: readGmsh is not thread-safe, and a program that uses
/// gmsh's API itself must not be inside a gmsh::initialize when it calls
/// readGmsh (readGmsh initialises and finalises gmsh for each file).
/// Lives in the library coulomb_gmsh, not in libcoulomb (CMakeLists.txt).
///
/// Mapping of physical groups (d = highest element dimension in the file):
/// - dimension d (surfaces in 2D, volumes in 3D) -> element blocks, in
///   ascending physical tag order; id = physical tag, name = physical name.
///   One block holds one cell type (QUAD4, TRI3, HEX8, TET4 or, from a mesh
///   of order 2, QUAD8, QUAD9, TRI6, HEX20, HEX27, TET10).
/// - dimension d-1 -> a side set AND a node set of the same name and id
///   (physical tag). Each boundary element is matched to the bulk element
///   side with exactly its nodes; if two bulk elements share that side (an
///   interior face) the first in block order is taken.
/// - dimension < d-1 (points, and curves in 3D) -> node sets; id = physical
///   tag unless a set of dimension d-1 already has it, then the next free id.
/// - Elements in no physical group are ignored, as are nodes no bulk element
///   uses (geometry points); nodes are renumbered compactly in gmsh tag order.
/// - 2D meshes must lie in the plane z = 0; z is dropped. Cells are oriented
///   counter-clockwise (2D) / with positive volume (3D), flipped if needed;
///   degenerate or inverted-after-flip (non-convex) cells are errors.
/// gmsh's node order for line2/tri3/quad4/tet4/hex8 and line3/tri6/quad8/quad9
/// is Exodus' order; TET10, HEX20 and HEX27 cells are renumbered (their edge
/// and face nodes come in another order in gmsh). Orientation of a quadratic
/// cell is judged by its corners. Boundary elements of order 2 (line3, tri6,
/// quad8, quad9) match the sides of the quadratic cells.
#include <string>
#include <vector>

#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::io {

/// @brief Reads and converts @p path (see the file comment for the rules).
/// @throws coulomb::Error naming @p path (and group or element where it
/// applies) on a missing file, a file that is no .msh, anything gmsh cannot
/// read (with gmsh's message), an unsupported element type, a physical group
/// mixing cell types, or a boundary element that is not the side of any bulk
/// element. gmsh prints nothing (its messages go to its logger).
mesh::GlobalMesh readGmsh(const std::string& path);

/// @brief 0-based local nodes of 0-based Exodus side @p side of a @p type cell,
/// ordered so that the side's normal (right-hand rule in 3D; (dy,-dx) of the
/// edge in 2D) points out of a positively oriented cell.
/// QUAD4/TRI3: side k = nodes k, k+1. HEX8 (1-based): 1-2-6-5, 2-3-7-6,
/// 3-4-8-7, 1-5-8-4, 1-4-3-2, 5-6-7-8. TET4 (1-based): 1-2-4, 2-3-4, 1-4-3, 1-3-2.
/// Quadratic cells: those corners, then the side's edge (and face centre)
/// nodes in cell node order (a node set for matching, not the face's order:
/// fem::faceLocalNodes gives that).
const std::vector<int>& exodusSideNodes(mesh::CellType type, int side);

}  // namespace coulomb::io
