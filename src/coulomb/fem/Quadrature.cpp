/// @file Quadrature.cpp
/// @brief Gauss and simplex quadrature tables.
#include "coulomb/fem/Quadrature.hpp"

#include <cmath>

namespace coulomb::fem {
namespace {

/// Tensor product of the 1D Gauss rule with P points over D variables (first variable fastest).
template <ReferenceShape S, int P>
void gaussProduct(const double (&x)[P], const double (&w)[P], QuadratureRule<S>& rule) {
  constexpr int D = ShapeTraits<S>::dim;
  static_assert(QuadratureRule<S>::points == (D == 1 ? P : D == 2 ? P * P : P * P * P), "Gauss product size");
  for (int q = 0; q < rule.points; ++q) {
    int rest = q;
    rule.weight[q] = 1.0;
    for (int i = 0; i < D; ++i) {
      rule.xi[q][i] = x[rest % P];
      rule.weight[q] *= w[rest % P];
      rest /= P;
    }
  }
}

template <ReferenceShape S>
QuadratureRule<S> makeRule() {
  QuadratureRule<S> rule{};
  const double g = 1.0 / std::sqrt(3.0);  // 2-point Gauss abscissa, weight 1
  const double gauss[2] = {-g, g};
  const double g3 = std::sqrt(0.6);  // 3-point Gauss: -g3, 0, g3 with weights 5/9, 8/9, 5/9
  const double gauss3[3] = {-g3, 0.0, g3};
  const double weight3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  if constexpr (S == ReferenceShape::Line3 || S == ReferenceShape::Quad8 || S == ReferenceShape::Quad9 ||
                S == ReferenceShape::Hex20 || S == ReferenceShape::Hex27) {
    gaussProduct<S, 3>(gauss3, weight3, rule);
  } else if constexpr (S == ReferenceShape::Tri6) {
    // Strang-Fix / Dunavant degree-4 rule: barycentric (1 - 2a, a, a) and permutations,
    // two orbits; the weights are fractions of the triangle's area 1/2.
    const double a[2] = {0.445948490915965, 0.091576213509771};
    const double w[2] = {0.223381589678011, 0.109951743655322};
    for (int k = 0; k < 2; ++k) {
      const double b = 1.0 - 2.0 * a[k];
      rule.xi[3 * k + 0] = {a[k], a[k]};
      rule.xi[3 * k + 1] = {b, a[k]};
      rule.xi[3 * k + 2] = {a[k], b};
      for (int j = 0; j < 3; ++j) rule.weight[3 * k + j] = 0.5 * w[k];
    }
  } else if constexpr (S == ReferenceShape::Tet10) {
    // Collapsed (Duffy) product rule: x = u, y = (1-u) v, z = (1-u)(1-v) w on the unit
    // cube, dV = (1-u)^2 (1-v) du dv dw. A monomial of total degree k <= 3 becomes a
    // polynomial of degree k+2 in u, k+1 in v, k in w: 3-point Gauss in u and v, 2-point
    // in w integrate it exactly. Degree 3 makes the constant-stress residual of a curved
    // TET10 (adj J, degree 2, times grad N, degree 1) exact: the patch test holds on
    // meshes with moved mid-side nodes. All 18 weights are positive.
    const double u3[3] = {0.5 * (1.0 - g3), 0.5, 0.5 * (1.0 + g3)};
    const double w3[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    const double u2[2] = {0.5 * (1.0 - g), 0.5 * (1.0 + g)};
    int q = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 2; ++k, ++q) {
          const double u = u3[i], v = u3[j], w = u2[k];
          rule.xi[q] = {u, (1.0 - u) * v, (1.0 - u) * (1.0 - v) * w};
          rule.weight[q] = w3[i] * w3[j] * 0.5 * (1.0 - u) * (1.0 - u) * (1.0 - v);
        }
  } else if constexpr (S == ReferenceShape::Line2) {
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
    static_assert(S == ReferenceShape::Tet4, "makeRule: unknown shape");
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
COULOMB_INSTANTIATE_RULE(ReferenceShape::Line3)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Tri6)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Quad8)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Quad9)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Tet10)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Hex20)
COULOMB_INSTANTIATE_RULE(ReferenceShape::Hex27)
#undef COULOMB_INSTANTIATE_RULE

}  // namespace coulomb::fem
