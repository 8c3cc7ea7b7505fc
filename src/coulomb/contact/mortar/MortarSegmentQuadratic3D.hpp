#pragma once
/// @file MortarSegmentQuadratic3D.hpp
/// @brief Mortar integration of a 3D face pair of which one is quadratic
/// (Quad9, Quad8 or Tri6; issue 18, item 2): the quantities of
/// MortarSegment3D.hpp (D_j, M_jl, g~_j and their derivatives), segmented on
/// linear sub-facets.
///
/// The dual basis: a Quad9's standard biquadratic one has D_j = int N_j dA
/// > 0 at every node, so D stays diagonal and positive and the condensation
/// works as for linear faces. Quad8 and Tri6 have a negative or zero int N_j
/// at the corners; their dual basis is built on the transformed basis N~
/// (DualBasis.hpp, faceTrialValues), so D_j = int N~_j > 0, and the pair's
/// rows are carried between the transformed and the physical slave nodes by
/// SlaveTransform.hpp. The master side always takes its standard shape
/// functions N^2_l, so any slave type pairs with any master type (a HEX27
/// body on a TET10 one); a slave surface takes one kind of quadratic face
/// (Quad9, or Quad8 / Tri6: SlaveTransform.hpp).
///
/// Segmentation (Puso and Laursen's sub-facets, as in the dual quadratic
/// mortar of Popp, Wohlmuth, Gee and Wall): a Quad9 is split into its four
/// Quad4 quadrants (nodes 0 4 8 7, 4 1 5 8, 8 5 2 6, 7 8 6 3), a Tri6 into
/// its four triangles (0 3 5, 3 1 4, 5 4 2, 3 4 5), a Quad8 (no centre node)
/// into a triangle at each corner (0 4 7, 1 5 4, 2 6 5, 3 7 6) and the
/// quadrilateral of its mid-sides (4 5 6 7); a Tri3 or Quad4 is one sub-facet. Each (slave sub-facet, master sub-facet) pair is
/// clipped on the auxiliary plane of the slave sub-facet exactly as in
/// MortarSegment3D.hpp (projection along its normal, Sutherland-Hodgman,
/// the fan of triangles from the centroid, the 7-point rule). A Gauss point
/// is mapped back to each sub-facet's own coordinates and from there
/// (affinely) to the parent face's, where the quadratic quantities are
/// evaluated: the dual functions Phi_j, the master's N^2_l, the points
/// x^1, x^2 of the quadratic faces, the interpolated normal n; the measure is
/// the sub-facet's. Exact for plane parallel faces in the patch-test sense
/// (sum_l M_jl = D_j, g~_j = g D_j, D_j = int N~_j under a covering master);
/// an approximation on curved faces (the sub-facets are their chords).
#include "coulomb/contact/mortar/MortarSegment3D.hpp"

namespace coulomb::contact {

/// @brief Integrates one pair (S or Mf quadratic: Quad9, Quad8 or Tri6; the
/// other any of Tri3, Quad4, Tri6, Quad8, Quad9).
template <mesh::FaceType S, mesh::FaceType Mf, typename T>
MortarSegment3D<S, Mf, T> integrateQuadraticSegment3D(const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns,
                                                      const FaceNodes<Mf, T>& xm, double relativeTolerance);

/// @brief Values and derivatives (input order as linearizeSegment3D): Sacado
/// SFad over the coordinates alone (SubFacetFad3D), the nodal normals'
/// derivatives (of g~ only) summed by hand.
template <mesh::FaceType S, mesh::FaceType Mf>
MortarSegment3DLinearization<S, Mf> linearizeQuadraticSegment3D(const FaceNodes<S, double>& xs,
                                                                const FaceNodes<S, double>& ns,
                                                                const FaceNodes<Mf, double>& xm,
                                                                double relativeTolerance);

}  // namespace coulomb::contact
