#pragma once
/// @file ShapeFunctions.hpp
/// @brief Lagrange shape functions of the linear reference elements and their
/// isoparametric mapping to physical gradients.
///
/// Reference elements (Exodus node order):
///   Line2 on [-1,1]:          nodes -1, +1
///   Tri3  on the unit simplex: (0,0) (1,0) (0,1)
///   Quad4 on [-1,1]^2:         (-1,-1) (1,-1) (1,1) (-1,1)
///   Tet4  on the unit simplex: (0,0,0) (1,0,0) (0,1,0) (0,0,1)
///   Hex8  on [-1,1]^3:         bottom face (z=-1) counter-clockwise, then top face.
#include <array>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::fem {

/// @brief Reference element shapes shared by cells and faces.
enum class ReferenceShape { Line2, Tri3, Quad4, Tet4, Hex8 };

/// @brief Reference shape of a bulk cell type.
constexpr ReferenceShape referenceShape(mesh::CellType t) {
  return t == mesh::CellType::Quad4  ? ReferenceShape::Quad4
         : t == mesh::CellType::Tri3 ? ReferenceShape::Tri3
         : t == mesh::CellType::Hex8 ? ReferenceShape::Hex8
                                     : ReferenceShape::Tet4;
}

/// @brief Reference shape of a face type (a face is parametrised by its own shape).
constexpr ReferenceShape referenceShape(mesh::FaceType t) {
  return t == mesh::FaceType::Line2  ? ReferenceShape::Line2
         : t == mesh::FaceType::Tri3 ? ReferenceShape::Tri3
                                     : ReferenceShape::Quad4;
}

/// @brief Number of nodes of a reference shape.
constexpr int numNodes(ReferenceShape s) {
  return s == ReferenceShape::Line2 ? 2
         : s == ReferenceShape::Tri3 ? 3
         : s == ReferenceShape::Hex8 ? 8
                                     : 4;
}

/// @brief Parametric dimension of a reference shape.
constexpr int parametricDimension(ReferenceShape s) {
  return s == ReferenceShape::Line2 ? 1 : (s == ReferenceShape::Tri3 || s == ReferenceShape::Quad4) ? 2 : 3;
}

/// @brief Compile-time sizes of a reference shape.
template <ReferenceShape S>
struct ShapeTraits {
  static constexpr int nodes = numNodes(S);
  static constexpr int dim = parametricDimension(S);
};

/// @brief Parametric coordinates of local node a (0-based) of the reference element.
template <ReferenceShape S>
std::array<double, ShapeTraits<S>::dim> referenceNode(int a);

/// @brief Shape function values N_a(xi) for all nodes a.
template <ReferenceShape S>
void shapeValues(const std::array<double, ShapeTraits<S>::dim>& xi,
                 std::array<double, ShapeTraits<S>::nodes>& N);

/// @brief Parametric gradients dNdxi[a*dim+i] = dN_a/dxi_i at xi.
template <ReferenceShape S>
void shapeGradients(const std::array<double, ShapeTraits<S>::dim>& xi,
                    std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& dNdxi);

/// @brief Physical gradients of a cell's shape functions at one point.
///
/// With the reference map x(xi) = sum_a X_a N_a(xi), J_ij = dx_i/dxi_j =
/// sum_a X_{a,i} dN_a/dxi_j, the physical gradients are
/// dN_a/dX_i = sum_j dN_a/dxi_j (J^{-1})_{ji}. X is node-major (x0 y0 [z0] x1 ...).
/// Returns det J; dNdX is left unchanged when det J <= 0 (inverted or degenerate map).
template <ReferenceShape S>
double physicalGradients(const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& X,
                         const std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& dNdxi,
                         std::array<double, ShapeTraits<S>::nodes * ShapeTraits<S>::dim>& dNdX);

}  // namespace coulomb::fem
