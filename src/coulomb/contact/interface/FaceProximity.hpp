#pragma once
/// @file FaceProximity.hpp
/// @brief Where a point lies relative to one contact face: its distance to the
/// face, its signed distance along the face's outward normal, and whether its
/// normal projection falls on the face. A kernel on fixed-size arrays (no MPI).
///
/// Used by the contact search (ContactSearch.cpp) to find slave nodes that lie
/// inside the master body beyond the search radius: a node whose nearest
/// master face has it behind (signed distance < 0) with its projection on the
/// face is inside the master, however deep (bodies that overlap in the mesh).
///
/// Geometry: Line2 (2D) exactly; Tri3 exactly; Quad4 by its mean plane (the
/// Newell normal through the node average) with the projection tested against
/// the projected quadrilateral's edges (exact for a plane Quad4). The outward
/// normal follows the node order of ContactFace (right-hand rule in 3D,
/// (dy, -dx) in 2D).
#include <array>

namespace coulomb::contact {

struct FaceProximity {
  double distance = 0.0;       ///< Euclidean distance from the point to the face (>= 0)
  double normalDistance = 0.0; ///< (p - face) . n_outward: < 0 behind the face
  bool overFace = false;       ///< the normal projection of p lies on the face (edges included)
};

/// @brief The outward unit normal of the face (Line2: (dy, -dx); Tri3 /
/// Quad4: Newell's normal, the mean plane's); false for a degenerate face.
bool faceOutwardNormal(int dim, int numNodes, const std::array<std::array<double, 3>, 4>& nodes,
                       std::array<double, 3>& normal);

/// @brief `dim` = 2 (numNodes = 2) or 3 (numNodes = 3 or 4); `nodes[a]` the
/// coordinates of node a in outward order, `p` the point. A degenerate face
/// (zero length or area) gives the distance to its nodes and overFace = false.
FaceProximity faceProximity(int dim, int numNodes, const std::array<std::array<double, 3>, 4>& nodes,
                            const std::array<double, 3>& p);

}  // namespace coulomb::contact
