#pragma once
/// @file DualBasis.hpp
/// @brief Standard and dual (biorthogonal) shape functions of a slave face
/// (Line2 in 2D, Tri3 / Quad4 in 3D), templated on the scalar type.
///
/// Reference faces (same node order as fem/ShapeFunctions.hpp, Exodus):
///   Line2 on [-1,1]            nodes -1, +1
///   Line3 on [-1,1]            nodes -1, +1, 0 (quadratic Lagrange; its dual
///                              basis keeps D_j = int N_j > 0: h/6, h/6, 2h/3
///                              on a straight face)
///   Tri3  on the unit simplex   (0,0) (1,0) (0,1)
///   Quad4 on [-1,1]^2           (-1,-1) (1,-1) (1,1) (-1,1)
///   Quad9 on [-1,1]^2           the Quad4 corners, mid-sides (0,-1) (1,0)
///                              (0,1) (-1,0), centre (0,0): biquadratic; its
///                              dual basis keeps D_j = int N_j > 0 (A/36,
///                              A/9, 4A/9 on a parallelogram of area A), which
///                              Quad8 and Tri6 do not (negative / zero at
///                              corners): theirs is dual to a transformed
///                              basis N~ (faceTrialValues)
///   Quad8 on [-1,1]^2           the Quad9 nodes but the centre (serendipity)
///   Tri6  on the unit simplex   corners, mid-sides of (0,1) (1,2) (2,0)
///
/// Dual basis (thesis §4.3.3, "dual Lagrange multipliers"; Wohlmuth's
/// biorthogonality): on a slave face gamma_e with standard shape functions N_k,
///   Phi_j(xi) = sum_k A_jk N_k(xi),   A = D_e M_e^{-1},
///   D_e = diag( int_{gamma_e} N_j dA ),  M_e = [ int_{gamma_e} N_j N_k dA ],
/// so that  int_{gamma_e} Phi_j N_k dA = delta_jk int_{gamma_e} N_k dA  and
/// sum_j Phi_j = 1 (because the rows of M_e sum to D_e).
/// dA is the current-configuration surface measure |dx/dxi| dxi (Line2: |x1-x0|/2,
/// Tri3/Quad4: |x_xi × x_eta|). For Line2 and Tri3 the measure is constant on the
/// face and A is the fixed matrix [[2,-1],[-1,2]] resp. 4 I - 1 1^T (i.e. 3 on the
/// diagonal, -1 off it); for a Quad4 it depends on the coordinates unless the face
/// is a parallelogram.
///
/// Integration: Line2 2-point Gauss, Line3 5-point Gauss (exact on a straight
/// face, an approximation on a curved one, whose measure is not polynomial), Tri3 the 3-point degree-2 rule (both from
/// fem/Quadrature, exact); Quad4 3x3 Gauss: exact for plane quadrilaterals
/// (integrand N_j N_k det J of degree <= 3 per variable), an approximation for
/// warped ones (|x_xi × x_eta| is then not polynomial; biorthogonality then holds
/// for that rule only).
///
/// Scalar types: the functions declared here are explicitly instantiated in
/// DualBasis.cpp for double and for Sacado::Fad::SFad<double, N> with
/// N = 12, 27, 30, 33, 36 (the input counts of the mortar segment kernels); only
/// the double instantiations are declared `extern` below so that this header
/// does not need Sacado. The inline helpers work for any scalar with + - *.
#include <array>

#include "coulomb/mesh/CellType.hpp"

namespace coulomb::contact {

/// @brief Compile-time sizes of a face: nodes, parametric and spatial dimension.
template <mesh::FaceType F>
struct FaceTraits {
  static constexpr bool line = F == mesh::FaceType::Line2 || F == mesh::FaceType::Line3;
  static constexpr int nodes = mesh::numNodes(F);
  static constexpr int paramDim = line ? 1 : 2;
  static constexpr int spaceDim = line ? 2 : 3;
};

/// Nodal coordinates (or nodal vectors such as normals): x[a][i].
template <mesh::FaceType F, typename T>
using FaceNodes = std::array<std::array<T, FaceTraits<F>::spaceDim>, FaceTraits<F>::nodes>;
/// A point of the reference face.
template <mesh::FaceType F, typename T>
using FacePoint = std::array<T, FaceTraits<F>::paramDim>;
/// One value per face node.
template <mesh::FaceType F, typename T>
using NodalValues = std::array<T, FaceTraits<F>::nodes>;
/// A nodes x nodes matrix, m[j][k].
template <mesh::FaceType F, typename T>
using NodalMatrix = std::array<std::array<T, FaceTraits<F>::nodes>, FaceTraits<F>::nodes>;

/// Reference coordinates of the Quad9 nodes (Exodus: corners, mid-sides from
/// the edge 0-1 on, centre).
inline constexpr int kQuad9Node[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
/// Reference coordinates of the Tri6 nodes (corners, mid-sides of 0-1, 1-2, 2-0).
inline constexpr double kTri6Node[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
/// Reference coordinates of node a of a quadratic face (Tri6, Quad8 or Quad9;
/// Quad8 has the first eight Quad9 nodes).
template <mesh::FaceType F>
constexpr std::array<double, 2> quadraticFaceNode(int a) {
  if constexpr (F == mesh::FaceType::Tri6) return {kTri6Node[a][0], kTri6Node[a][1]};
  else return {double(kQuad9Node[a][0]), double(kQuad9Node[a][1])};
}
/// The 1D quadratic Lagrange function of the node at c in {-1, 0, 1}, and its derivative.
template <typename X>
inline X lagrange3(int c, const X& s) {
  return c == 0 ? X(1.0 - s * s) : X(0.5 * s * (s + double(c)));
}
template <typename X>
inline X lagrange3Derivative(int c, const X& s) {
  return c == 0 ? X(-2.0 * s) : X(s + 0.5 * double(c));
}

/// Quad8 and Tri6: the edge nodes with the two corners of their edge
/// (Exodus order: Quad8 4 (0,1), 5 (1,2), 6 (2,3), 7 (3,0); Tri6 3 (0,1),
/// 4 (1,2), 5 (2,0)).
inline constexpr int kQuad8Edge[4][3] = {{4, 0, 1}, {5, 1, 2}, {6, 2, 3}, {7, 3, 0}};
inline constexpr int kTri6Edge[3][3] = {{3, 0, 1}, {4, 1, 2}, {5, 2, 0}};
/// The weight alpha of the transformed slave basis of Quad8 and Tri6 faces
/// (faceTrialValues): 1/5, within (1/8, 1/2) where every int N~_j > 0 on a
/// Quad8 (corners -1/12 + 2 alpha / 3, edges (1 - 2 alpha) / 3 of the area)
/// and within (0, 1/2) on a Tri6 (corners 2 alpha / 3, edges (1 - 2 alpha) / 3).
inline constexpr double kTransformedBasisAlpha = 0.2;
/// Whether the slave displacements of a face type are transformed (Quad8, Tri6).
constexpr bool transformedSlaveBasis(mesh::FaceType f) {
  return f == mesh::FaceType::Quad8 || f == mesh::FaceType::Tri6;
}
/// The edges of a transformed face type (edge node, corner, corner), and how many; none for the others.
inline int transformedEdges(mesh::FaceType f, const int (**edges)[3]) {
  if (f == mesh::FaceType::Quad8) {
    *edges = kQuad8Edge;
    return 4;
  }
  if (f == mesh::FaceType::Tri6) {
    *edges = kTri6Edge;
    return 3;
  }
  *edges = nullptr;
  return 0;
}

/// @brief Standard (Lagrange) shape functions N_a(xi) of the reference face.
template <mesh::FaceType F, typename X>
inline NodalValues<F, X> faceShapeValues(const FacePoint<F, X>& xi) {
  if constexpr (F == mesh::FaceType::Tri6) {
    const X L0 = 1.0 - xi[0] - xi[1], L1 = xi[0], L2 = xi[1];
    return {X(L0 * (2.0 * L0 - 1.0)), X(L1 * (2.0 * L1 - 1.0)), X(L2 * (2.0 * L2 - 1.0)),
            X(4.0 * L0 * L1),         X(4.0 * L1 * L2),         X(4.0 * L2 * L0)};
  } else if constexpr (F == mesh::FaceType::Quad8) {
    NodalValues<F, X> N{};
    for (int a = 0; a < 4; ++a) {
      const double sa = kQuad9Node[a][0], ta = kQuad9Node[a][1];
      N[a] = 0.25 * (1.0 + sa * xi[0]) * (1.0 + ta * xi[1]) * (sa * xi[0] + ta * xi[1] - 1.0);
    }
    for (int a = 4; a < 8; ++a) {
      const double sa = kQuad9Node[a][0], ta = kQuad9Node[a][1];
      N[a] = sa == 0 ? X(0.5 * (1.0 - xi[0] * xi[0]) * (1.0 + ta * xi[1]))
                     : X(0.5 * (1.0 + sa * xi[0]) * (1.0 - xi[1] * xi[1]));
    }
    return N;
  } else if constexpr (F == mesh::FaceType::Line2) {
    return {X(0.5 * (1.0 - xi[0])), X(0.5 * (1.0 + xi[0]))};
  } else if constexpr (F == mesh::FaceType::Line3) {
    return {X(0.5 * xi[0] * (xi[0] - 1.0)), X(0.5 * xi[0] * (xi[0] + 1.0)), X(1.0 - xi[0] * xi[0])};
  } else if constexpr (F == mesh::FaceType::Quad9) {
    NodalValues<F, X> N{};
    for (int a = 0; a < 9; ++a) N[a] = lagrange3<X>(kQuad9Node[a][0], xi[0]) * lagrange3<X>(kQuad9Node[a][1], xi[1]);
    return N;
  } else if constexpr (F == mesh::FaceType::Tri3) {
    return {X(1.0 - xi[0] - xi[1]), xi[0], xi[1]};
  } else {
    const X a = 1.0 - xi[0], b = 1.0 + xi[0], c = 1.0 - xi[1], d = 1.0 + xi[1];
    return {X(0.25 * a * c), X(0.25 * b * c), X(0.25 * b * d), X(0.25 * a * d)};
  }
}

/// @brief Parametric gradients g[a][i] = dN_a/dxi_i of the reference face.
template <mesh::FaceType F, typename X>
inline std::array<std::array<X, FaceTraits<F>::paramDim>, FaceTraits<F>::nodes> faceShapeGradients(
    const FacePoint<F, X>& xi) {
  if constexpr (F == mesh::FaceType::Tri6) {
    const X L0 = 1.0 - xi[0] - xi[1], L1 = xi[0], L2 = xi[1];
    // dL0 = (-1, -1), dL1 = (1, 0), dL2 = (0, 1).
    return {{{X(1.0 - 4.0 * L0), X(1.0 - 4.0 * L0)},
             {X(4.0 * L1 - 1.0), X(0.0)},
             {X(0.0), X(4.0 * L2 - 1.0)},
             {X(4.0 * (L0 - L1)), X(-4.0 * L1)},
             {X(4.0 * L2), X(4.0 * L1)},
             {X(-4.0 * L2), X(4.0 * (L0 - L2))}}};
  } else if constexpr (F == mesh::FaceType::Quad8) {
    std::array<std::array<X, 2>, 8> g{};
    for (int a = 0; a < 4; ++a) {
      const double sa = kQuad9Node[a][0], ta = kQuad9Node[a][1];
      g[a][0] = 0.25 * sa * (1.0 + ta * xi[1]) * (2.0 * sa * xi[0] + ta * xi[1]);
      g[a][1] = 0.25 * ta * (1.0 + sa * xi[0]) * (sa * xi[0] + 2.0 * ta * xi[1]);
    }
    for (int a = 4; a < 8; ++a) {
      const double sa = kQuad9Node[a][0], ta = kQuad9Node[a][1];
      if (sa == 0) {
        g[a][0] = -xi[0] * (1.0 + ta * xi[1]);
        g[a][1] = 0.5 * ta * (1.0 - xi[0] * xi[0]);
      } else {
        g[a][0] = 0.5 * sa * (1.0 - xi[1] * xi[1]);
        g[a][1] = -xi[1] * (1.0 + sa * xi[0]);
      }
    }
    return g;
  } else if constexpr (F == mesh::FaceType::Line2) {
    (void)xi;
    return {{{X(-0.5)}, {X(0.5)}}};
  } else if constexpr (F == mesh::FaceType::Line3) {
    return {{{X(xi[0] - 0.5)}, {X(xi[0] + 0.5)}, {X(-2.0 * xi[0])}}};
  } else if constexpr (F == mesh::FaceType::Quad9) {
    std::array<std::array<X, 2>, 9> g{};
    for (int a = 0; a < 9; ++a) {
      g[a][0] = lagrange3Derivative<X>(kQuad9Node[a][0], xi[0]) * lagrange3<X>(kQuad9Node[a][1], xi[1]);
      g[a][1] = lagrange3<X>(kQuad9Node[a][0], xi[0]) * lagrange3Derivative<X>(kQuad9Node[a][1], xi[1]);
    }
    return g;
  } else if constexpr (F == mesh::FaceType::Tri3) {
    (void)xi;
    return {{{X(-1.0), X(-1.0)}, {X(1.0), X(0.0)}, {X(0.0), X(1.0)}}};
  } else {
    const X a = 1.0 - xi[0], b = 1.0 + xi[0], c = 1.0 - xi[1], d = 1.0 + xi[1];
    return {{{X(-0.25 * c), X(-0.25 * a)},
             {X(0.25 * c), X(-0.25 * b)},
             {X(0.25 * d), X(0.25 * b)},
             {X(-0.25 * d), X(0.25 * a)}}};
  }
}

/// @brief The slave displacement basis the multipliers are dual to: N for
/// every face but Quad8 and Tri6, whose standard D_j = int N_j is negative
/// or zero at the corners; for those the transformed basis of Popp,
/// Wohlmuth, Gee and Wall (2012),
///   N~_c = N_c + alpha (N_e + N_e')  (corner c, e and e' its two edges),
///   N~_e = (1 - 2 alpha) N_e          (edge node e),
/// the same space (sum N~ = 1, the surface unchanged), with every
/// int N~_j dA > 0 (kTransformedBasisAlpha). The nodal values it
/// interpolates are transformed too (d = T d~: d_c = d~_c, d_e = (1 - 2
/// alpha) d~_e + alpha (d~_a + d~_b)); ContactPair carries the contact rows
/// between the two (docs/architecture.md, "Quadratic faces").
/// (trialFromShapeValues: N~ from the standard values N at the same point.)
template <mesh::FaceType F, typename X>
inline NodalValues<F, X> trialFromShapeValues(const NodalValues<F, X>& N) {
  if constexpr (transformedSlaveBasis(F)) {
    const int (*edges)[3] = nullptr;
    const int count = transformedEdges(F, &edges);
    NodalValues<F, X> out = N;
    for (int k = 0; k < count; ++k) {
      const X Ne = N[edges[k][0]];
      out[edges[k][0]] = (1.0 - 2.0 * kTransformedBasisAlpha) * Ne;
      out[edges[k][1]] += kTransformedBasisAlpha * Ne;
      out[edges[k][2]] += kTransformedBasisAlpha * Ne;
    }
    return out;
  }
  return N;
}
template <mesh::FaceType F, typename X>
inline NodalValues<F, X> faceTrialValues(const FacePoint<F, X>& xi) {
  return trialFromShapeValues<F, X>(faceShapeValues<F, X>(xi));
}

/// @brief Dual shape functions Phi_j = sum_k A_jk N~_k at xi, from the
/// coefficients A (N~ = faceTrialValues: N but on Quad8 and Tri6).
template <mesh::FaceType F, typename T, typename X>
inline NodalValues<F, T> dualShapeValues(const NodalMatrix<F, T>& A, const FacePoint<F, X>& xi) {
  const NodalValues<F, X> N = faceTrialValues<F, X>(xi);
  NodalValues<F, T> phi{};
  for (int j = 0; j < FaceTraits<F>::nodes; ++j) {
    phi[j] = 0.0;
    for (int k = 0; k < FaceTraits<F>::nodes; ++k) phi[j] += A[j][k] * N[k];
  }
  return phi;
}

/// @brief Point x(xi) = sum_a N_a(xi) x_a of the face.
template <mesh::FaceType F, typename T, typename X>
inline std::array<T, FaceTraits<F>::spaceDim> facePoint(const FaceNodes<F, T>& x, const FacePoint<F, X>& xi) {
  const NodalValues<F, X> N = faceShapeValues<F, X>(xi);
  std::array<T, FaceTraits<F>::spaceDim> p{};
  for (int i = 0; i < FaceTraits<F>::spaceDim; ++i) {
    p[i] = 0.0;
    for (int a = 0; a < FaceTraits<F>::nodes; ++a) p[i] += N[a] * x[a][i];
  }
  return p;
}

/// @brief Surface measure |dx/dxi| at xi: Line2 |x1 - x0|/2, Tri3/Quad4 |x_xi × x_eta|.
template <mesh::FaceType F, typename T>
T surfaceJacobian(const FaceNodes<F, T>& x, const FacePoint<F, T>& xi);

/// @brief Element integrals of the slave basis (faceTrialValues: N~ = N
/// but on Quad8 and Tri6) on the current face.
template <mesh::FaceType F, typename T>
struct FaceMass {
  NodalValues<F, T> De{};  ///< De[j] = int N~_j dA
  NodalMatrix<F, T> Me{};  ///< Me[j][k] = int N~_j N~_k dA
};

/// @brief D_e and M_e of the face with nodal coordinates x.
template <mesh::FaceType F, typename T>
FaceMass<F, T> faceMass(const FaceNodes<F, T>& x);

/// @brief Dual coefficients A = D_e M_e^{-1} (A[j][k]) of the face with nodal coordinates x.
/// Throws coulomb::Error for a degenerate face (M_e not positive definite).
template <mesh::FaceType F, typename T>
NodalMatrix<F, T> dualCoefficients(const FaceNodes<F, T>& x);

#define COULOMB_CONTACT_DUAL_EXTERN(F)                                                            \
  extern template double surfaceJacobian<F, double>(const FaceNodes<F, double>&,                  \
                                                    const FacePoint<F, double>&);                 \
  extern template FaceMass<F, double> faceMass<F, double>(const FaceNodes<F, double>&);           \
  extern template NodalMatrix<F, double> dualCoefficients<F, double>(const FaceNodes<F, double>&);
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Line2)
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Line3)
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Tri3)
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Quad4)
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Quad9)
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Quad8)
COULOMB_CONTACT_DUAL_EXTERN(mesh::FaceType::Tri6)
#undef COULOMB_CONTACT_DUAL_EXTERN

}  // namespace coulomb::contact
