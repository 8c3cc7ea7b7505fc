/// @file DualBasis.cpp
/// @brief Element mass matrices and dual-basis coefficients of slave faces.
#include "coulomb/contact/mortar/DualBasis.hpp"

#include "coulomb/contact/mortar/MortarScalarTypes.hpp"

#include <algorithm>
#include <cmath>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/Quadrature.hpp"

namespace coulomb::contact {
namespace {

template <typename T>
double valueOf(const T& x) {
  return Sacado::ScalarValue<T>::eval(x);
}

/// Tangent vectors t_i = sum_a g[a][i] x_a of a face at one point.
template <mesh::FaceType F, typename T, typename G>
std::array<std::array<T, FaceTraits<F>::spaceDim>, FaceTraits<F>::paramDim> tangents(const FaceNodes<F, T>& x,
                                                                                     const G& g) {
  std::array<std::array<T, FaceTraits<F>::spaceDim>, FaceTraits<F>::paramDim> t{};
  for (int i = 0; i < FaceTraits<F>::paramDim; ++i)
    for (int d = 0; d < FaceTraits<F>::spaceDim; ++d) {
      t[i][d] = 0.0;
      for (int a = 0; a < FaceTraits<F>::nodes; ++a) t[i][d] += g[a][i] * x[a][d];
    }
  return t;
}

/// |x_xi| (Line2) or |x_xi × x_eta| (Tri3, Quad4) from the tangents.
template <mesh::FaceType F, typename T>
T measureFromTangents(const std::array<std::array<T, FaceTraits<F>::spaceDim>, FaceTraits<F>::paramDim>& t) {
  using std::sqrt;
  if constexpr (FaceTraits<F>::paramDim == 1) {
    return sqrt(t[0][0] * t[0][0] + t[0][1] * t[0][1]);
  } else {
    const T c0 = t[0][1] * t[1][2] - t[0][2] * t[1][1];
    const T c1 = t[0][2] * t[1][0] - t[0][0] * t[1][2];
    const T c2 = t[0][0] * t[1][1] - t[0][1] * t[1][0];
    return sqrt(c0 * c0 + c1 * c1 + c2 * c2);
  }
}

/// Quadrature of the face mass matrices: points, weights, the slave basis N~
/// (faceTrialValues) and dN/dxi (all coordinate independent). Line2/Tri3 reuse
/// fem's rules (exact for the constant measure), Tri6 fem's 6-point degree-4
/// rule and Quad8 its 3x3 Gauss (exact for plane faces); Quad4 uses 3x3
/// Gauss (exact for plane quadrilaterals).
template <mesh::FaceType F>
struct MassRule {
  static constexpr int n = FaceTraits<F>::nodes;
  static constexpr int pd = FaceTraits<F>::paramDim;
  static constexpr int points = F == mesh::FaceType::Line2 ? 2 : F == mesh::FaceType::Line3 ? 5
                                 : F == mesh::FaceType::Tri3  ? 3 : F == mesh::FaceType::Quad9 ? 16
                                 : F == mesh::FaceType::Tri6  ? 6 : 9;
  std::array<double, points> weight{};
  std::array<NodalValues<F, double>, points> N{};
  std::array<std::array<std::array<double, pd>, n>, points> dN{};
};

template <mesh::FaceType F>
MassRule<F> makeMassRule() {
  MassRule<F> rule;
  if constexpr (F == mesh::FaceType::Line3) {
    const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    const double gx[5] = {-b, -a, 0.0, a, b};
    const double gw[5] = {wb, wa, 128.0 / 225.0, wa, wb};
    for (int q = 0; q < 5; ++q) {
      const FacePoint<F, double> xi{gx[q]};
      rule.weight[q] = gw[q];
      rule.N[q] = faceTrialValues<F, double>(xi);
      rule.dN[q] = faceShapeGradients<F, double>(xi);
    }
  } else if constexpr (F == mesh::FaceType::Quad9) {
    // 4 x 4 Gauss: exact for a parallelogram (N_j N_k of degree 4 per variable).
    const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
    const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
    const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
    const double gx[4] = {-b, -a, a, b};
    const double gw[4] = {wb, wa, wa, wb};
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const int q = 4 * j + i;
        const FacePoint<F, double> xi{gx[i], gx[j]};
        rule.weight[q] = gw[i] * gw[j];
        rule.N[q] = faceTrialValues<F, double>(xi);
        rule.dN[q] = faceShapeGradients<F, double>(xi);
      }
  } else if constexpr (F == mesh::FaceType::Quad4) {
    const double g = std::sqrt(0.6);
    const double gx[3] = {-g, 0.0, g};
    const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const int q = 3 * j + i;
        const FacePoint<F, double> xi{gx[i], gx[j]};
        rule.weight[q] = gw[i] * gw[j];
        rule.N[q] = faceTrialValues<F, double>(xi);
        rule.dN[q] = faceShapeGradients<F, double>(xi);
      }
  } else {
    constexpr fem::ReferenceShape S = fem::referenceShape(F);
    const fem::QuadratureRule<S>& quad = fem::quadratureRule<S>();
    static_assert(fem::QuadratureRule<S>::points == MassRule<F>::points);
    for (int q = 0; q < MassRule<F>::points; ++q) {
      FacePoint<F, double> xi{};
      for (int i = 0; i < FaceTraits<F>::paramDim; ++i) xi[i] = quad.xi[q][i];
      rule.weight[q] = quad.weight[q];
      rule.N[q] = faceTrialValues<F, double>(xi);
      rule.dN[q] = faceShapeGradients<F, double>(xi);
    }
  }
  return rule;
}

template <mesh::FaceType F>
const MassRule<F>& massRule() {
  static const MassRule<F> rule = makeMassRule<F>();
  return rule;
}

}  // namespace

template <mesh::FaceType F, typename T>
T surfaceJacobian(const FaceNodes<F, T>& x, const FacePoint<F, T>& xi) {
  return measureFromTangents<F, T>(tangents<F, T>(x, faceShapeGradients<F, T>(xi)));
}

template <mesh::FaceType F, typename T>
FaceMass<F, T> faceMass(const FaceNodes<F, T>& x) {
  constexpr int n = FaceTraits<F>::nodes;
  const MassRule<F>& rule = massRule<F>();
  FaceMass<F, T> mass;
  for (int j = 0; j < n; ++j) {
    mass.De[j] = 0.0;
    for (int k = 0; k < n; ++k) mass.Me[j][k] = 0.0;
  }
  for (int q = 0; q < MassRule<F>::points; ++q) {
    const T dA = rule.weight[q] * measureFromTangents<F, T>(tangents<F, T>(x, rule.dN[q]));
    for (int j = 0; j < n; ++j) {
      mass.De[j] += rule.N[q][j] * dA;
      for (int k = 0; k < n; ++k) mass.Me[j][k] += rule.N[q][j] * rule.N[q][k] * dA;
    }
  }
  return mass;
}

template <mesh::FaceType F, typename T>
NodalMatrix<F, T> dualCoefficients(const FaceNodes<F, T>& x) {
  constexpr int n = FaceTraits<F>::nodes;
  const FaceMass<F, T> mass = faceMass<F, T>(x);
  // Cholesky M_e = L L^T (M_e is symmetric positive definite for a non-degenerate face).
  NodalMatrix<F, T> L{};
  double scale = 0.0;
  for (int j = 0; j < n; ++j) scale = std::max(scale, std::abs(valueOf(mass.Me[j][j])));
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k <= j; ++k) {
      T s = mass.Me[j][k];
      for (int m = 0; m < k; ++m) s -= L[j][m] * L[k][m];
      if (k == j) {
        COULOMB_REQUIRE(valueOf(s) > 1e-14 * scale && std::isfinite(valueOf(s)),
                        "dual basis: degenerate slave face (element mass matrix not positive definite)");
        using std::sqrt;
        L[j][j] = sqrt(s);
      } else {
        L[j][k] = s / L[k][k];
      }
    }
  }
  // Row j of A solves M_e a_j = De_j e_j (M_e symmetric): A M_e = D_e.
  NodalMatrix<F, T> A{};
  for (int j = 0; j < n; ++j) {
    std::array<T, n> y{};
    for (int r = 0; r < n; ++r) {
      T s = (r == j) ? mass.De[j] : T(0.0);
      for (int m = 0; m < r; ++m) s -= L[r][m] * y[m];
      y[r] = s / L[r][r];
    }
    for (int r = n - 1; r >= 0; --r) {
      T s = y[r];
      for (int m = r + 1; m < n; ++m) s -= L[m][r] * A[j][m];
      A[j][r] = s / L[r][r];
    }
  }
  return A;
}

#define COULOMB_CONTACT_DUAL_INSTANTIATE(F, T)                                              \
  template T surfaceJacobian<F, T>(const FaceNodes<F, T>&, const FacePoint<F, T>&);         \
  template FaceMass<F, T> faceMass<F, T>(const FaceNodes<F, T>&);                           \
  template NodalMatrix<F, T> dualCoefficients<F, T>(const FaceNodes<F, T>&);
#define COULOMB_CONTACT_DUAL_ALL_FACES(T)                  \
  COULOMB_CONTACT_DUAL_INSTANTIATE(mesh::FaceType::Line2, T) \
  COULOMB_CONTACT_DUAL_INSTANTIATE(mesh::FaceType::Tri3, T)  \
  COULOMB_CONTACT_DUAL_INSTANTIATE(mesh::FaceType::Quad4, T)

// The scalar types of the mortar kernels (MortarScalarTypes.hpp).
using mesh::FaceType;
using Fad3DTriTri = SegmentFad3D<FaceType::Tri3, FaceType::Tri3>;
using Fad3DTriQuad = SegmentFad3D<FaceType::Tri3, FaceType::Quad4>;
using Fad3DQuadTri = SegmentFad3D<FaceType::Quad4, FaceType::Tri3>;
using Fad3DQuadQuad = SegmentFad3D<FaceType::Quad4, FaceType::Quad4>;
COULOMB_CONTACT_DUAL_ALL_FACES(double)
COULOMB_CONTACT_DUAL_ALL_FACES(SegmentFad2D)
COULOMB_CONTACT_DUAL_ALL_FACES(Fad3DTriTri)
COULOMB_CONTACT_DUAL_ALL_FACES(Fad3DTriQuad)
COULOMB_CONTACT_DUAL_ALL_FACES(Fad3DQuadTri)
COULOMB_CONTACT_DUAL_ALL_FACES(Fad3DQuadQuad)
// Quadratic faces: Line3 and Quad9 (2D: MortarSegmentCurved2D has its own
// ring-weighted mass), Quad8 and Tri6.
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Line3, double)
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad9, double)
// The sub-facet kernel's Sacado types (SubFacetFad3D: 3 x the nodes of
// both faces) with the slave types they are used with; Tri3 and Quad4 with
// 27 to 36 inputs are above.
using FadInputs27 = Sacado::Fad::SFad<double, 27>;
using FadInputs30 = Sacado::Fad::SFad<double, 30>;
using FadInputs33 = Sacado::Fad::SFad<double, 33>;
using FadInputs36 = Sacado::Fad::SFad<double, 36>;
using FadInputs39 = Sacado::Fad::SFad<double, 39>;
using FadInputs42 = Sacado::Fad::SFad<double, 42>;
using FadInputs45 = Sacado::Fad::SFad<double, 45>;
using FadInputs48 = Sacado::Fad::SFad<double, 48>;
using FadInputs51 = Sacado::Fad::SFad<double, 51>;
using FadInputs54 = Sacado::Fad::SFad<double, 54>;
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad9, FadInputs54)  // Quad9 / Quad9
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad9, FadInputs39)  // Quad9 / Quad4
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad9, FadInputs36)  // Quad9 / Tri3
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad4, FadInputs39)  // Quad4 / Quad9
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad8, double)
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Tri6, double)
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad8, FadInputs48)  // Quad8 / Quad8
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad8, FadInputs42)  // Quad8 / Tri6
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad8, FadInputs36)  // Quad8 / Quad4
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad8, FadInputs33)  // Quad8 / Tri3
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Tri6, FadInputs36)   // Tri6 / Tri6
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Tri6, FadInputs42)   // Tri6 / Quad8
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Tri6, FadInputs30)   // Tri6 / Quad4
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Tri6, FadInputs27)   // Tri6 / Tri3
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad9, FadInputs51)  // Quad9 / Quad8
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad9, FadInputs45)  // Quad9 / Tri6
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Quad8, FadInputs51)  // Quad8 / Quad9
COULOMB_CONTACT_DUAL_INSTANTIATE(FaceType::Tri6, FadInputs45)   // Tri6 / Quad9
#undef COULOMB_CONTACT_DUAL_ALL_FACES
#undef COULOMB_CONTACT_DUAL_INSTANTIATE

}  // namespace coulomb::contact
