#pragma once
/// @file MortarScalarTypes.hpp
/// @brief The Sacado scalar types the mortar kernels are instantiated for,
/// derived from the kernels' input counts (one place, so DualBasis and
/// PolygonClipping instantiate exactly what the segment kernels use).
/// Includes Sacado: for .cpp files only.
#include <Sacado.hpp>

#include "coulomb/contact/mortar/MortarSegment2D.hpp"
#include "coulomb/contact/mortar/MortarSegment3D.hpp"

namespace coulomb::contact {

/// Forward AD over the 12 inputs of a Line2/Line2 segment.
using SegmentFad2D = Sacado::Fad::SFad<double, kSegment2DInputs>;
/// Forward AD over the inputs of a slave S / master Mf segment in 3D.
template <mesh::FaceType S, mesh::FaceType Mf>
using SegmentFad3D = Sacado::Fad::SFad<double, segment3DInputs<S, Mf>>;
/// Forward AD over the coordinates of a slave S / master Mf pair alone (the
/// sub-facet kernel of MortarSegmentQuadratic3D differentiates the normals by hand).
template <mesh::FaceType S, mesh::FaceType Mf>
using SubFacetFad3D = Sacado::Fad::SFad<double, 3 * (FaceTraits<S>::nodes + FaceTraits<Mf>::nodes)>;

}  // namespace coulomb::contact
