#pragma once
/// @file Quadrature.hpp
/// @brief Fixed quadrature rules on the reference elements (full integration).
///
/// Line2: 2-point Gauss (exact for degree 3). Quad4: 2x2 Gauss, Hex8: 2x2x2 Gauss
/// (exact for degree 3 in each variable). Tri3: 3-point interior rule, Tet4:
/// 4-point rule (both exact for total degree 2). Weights sum to the reference
/// measure: 2, 4, 8 for Line2/Quad4/Hex8; 1/2, 1/6 for Tri3/Tet4.
/// Quadratic shapes: Line3 3-point Gauss, Quad8/Quad9 3x3, Hex20/Hex27 3x3x3
/// Gauss (exact for degree 5 in each variable: the stiffness of an affine
/// cell has degree 4 per variable); Tri6 the 6-point Strang-Fix/Dunavant rule
/// (total degree 4, so also the degree-4 pressure and stress-projection
/// integrands of a straight TRI6); Tet10 an 18-point collapsed Gauss product
/// rule of total degree 3 (the constant-stress residual of a TET10 with curved
/// edges has degree 3: the patch test needs it; Tet4's degree-2 rule fails it).
#include <array>

#include "coulomb/fem/ShapeFunctions.hpp"

namespace coulomb::fem {

/// @brief Number of quadrature points of the rule used for a reference shape.
constexpr int numQuadraturePoints(ReferenceShape s) {
  switch (s) {
    case ReferenceShape::Line2: return 2;
    case ReferenceShape::Tri3: return 3;
    case ReferenceShape::Quad4: return 4;
    case ReferenceShape::Tet4: return 4;
    case ReferenceShape::Hex8: return 8;
    case ReferenceShape::Line3: return 3;
    case ReferenceShape::Tri6: return 6;
    case ReferenceShape::Quad8:
    case ReferenceShape::Quad9: return 9;
    case ReferenceShape::Tet10: return 18;
    case ReferenceShape::Hex20:
    case ReferenceShape::Hex27: return 27;
  }
  return 0;
}

/// @brief Quadrature points (parametric coordinates) and weights of one reference shape.
template <ReferenceShape S>
struct QuadratureRule {
  static constexpr int dim = ShapeTraits<S>::dim;
  static constexpr int points = numQuadraturePoints(S);
  std::array<std::array<double, dim>, points> xi;
  std::array<double, points> weight;
};

/// @brief The (static, immutable) quadrature rule of a reference shape.
template <ReferenceShape S>
const QuadratureRule<S>& quadratureRule();

/// @brief Shape function values and parametric gradients tabulated at the quadrature points.
template <ReferenceShape S>
struct TabulatedShape {
  static constexpr int points = numQuadraturePoints(S);
  static constexpr int nodes = ShapeTraits<S>::nodes;
  static constexpr int dim = ShapeTraits<S>::dim;
  std::array<double, points> weight;                              ///< quadrature weights
  std::array<std::array<double, nodes>, points> N;                ///< N[q][a]
  std::array<std::array<double, nodes * dim>, points> dNdxi;      ///< dNdxi[q][a*dim+i]
};

/// @brief The (static, immutable) tabulation of a reference shape on its quadrature rule.
template <ReferenceShape S>
const TabulatedShape<S>& tabulatedShape();

}  // namespace coulomb::fem
