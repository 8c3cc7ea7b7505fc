/// @file Quadrature.cpp
/// @brief Gauss and simplex quadrature tables.
#include "coulomb/fem/Quadrature.hpp"

#include <cmath>

namespace coulomb::fem {
namespace {

template <ReferenceShape S>
QuadratureRule<S> makeRule() {
  QuadratureRule<S> rule{};
  const double g = 1.0 / std::sqrt(3.0);  // 2-point Gauss abscissa, weight 1
  const double gauss[2] = {-g, g};
  if constexpr (S == ReferenceShape::Line2) {
    for (int i = 0; i < 2; ++i) {
      rule.xi[i] = {gauss[i]};
      rule.weight[i] = 1.0;
    }
  } else if constexpr (S == ReferenceShape::Quad4) {
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        rule.xi[j * 2 + i] = {gauss[i], gauss[j]};
        rule.weight[j * 2 + i] = 1.0;
      }
  } else if constexpr (S == ReferenceShape::Hex8) {
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          rule.xi[(k * 2 + j) * 2 + i] = {gauss[i], gauss[j], gauss[k]};
          rule.weight[(k * 2 + j) * 2 + i] = 1.0;
        }
  } else if constexpr (S == ReferenceShape::Tri3) {
    // Interior 3-point rule: barycentric (2/3, 1/6, 1/6) and permutations, weight 1/6 each.
    rule.xi = {{{1.0 / 6.0, 1.0 / 6.0}, {2.0 / 3.0, 1.0 / 6.0}, {1.0 / 6.0, 2.0 / 3.0}}};
    rule.weight = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
  } else {
    // 4-point rule: barycentric (a, b, b, b) and permutations, a = (5+3 sqrt5)/20,
    // b = (5 - sqrt5)/20, weight 1/24 each.
    const double a = (5.0 + 3.0 * std::sqrt(5.0)) / 20.0;
    const double b = (5.0 - std::sqrt(5.0)) / 20.0;
    rule.xi = {{{b, b, b}, {a, b, b}, {b, a, b}, {b, b, a}}};
    rule.weight = {1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0};
  }
  return rule;
}

template <ReferenceShape S>
TabulatedShape<S> makeTable() {
  const QuadratureRule<S>& rule = quadratureRule<S>();
  TabulatedShape<S> table{};
  for (int q = 0; q < rule.points; ++q) {
    table.weight[q] = rule.weight[q];
    shapeValues<S>(rule.xi[q], table.N[q]);
    shapeGradients<S>(rule.xi[q], table.dNdxi[q]);
  }
  return table;
}

}  // namespace

template <ReferenceShape S>
const TabulatedShape<S>& tabulatedShape() {
  static const TabulatedShape<S> table = makeTable<S>();
  return table;
}

template <ReferenceShape S>
const QuadratureRule<S>& quadratureRule() {
  static const QuadratureRule<S> rule = makeRule<S>();
  return rule;
}

#define COULOMB_INSTANTIATE_RULE(S)                          \
  template const QuadratureRule<S>& quadratureRule<S>(); \
  template const TabulatedShape<S>& tabulatedShape<S>();
COULOMB_INSTANTIATE_RULE(ReferenceShape::Line2)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Tri3)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Quad4)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Tet4)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Hex8)
#undef COULOMB_INSTANTIATE_RULE

}  // namespace coulomb::fem
