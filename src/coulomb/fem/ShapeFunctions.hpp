#pragma once
/// @file ShapeFunctions.hpp
/// @brief Lagrange shape functions of the linear and quadratic reference
/// elements and their isoparametric mapping to physical gradients.
///
/// Reference elements (Exodus node order):
///   Line2 on [-1,1]:          nodes -1, +1; Line3 adds the midpoint 0
///   Tri3  on the unit simplex: (0,0) (1,0) (0,1); Tri6 adds the edge midpoints
///                              of (0,1) (1,2) (2,0)
///   Quad4 on [-1,1]^2:         (-1,-1) (1,-1) (1,1) (-1,1); Quad8 adds the
///                              midpoints of edges (0,1) (1,2) (2,3) (3,0),
///                              Quad9 also the centre (biquadratic Lagrange;
///                              Quad8 is the serendipity element)
///   Tet4  on the unit simplex: (0,0,0) (1,0,0) (0,1,0) (0,0,1); Tet10 adds the
///                              midpoints of (0,1) (1,2) (2,0) (0,3) (1,3) (2,3)
///   Hex8  on [-1,1]^3:         bottom face (z=-1) counter-clockwise, then top face;
///                              Hex20 adds the midpoints of the bottom edges,
///                              the vertical edges, the top edges (serendipity);
///                              Hex27 also the centre, then the centres of the
///                              faces z=-1, z=+1, x=-1, x=+1, y=-1, y=+1
///                              (triquadratic Lagrange). See mesh::nodeCorners.
#include <array>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::fem {

/// @brief Reference element shapes shared by cells and faces.
enum class ReferenceShape { Line2, Tri3, Quad4, Tet4, Hex8, Line3, Tri6, Quad8, Quad9, Tet10, Hex20, Hex27 };

/// @brief Reference shape of a bulk cell type.
constexpr ReferenceShape referenceShape(mesh::CellType t) {
  switch (t) {
    case mesh::CellType::Quad4: return ReferenceShape::Quad4;
    case mesh::CellType::Tri3: return ReferenceShape::Tri3;
    case mesh::CellType::Hex8: return ReferenceShape::Hex8;
    case mesh::CellType::Tet4: return ReferenceShape::Tet4;
    case mesh::CellType::Quad8: return ReferenceShape::Quad8;
    case mesh::CellType::Quad9: return ReferenceShape::Quad9;
    case mesh::CellType::Tri6: return ReferenceShape::Tri6;
    case mesh::CellType::Hex20: return ReferenceShape::Hex20;
    case mesh::CellType::Hex27: return ReferenceShape::Hex27;
    case mesh::CellType::Tet10: return ReferenceShape::Tet10;
  }
  return ReferenceShape::Hex8;
}

/// @brief Reference shape of a face type (a face is parametrised by its own shape).
constexpr ReferenceShape referenceShape(mesh::FaceType t) {
  switch (t) {
    case mesh::FaceType::Line2: return ReferenceShape::Line2;
    case mesh::FaceType::Tri3: return ReferenceShape::Tri3;
    case mesh::FaceType::Quad4: return ReferenceShape::Quad4;
    case mesh::FaceType::Line3: return ReferenceShape::Line3;
    case mesh::FaceType::Tri6: return ReferenceShape::Tri6;
    case mesh::FaceType::Quad8: return ReferenceShape::Quad8;
    case mesh::FaceType::Quad9: return ReferenceShape::Quad9;
  }
  return ReferenceShape::Quad4;
}

/// @brief Number of nodes of a reference shape.
constexpr int numNodes(ReferenceShape s) {
  switch (s) {
    case ReferenceShape::Line2: return 2;
    case ReferenceShape::Tri3: return 3;
    case ReferenceShape::Quad4: return 4;
    case ReferenceShape::Tet4: return 4;
    case ReferenceShape::Hex8: return 8;
    case ReferenceShape::Line3: return 3;
    case ReferenceShape::Tri6: return 6;
    case ReferenceShape::Quad8: return 8;
    case ReferenceShape::Quad9: return 9;
    case ReferenceShape::Tet10: return 10;
    case ReferenceShape::Hex20: return 20;
    case ReferenceShape::Hex27: return 27;
  }
  return 0;
}

/// @brief Simplex reference shapes (unit simplex, not a cube).
constexpr bool isSimplex(ReferenceShape s) {
  return s == ReferenceShape::Tri3 || s == ReferenceShape::Tet4 || s == ReferenceShape::Tri6 ||
         s == ReferenceShape::Tet10;
}

/// @brief Parametric dimension of a reference shape.
constexpr int parametricDimension(ReferenceShape s) {
  switch (s) {
    case ReferenceShape::Line2:
    case ReferenceShape::Line3: return 1;
    case ReferenceShape::Tri3:
    case ReferenceShape::Quad4:
    case ReferenceShape::Tri6:
    case ReferenceShape::Quad8:
    case ReferenceShape::Quad9: return 2;
    default: return 3;
  }
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
