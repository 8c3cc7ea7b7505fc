#pragma once
/// @file FaceKernel.hpp
/// @brief Consistent nodal forces of surface loads (traction, pressure) on a
/// reference-configuration face, and face measures.
///
/// Face nodes are in the order of faceLocalNodes (outward right-hand-rule normal);
/// X is node-major (x0 y0 [z0] x1 ...). Line2/Line3 faces live in the x-y plane.
#include <array>

#include "coulomb/fem/ShapeFunctions.hpp"
#include "coulomb/mesh/CellType.hpp"

namespace coulomb::fem {

/// @brief Compile-time sizes of a face type (dim = spatial dimension of its coordinates).
template <mesh::FaceType F>
struct FaceTraits {
  static constexpr int nodes = mesh::numNodes(F);
  static constexpr int dim = (F == mesh::FaceType::Line2 || F == mesh::FaceType::Line3) ? 2 : 3;
  static constexpr int dofs = nodes * dim;
  static constexpr ReferenceShape shape = referenceShape(F);
};

/// @brief Consistent nodal forces of a uniform traction t: f_a = \int_A N_a t dA (2D: x thickness).
///
/// dA is the reference area element |dX/dxi x dX/deta| dxi deta (2D: |dX/dxi| dxi);
/// `thickness` is ignored for 3D faces; `axisymmetric` (2D): 2 pi r instead of the
/// thickness, r = x at each quadrature point (the whole ring's force). force is overwritten.
template <mesh::FaceType F>
void faceTractionForces(const std::array<double, FaceTraits<F>::dofs>& X,
                        const std::array<double, FaceTraits<F>::dim>& traction, double thickness,
                        std::array<double, FaceTraits<F>::dofs>& force, bool axisymmetric = false);

/// @brief Consistent nodal forces of a uniform pressure: f_a = -p \int_A N_a n dA (2D: x thickness).
///
/// p > 0 pushes into the body. n dA = dX/dxi x dX/deta dxi deta (2D: (dy, -dx) dxi) is the
/// pointwise outward area element, so warped Quad4 faces are integrated exactly (curved
/// quadratic faces to the order of their rule).
/// `thickness` is ignored for 3D faces; `axisymmetric` as above. force is overwritten.
template <mesh::FaceType F>
void facePressureForces(const std::array<double, FaceTraits<F>::dofs>& X, double pressure, double thickness,
                        std::array<double, FaceTraits<F>::dofs>& force, bool axisymmetric = false);

/// @brief Reference area \int_A dA of a face (2D: edge length, no thickness).
template <mesh::FaceType F>
double faceArea(const std::array<double, FaceTraits<F>::dofs>& X);

/// @brief Area vector \int_A n dA of a face (outward; area times unit normal for flat faces).
template <mesh::FaceType F>
std::array<double, FaceTraits<F>::dim> faceAreaVector(const std::array<double, FaceTraits<F>::dofs>& X);

}  // namespace coulomb::fem
