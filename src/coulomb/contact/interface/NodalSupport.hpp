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
#include <vector>

#include "coulomb/contact/interface/MortarPass.hpp"

namespace coulomb::contact {

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
