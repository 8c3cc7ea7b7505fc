#pragma once
/// @file MeshChecks.hpp
/// @brief Checks of a mesh as read, before any solve, for the defects that
/// meshers leave and that would otherwise surface as a singular matrix, a
/// body that falls apart or a contact surface that never closes: nodes at
/// one point that no element joins, cells of zero volume, contact side sets
/// inside a body. Each failing check is a one-line coulomb::Error naming the
/// nodes, element or face. Every rank holds the whole mesh, so every rank
/// reaches the same verdict.
#include <array>
#include <string>
#include <vector>

#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::fem {

/// Signed length (2D: area) measure of one cell: the area of a TRI3 or QUAD4
/// (x-y plane, positive counter-clockwise), the volume of a TET4, and of a
/// HEX8 the sum of its six tetrahedra about the diagonal 0-6 (Exodus order;
/// exact for planar faces). `X` holds the nodes' coordinates node-major.
double cellMeasure(mesh::CellType type, const double* X);

/// The largest distance between two nodes of the cell.
double cellDiameter(mesh::CellType type, const double* X);

/// A cell of zero volume: |measure| at most 1e-10 diameter^dim (round-off
/// of a cell whose nodes lie on one plane or line is about 1e-16).
bool hasZeroVolume(mesh::CellType type, const double* X);

/// Two nodes at one point (within 1e-10 of the mesh's bounding-box
/// diagonal), both used by elements, in no element together, and neither
/// `exempt` (nodes of contact surfaces: two bodies meshed touching share
/// points legitimately): an unmerged mesh, whose parts are not joined. Returns the pair (0-based),
/// the lower number first, or {-1, -1}.
std::array<long long, 2> findCoincidentNodes(const mesh::GlobalMesh& mesh, const std::vector<char>& exempt);

/// Throws, naming `file` and the two nodes, when findCoincidentNodes finds a pair.
void checkCoincidentNodes(const mesh::GlobalMesh& mesh, const std::vector<char>& exempt, const std::string& file);

/// An axisymmetric mesh lies in x >= 0 (x is the radius): throws, naming
/// `file`, the first node with x below -1e-10 of the bounding-box diagonal.
void checkAxisymmetricMesh(const mesh::GlobalMesh& mesh, const std::string& file);

/// The element other than `element` that has every node of side `side` of
/// `element` (the face is inside the body), or -1 for a boundary face.
/// `adjacency` is from nodeElementAdjacency.
struct NodeElementAdjacency {
  std::vector<long long> offsets;   ///< per node, into elements
  std::vector<long long> elements;  ///< the elements of each node, ascending
};
NodeElementAdjacency nodeElementAdjacency(const mesh::GlobalMesh& mesh);
long long elementAcrossFace(const mesh::GlobalMesh& mesh, const NodeElementAdjacency& adjacency, long long element,
                            int side);

}  // namespace coulomb::fem
