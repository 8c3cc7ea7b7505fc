#pragma once
/// @file SharpEdges.hpp
/// @brief Slave nodes on a sharp edge or corner of the slave surface, and the
/// faces whose normals make their nodal normal.
///
/// Why: the nodal normal n_j averages the corner normals of every slave face
/// around node j (NodalNormals.hpp). Across a sharp edge — a block whose
/// bottom and sides are one slave surface — that average points 45 degrees
/// out of the bottom, the weighted gap and the friction cone of the edge
/// nodes are measured along it, and those nodes do not close on a flat
/// master (found on neo_hookean_shear_3d with the block's sides in its slave
/// set). A user selecting a whole body's skin is common; splitting it into
/// one pair per smooth patch is not something they should have to do.
///
/// Rule:
///  1. Feature groups (featureGroups): the faces around node j are grouped by
///     their corner normals m_f(j): two faces are in one group when the angle
///     between their corner normals is at most the pair's 'Feature Angle'
///     (single linkage, so a finely faceted smooth bend stays one group).
///     One group: a smooth node, its normal is the plain average.
///  2. A sharp node (two groups or more) takes the faces of the group that
///     faces the master (facingGroups): for each group g, with n_g its
///     averaged normal, the score max_m (-n_g . n_m) over the master faces m
///     within the search radius r of the node (n_m the outward normal of the
///     master face's corner plane; in self-contact the faces containing the
///     node are left out). The groups within 1e-3 of the best score are
///     taken together if the best is at least cos(Feature Angle) (a master
///     face within the feature angle of opposite, as the search's facing
///     test); else none faces a master and the node keeps the plain average
///     (it is not near a contact).
///  3. The search pairs a slave face with a master face only when their
///     normals are within the feature angle of opposite (facingNormalDot):
///     a side face tilted by the load would otherwise overlap a flat master
///     on its auxiliary plane, with gaps measured sideways.
///
/// The choice is made at each contact search (ContactPair::search) and kept
/// until the next one, so between searches n_j is a smooth
/// function of the coordinates of the chosen faces and its Sacado derivative
/// (computeNodalNormals) is exact; a choice changing at a search is a
/// discrete change like an active-set change. A node with a degenerate face
/// around it keeps the plain average (computeNodalNormals then reports the
/// face).
///
/// Parallel: every rank holds every interface face and the current
/// coordinates of every interface node, so every rank makes the same choice
/// for a node without communication.
#include <array>
#include <vector>

#include "coulomb/contact/interface/ContactInterface.hpp"

namespace coulomb::contact {

/// @brief Kernel: the feature group of each unit normal (single linkage: two
/// normals at an angle <= featureAngle [radians] are in one group). Groups
/// are numbered 0, 1, ... in the order of their first member.
std::vector<int> featureGroups(const std::vector<std::array<double, 3>>& normals, double featureAngle);

/// @brief Kernel: the groups that face a master: those whose score
/// max_m (-groupNormals[g] . masterNormals[m]) is within 1e-3 of the best,
/// if the best is at least minimumScore; empty otherwise.
std::vector<int> facingGroups(const std::vector<std::array<double, 3>>& groupNormals,
                              const std::vector<std::array<double, 3>>& masterNormals, double minimumScore);

/// The facing test of the search (searchContactPairs' maximumNormalDot):
/// slave and master faces pair when their normals are within the feature
/// angle of opposite, n_s . n_m <= -cos(angle); 1 (no test) at 180 degrees.
double facingNormalDot(double featureAngleDegrees);

/// @brief Which faces around each slave node make its nodal normal.
struct SlaveNormalFaces {
  /// faces[i] for slave node i: the positions k (0-based, within the node's
  /// faces slaveNodeFaces()[offset[i] + k]) of the faces to average, increasing;
  /// empty: all of them. Empty vector: every node averages all its faces.
  std::vector<std::vector<int>> faces;
  /// Of the nodes examined: the global numbers of the sharp ones, and of
  /// those that took a facing group's faces (increasing).
  std::vector<long long> sharpNodes, facingNodes;

  bool allFaces(int slaveNode) const {
    return faces.empty() || faces[static_cast<std::size_t>(slaveNode)].empty();
  }
};

/// @brief The choice for the slave nodes `slaveNodeIndices` (indices into
/// slaveNodes(); nullptr: all) in configuration x, with the search radius r.
/// featureAngleDegrees >= 180 turns it off (every node averages all its faces).
/// Not collective; deterministic (the same answer on every rank).
SlaveNormalFaces chooseSlaveNormalFaces(const ContactInterface& contact, const InterfaceConfiguration& x,
                                        double featureAngleDegrees, double radius,
                                        const std::vector<int>* slaveNodeIndices = nullptr);

}  // namespace coulomb::contact
