#pragma once
/// @file NodalNormals.hpp
/// @brief Averaged unit normals at the slave nodes in the current configuration,
/// and their derivatives with respect to the nodal coordinates.
///
/// Definition (the "nodal normal" of the mortar formulation, seed: the slave
/// normal n used in the weighted gap -n.(D x^1 - M x^2)): at slave node j,
///   n_j = s_j / |s_j|,   s_j = sum over the slave faces f containing j of m_f(j),
/// where m_f(j) is the unit outward normal of face f at its corner j:
///   Line2 (2D): (dy, -dx)/len, d = x_1 - x_0 (the same at both nodes);
///   Line3 (2D): the same with d = dx/dxi of the quadratic edge at the node
///          (xi = -1, 1, 0): a mid-side node has one face, a corner the
///          tangents of its two faces at their ends;
///   Tri3: (x_1 - x_0) × (x_2 - x_0) normalised (the same at all corners);
///   Quad4: x_xi × x_eta of the bilinear face at the corner, normalised, i.e.
///          (x_next - x_a) × (x_prev - x_a) at corner a (next/prev in face order);
///   Quad9: x_xi × x_eta of the biquadratic face at each of its nine nodes.
/// Every adjacent face counts once (unit normals, equal weights): on a flat
/// surface n_j is the plane normal exactly; on a smooth curved surface with a
/// smoothly varying (structured) faceting the error against the exact normal is
/// O(h²) (the O(h) tilts of the faces on either side of the node cancel to
/// leading order); on an irregular faceting it is O(h) in general.
/// Face nodes are in the outward order of fem::faceLocalNodes, so n points out
/// of the slave body, towards the master.
///
/// Derivatives: the face kernel faceCornerNormals is templated on the scalar
/// and differentiated with Sacado forward AD (SFad over the face's coordinates,
/// in the .cpp); the normalisation s -> s/|s| likewise (SFad over s); the chain
/// rule dn/dx = dn/ds · sum_f dm_f/dx is then a small product. The result is a
/// sparse list over the nodes of all faces around j.
///
/// Scalars: faceCornerNormals is explicitly instantiated for double and for
/// Sacado::Fad::SFad<double, dim × nodes> (4 Line2, 6 Line3, 9 Tri3, 12 Quad4, 27 Quad9); only the
/// double versions are declared here (no Sacado in headers).
#include <array>
#include <vector>

#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/SharpEdges.hpp"
#include "coulomb/contact/mortar/DualBasis.hpp"

namespace coulomb::contact {

/// @brief Kernel: unit outward normal of the face at each of its corners
/// (m[a] at corner a). Throws coulomb::Error for a degenerate face (zero edge
/// or zero area at a corner).
template <mesh::FaceType F, typename T>
FaceNodes<F, T> faceCornerNormals(const FaceNodes<F, T>& x);

extern template FaceNodes<mesh::FaceType::Line2, double> faceCornerNormals<mesh::FaceType::Line2, double>(
    const FaceNodes<mesh::FaceType::Line2, double>&);
extern template FaceNodes<mesh::FaceType::Line3, double> faceCornerNormals<mesh::FaceType::Line3, double>(
    const FaceNodes<mesh::FaceType::Line3, double>&);
extern template FaceNodes<mesh::FaceType::Tri3, double> faceCornerNormals<mesh::FaceType::Tri3, double>(
    const FaceNodes<mesh::FaceType::Tri3, double>&);
extern template FaceNodes<mesh::FaceType::Quad9, double> faceCornerNormals<mesh::FaceType::Quad9, double>(
    const FaceNodes<mesh::FaceType::Quad9, double>&);
extern template FaceNodes<mesh::FaceType::Quad4, double> faceCornerNormals<mesh::FaceType::Quad4, double>(
    const FaceNodes<mesh::FaceType::Quad4, double>&);

/// @brief One face around a node: the input of averagedNormal.
struct FaceAtNode {
  mesh::FaceType type = mesh::FaceType::Line2;
  int corner = 0;                               ///< position of the node in the face
  std::array<long long, mesh::kMaxFaceNodes> nodes{};  ///< global node numbers (label the derivative)
  std::array<std::array<double, 3>, mesh::kMaxFaceNodes> x{};  ///< current coordinates (x[a][2] unused in 2D)
};

/// @brief Face k of the node-to-face lists (contact.slaveNodeFaces()[k]) as
/// seen from its node (slaveNodeFaceCorners()[k]) in configuration x.
FaceAtNode faceAtNode(const ContactInterface& contact, const InterfaceConfiguration& x, int k);

/// @brief d n / d x_{node, component}: one column of the normal's derivative.
struct NormalDerivative {
  long long node = -1;         ///< global node number
  int component = 0;           ///< coordinate component of that node
  std::array<double, 3> dn{};  ///< dn[i] = d n_i / d x_{node,component}; dn[2] = 0 in 2D
};

/// @brief A nodal normal and (optionally) its derivative.
struct NodalNormal {
  std::array<double, 3> n{};  ///< unit normal; n[2] = 0 in 2D
  /// Pattern: every (node, component) of the faces around the node, sorted by
  /// node then component (some columns may be zero: a Quad4 corner normal does
  /// not depend on the opposite corner); empty when derivatives were not requested.
  std::vector<NormalDerivative> derivative;
};

/// @brief n = normalize(sum_f m_f(corner)) over `faces` (all around the same node;
/// Line2 faces when dimension = 2, Tri3/Quad4 when 3).
/// Throws coulomb::Error naming the node when a face is degenerate or the face
/// normals cancel (|s| below 1e-8 × the number of faces).
NodalNormal averagedNormal(int dimension, const std::vector<FaceAtNode>& faces, bool withDerivative);

/// @brief Nodal normals at the slave nodes of `contact` in configuration `x`.
///
/// Returns one entry per ContactInterface::slaveNodes() entry. `slaveNodeIndices`
/// (indices into slaveNodes()) restricts the work to those nodes, e.g.
/// slaveNodesOfFaces (InterfaceBalance.hpp) of the faces a rank integrates; entries not
/// listed stay zero. Default (nullptr): every slave node. No communication:
/// with the same configuration every rank computes the same normals (and
/// throws the same errors when it computes every node).
/// `faces` (SharpEdges.hpp): at a sharp node, the faces whose corner normals
/// are averaged (the group facing the master); nullptr or an empty entry:
/// all the node's faces.
std::vector<NodalNormal> computeNodalNormals(const ContactInterface& contact, const InterfaceConfiguration& x,
                                             bool withDerivatives,
                                             const std::vector<int>* slaveNodeIndices = nullptr,
                                             const SlaveNormalFaces* faces = nullptr);

}  // namespace coulomb::contact
