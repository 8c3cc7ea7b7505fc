#pragma once
/// @file NodalSupport.hpp
/// @brief The measure a slave node's D_j has when its whole support lies on
/// the master (S_j), and its derivative: what the coverage test of the
/// objective slip compares D_j with (ContactPair::objectiveWeight;
/// docs/architecture.md, "Coverage").
///
/// S_j is D_j of the node with each of its slave faces paired with itself
/// (the segment kernel the mortar pass uses, with the face as its own
/// master). On linear faces that is int N_j dA (the dual basis integrates
/// to it face by face) to 1e-9; on Quad9, Quad8 and Tri6 faces the sub-facet
/// kernel's measure is that of the sub-facets, the chords of a curved face,
/// and int N~_j on the curved face differs from a covered D_j by up to 4e-3
/// (Mortar3DQuadratic.CurvedFaceUnderACoveringMasterHasItsSelfIntegral).
/// A 3D face too crumpled for the kernel to project it onto the plane of
/// one of its own pieces (the kernel's bow-tie or non-convex error) takes
/// int N~_j on the curved face instead (faceMass): S_j is a scale, and a
/// geometry error there must not stop a run whose real mortar pairs work.
#include <array>
#include <vector>

#include "coulomb/contact/interface/MortarPass.hpp"

namespace coulomb::contact {

/// @brief S of each node of slave face f (in the order of f.nodes) at x:
/// the face paired with itself, or its int N~_j (see above). Not collective.
std::array<double, mesh::kMaxFaceNodes> faceSupportMeasures(const ContactFace& f, const InterfaceConfiguration& x,
                                                            bool axisymmetric, double relativeTolerance = 1e-12);

/// @brief Adds d S / d x of face f's node `corner` (index into f.nodes) to
/// `row`, keyed by the DoFs of f's nodes.
void addFaceSupportMeasureDerivative(const ContactFace& f, const InterfaceConfiguration& x, bool axisymmetric,
                                     int corner, DerivativeRow& row, double relativeTolerance = 1e-12);

/// @brief S_j of each entry's node in the configuration x (the nodes' slave
/// faces must be in x). Each face is integrated once. Not collective.
std::vector<double> nodalSupportMeasures(const ContactInterface& contact, const InterfaceConfiguration& x,
                                         const std::vector<NodalMortarEntry>& entries,
                                         double relativeTolerance = 1e-12);

/// @brief d S_j / d x of the slave node `node` (global number), keyed by
/// the DoFs of the nodes of its slave faces. Not collective.
DerivativeRow nodalSupportMeasureDerivative(const ContactInterface& contact, const InterfaceConfiguration& x,
                                            long long node, double relativeTolerance = 1e-12);

}  // namespace coulomb::contact
