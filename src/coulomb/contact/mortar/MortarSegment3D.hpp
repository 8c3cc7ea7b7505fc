#pragma once
/// @file MortarSegment3D.hpp
/// @brief Mortar integration of one slave face (Tri3 / Quad4) against one master
/// face (Tri3 / Quad4) in 3D on an auxiliary plane: the contributions of the pair
/// to D, M and the weighted gap, with their derivatives.
///
/// Same quantities and sign convention as the 2D kernel (MortarSegment2D.hpp;
/// seed eq. 4.63, superscript 1 = slave, 2 = master):
///   D_j  = int_{gamma_seg} Phi_j dA,  M_jl = int_{gamma_seg} Phi_j N^2_l dA,
///   g~_j = int_{gamma_seg} Phi_j g_n dA,  g_n = (x^2 - x^1) . n^,  g_n > 0 open,
///   n^(xi) = sum_k N^1_k(xi) n_k / |sum_k N^1_k(xi) n_k|   (slave unit nodal normals n_k).
/// D_j is the lumped (row-sum) form, so sum_l M_jl = D_j segment by segment, and
/// over master faces tiling a slave face sum D_j = int N_j dA (biorthogonality).
///
/// Segmentation (Popp, Gitterle, Gee & Wall 2010, "auxiliary plane" variant):
///  1. auxiliary plane through the slave centre x0 = x^1(xi_c) (mean of the nodes)
///     with unit normal n0 = the slave face normal at the centre
///     (Tri3: (x1-x0)×(x2-x0); Quad4: (x2-x0)×(x3-x1), the cross product of the
///     diagonals = x_xi × x_eta at the centre = the face-averaged normal); the
///     geometric normal is used rather than the average of the nodal normals so
///     that a plane slave face lies in its plane and the segments tile it exactly;
///  2. orthogonal projection of the slave and master nodes onto the plane
///     (projection along n0; as the projection is affine, the projected face maps
///     are the Tri3/Quad4 maps of the projected nodes);
///  3. clip polygon = projected master ∩ projected slave (Sutherland–Hodgman,
///     PolygonClipping.hpp); an overlap of area below relativeTolerance × projected
///     slave area is "no contribution";
///  4. integration cells: the fan of triangles from the clip polygon's area
///     centroid, triangles too (continuous where a vertex splits in two or
///     two merge; the vertex average jumps there);
///  5. on each cell the 7-point degree-5 triangle rule (Radon); each Gauss point p
///     of the plane is mapped back to xi (slave) and xi^2 (master) by inverting the
///     projected face maps (affine for Tri3; Newton on the bilinear map for Quad4,
///     the derivative through one Newton step at the converged point), i.e. the
///     projection along n0;
///  6. dA = dA_plane × J^1(xi)/J^1_proj(xi), J^1 = |x_xi × x_eta|, J^1_proj =
///     (x_xi × x_eta).n0: the slave surface measure (the ratio is 1 on a plane
///     slave face; it corrects the measure of a warped Quad4).
///
/// Exactness: for Tri3 and parallelogram Quad4 faces, plane and parallel, with
/// equal nodal normals, every integrand is a polynomial of degree <= 4 in the
/// plane coordinates and D, M, g~ are exact (up to round-off). Approximate (the
/// same rule in value and derivative): a non-parallelogram Quad4 (the inverse
/// bilinear map is not polynomial), different nodal normals (renormalised n^),
/// warped Quad4 faces (curved surface against its plane projection: the
/// integration domain is the projected overlap, and the measure ratio is not
/// polynomial). Projected faces must be convex (no check beyond the Newton
/// convergence of the Quad4 inversion).
///
/// Scalar types: integrateSegment3D is explicitly instantiated in
/// MortarSegment3D.cpp for double and for Sacado::Fad::SFad<double, N> with
/// N = segment3DInputs<S, M> (27 Tri3/Tri3, 30 Tri3/Quad4, 33 Quad4/Tri3,
/// 36 Quad4/Quad4); only the double ones are declared `extern` here.
#include <array>

#include "coulomb/contact/mortar/DualBasis.hpp"

namespace coulomb::contact {

/// @brief Contribution of one (slave S, master Mf) face pair.
template <mesh::FaceType S, mesh::FaceType Mf, typename T>
struct MortarSegment3D {
  static constexpr int nS = FaceTraits<S>::nodes;
  static constexpr int nM = FaceTraits<Mf>::nodes;
  bool contributes = false;               ///< false: no overlap (all values zero)
  std::array<T, nS> D{};                  ///< D_j = int Phi_j dA
  std::array<std::array<T, nM>, nS> M{};  ///< M[j][l] = int Phi_j N^2_l dA
  std::array<T, nS> gap{};                ///< g~_j = int Phi_j g_n dA
  T area{};                               ///< overlap area on the slave surface = sum_j D_j
  int polygonVertices = 0;                ///< vertices of the clip polygon (0 when none)
};

/// @brief Integrates one pair. xs: slave nodes, ns: slave unit nodal normals,
/// xm: master nodes (Exodus node order; both faces may have either orientation).
template <mesh::FaceType S, mesh::FaceType Mf, typename T>
MortarSegment3D<S, Mf, T> integrateSegment3D(const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns,
                                             const FaceNodes<Mf, T>& xm, double relativeTolerance = 1e-10);

/// Number of inputs of a 3D pair: slave coordinates, slave normals, master coordinates.
template <mesh::FaceType S, mesh::FaceType Mf>
inline constexpr int segment3DInputs = 3 * (2 * FaceTraits<S>::nodes + FaceTraits<Mf>::nodes);

/// @brief Values and first derivatives of a 3D pair.
///
/// Input index i of a derivative: [0, 3 nS) slave coordinates (node-major:
/// x0 y0 z0 x1 ...), [3 nS, 6 nS) slave nodal normals (same order),
/// [6 nS, 6 nS + 3 nM) master coordinates.
template <mesh::FaceType S, mesh::FaceType Mf>
struct MortarSegment3DLinearization {
  static constexpr int nS = FaceTraits<S>::nodes;
  static constexpr int nM = FaceTraits<Mf>::nodes;
  static constexpr int inputs = segment3DInputs<S, Mf>;
  MortarSegment3D<S, Mf, double> value;
  std::array<std::array<double, inputs>, nS> dD{};                   ///< dD[j][i]
  std::array<std::array<std::array<double, inputs>, nM>, nS> dM{};   ///< dM[j][l][i]
  std::array<std::array<double, inputs>, nS> dGap{};                 ///< dGap[j][i]
  std::array<double, inputs> dArea{};                                ///< dArea[i]
};

/// @brief Values and derivatives with respect to all inputs (Sacado SFad).
/// The derivatives are those of the current clip topology (see PolygonClipping.hpp).
template <mesh::FaceType S, mesh::FaceType Mf>
MortarSegment3DLinearization<S, Mf> linearizeSegment3D(const FaceNodes<S, double>& xs,
                                                       const FaceNodes<S, double>& ns,
                                                       const FaceNodes<Mf, double>& xm,
                                                       double relativeTolerance = 1e-10);

#define COULOMB_CONTACT_SEGMENT3D_EXTERN(S, Mf)                                                             \
  extern template MortarSegment3D<S, Mf, double> integrateSegment3D<S, Mf, double>(                       \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double);      \
  extern template MortarSegment3DLinearization<S, Mf> linearizeSegment3D<S, Mf>(                            \
      const FaceNodes<S, double>&, const FaceNodes<S, double>&, const FaceNodes<Mf, double>&, double);
COULOMB_CONTACT_SEGMENT3D_EXTERN(mesh::FaceType::Tri3, mesh::FaceType::Tri3)
COULOMB_CONTACT_SEGMENT3D_EXTERN(mesh::FaceType::Tri3, mesh::FaceType::Quad4)
COULOMB_CONTACT_SEGMENT3D_EXTERN(mesh::FaceType::Quad4, mesh::FaceType::Tri3)
COULOMB_CONTACT_SEGMENT3D_EXTERN(mesh::FaceType::Quad4, mesh::FaceType::Quad4)
#undef COULOMB_CONTACT_SEGMENT3D_EXTERN

}  // namespace coulomb::contact
