#pragma once
/// @file Quadrature.hpp
/// @brief Fixed quadrature rules on the reference elements (full integration).
///
/// Line2: 2-point Gauss (exact for degree 3). Quad4: 2x2 Gauss, Hex8: 2x2x2 Gauss
/// (exact for degree 3 in each variable). Tri3: 3-point interior rule, Tet4:
/// 4-point rule (both exact for total degree 2). Weights sum to the reference
/// measure: 2, 4, 8 for Line2/Quad4/Hex8; 1/2, 1/6 for Tri3/Tet4.
#include <array>

#include "coulomb/fem/ShapeFunctions.hpp"

namespace coulomb::fem {

/// @brief Number of quadrature points of the rule used for a reference shape.
constexpr int numQuadraturePoints(ReferenceShape s) {
  return s == ReferenceShape::Line2   ? 2
         : s == ReferenceShape::Tri3  ? 3
         : s == ReferenceShape::Quad4 ? 4
         : s == ReferenceShape::Tet4  ? 4
                                      : 8;
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
