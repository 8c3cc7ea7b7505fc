#pragma once
/// @file MortarSegment2D.hpp
/// @brief Mortar integration of one slave Line2 against one master Line2 (2D):
/// the contributions of the pair to D, M and the weighted gap, with their
/// derivatives.
///
/// Notation (thesis §4.3, superscript 1 = slave, 2 = master; seed eq. 4.63):
///   D_j  = int_{gamma_seg} Phi_j dA
///        = sum_k int_{gamma_seg} Phi_j N^1_k dA                (row-sum/lumped form),
///   M_jl = int_{gamma_seg} Phi_j N^2_l(xi^2(xi)) dA,
///   g~_j = int_{gamma_seg} Phi_j g_n dA,   g_n = (x^2(xi^2(xi)) - x^1(xi)) . n^(xi),
/// where gamma_seg is the part of the slave segment onto which the master segment
/// projects, Phi_j the dual basis of the slave (DualBasis.hpp) and dA the slave
/// measure. Summed over master segments covering a whole slave element, D_j is
/// int Phi_j dA = int N_j dA, i.e. the diagonal D_jj of the dual mortar matrix
/// int Phi_j N_k dA (biorthogonality); on a partial overlap the off-diagonal
/// parts of int Phi_j N_k dA are lumped onto the diagonal, so that
/// sum_l M_jl = D_j holds segment by segment (sum_l N^2_l = 1: a rigid
/// translation gives zero weighted relative displacement).
///
/// Sign convention: n are the slave normals (unit nodal normals n_k as given,
/// pointing from the slave body towards the master), g_n > 0 is an open gap and
/// g_n < 0 a penetration. This is the seed's weighted gap
/// -n.(D x^1 - M x^2) (positive when open) evaluated pointwise under the integral.
///
/// Projection (Popp et al. 2D segmentation; "normal field" projection):
///   slave normal field   n(xi) = sum_k N^1_k(xi) n_k        (not normalised),
///   master node l -> xi:  (x^2_l - x^1(xi)) × n(xi) = 0       (quadratic in xi, Newton),
///   slave point  -> xi^2: (x^2(xi^2) - x^1(xi)) × n(xi) = 0  (linear in xi^2),
/// with a × b = a_x b_y - a_y b_x. The overlap in slave coordinates is the
/// interval between the projections of the two master nodes, cut to [-1, 1];
/// at xi = ±1 the projection direction is the nodal normal n_k.
/// The gap normal is n^(xi) = n(xi)/|n(xi)|.
///
/// Integration: 5-point Gauss–Legendre on the overlap interval (degree 9). D is
/// exact (integrand linear); M and g~ are exact when the nodal normals are equal
/// (then xi^2 and g_n are affine in xi: degree 2); with different nodal normals
/// xi^2(xi) is rational and the renormalised n^ is not polynomial, and the rule
/// is an approximation (the same one in the value and its derivative).
///
/// Scalar types: integrateSegment2D is explicitly instantiated for double and
/// Sacado::Fad::SFad<double, 12> in MortarSegment2D.cpp.
#include <array>
#include <cmath>

#include "coulomb/contact/mortar/DualBasis.hpp"

namespace coulomb::contact {

/// Nodal 2D vectors of a Line2: x[node][component].
template <typename T>
using Line2Nodes = FaceNodes<mesh::FaceType::Line2, T>;

/// @brief Contribution of one (slave, master) Line2 pair.
template <typename T>
struct MortarSegment2D {
  bool contributes = false;                 ///< false: the projections do not overlap (all zero)
  std::array<T, 2> D{};                     ///< D_j = int Phi_j dA
  std::array<std::array<T, 2>, 2> M{};      ///< M[j][l] = int Phi_j N^2_l dA
  std::array<T, 2> gap{};                   ///< g~_j = int Phi_j g_n dA
  T length{};                               ///< overlap length on the slave = sum_j D_j
  std::array<double, 2> slaveInterval{};    ///< overlap [xi_lo, xi_hi] in slave coordinates
};

/// @brief Integrates one pair. xs: slave nodes, ns: slave unit nodal normals
/// (averaged over the slave faces at the node), xm: master nodes.
/// `relativeTolerance`: an overlap shorter than relativeTolerance × (slave
/// parametric length 2) is "no contribution".
/// `axisymmetric` (x = r, y = z; Plane Assumption = Axisymmetric): the
/// integrals are over the ring, dA = 2 pi r ds with r = x of the slave point,
/// and the dual basis is biorthogonal in that measure (axisymmetricDual), so
/// D stays diagonal; the 2 pi r of D, M and g~ carry through the derivatives.
template <typename T>
MortarSegment2D<T> integrateSegment2D(const Line2Nodes<T>& xs, const Line2Nodes<T>& ns, const Line2Nodes<T>& xm,
                                      double relativeTolerance = 1e-10, bool axisymmetric = false);

/// @brief D_e and M_e of a Line2 face in the ring measure 2 pi r ds (r linear
/// between the nodal radii r_0, r_1, L the length): D_e = 2 pi L/6 (2 r_0 + r_1,
/// r_0 + 2 r_1), M_e = 2 pi L/12 [[3 r_0 + r_1, r_0 + r_1], [r_0 + r_1, r_0 + 3 r_1]].
template <typename T>
FaceMass<mesh::FaceType::Line2, T> ringMass(const Line2Nodes<T>& xs);

/// @brief Dual coefficients A = D_e M_e^-1 of ringMass (the ring's dual basis).
/// Equal radii give the plane [[2, -1], [-1, 2]].
template <typename T>
NodalMatrix<mesh::FaceType::Line2, T> axisymmetricDual(const Line2Nodes<T>& xs);

/// Whether the Newton iteration of a 2D projection (a point onto a face along
/// a normal) has converged after a step `step` ending at face parameter `s`.
/// Newton converges quadratically there: a step of 1e-10 leaves an error of
/// ~1e-20, and the kernels take one more step in their scalar type after it.
/// A step at round-off (1e-14) was unreachable for a point far outside the
/// face (a master seven times as long as the slave face: s ~ 8, steps of
/// ~1.6e-13) and dropped the pair — D of its slave nodes incomplete, the
/// active set chattering (tests/zoo at order 2, tests/performance/README.md).
inline bool projectionConverged(double step, double s) { return std::abs(step) <= 1e-10 * (1.0 + std::abs(s)); }

extern template MortarSegment2D<double> integrateSegment2D<double>(const Line2Nodes<double>&,
                                                                   const Line2Nodes<double>&,
                                                                   const Line2Nodes<double>&, double, bool);
extern template NodalMatrix<mesh::FaceType::Line2, double> axisymmetricDual<double>(const Line2Nodes<double>&);
extern template FaceMass<mesh::FaceType::Line2, double> ringMass<double>(const Line2Nodes<double>&);

/// Number of inputs of the 2D kernel: xs (4), ns (4), xm (4).
inline constexpr int kSegment2DInputs = 12;

/// @brief Values and first derivatives of a 2D pair.
///
/// Input index of a derivative: [0,4) slave coordinates (node-major: x0 y0 x1 y1),
/// [4,8) slave nodal normals (same order), [8,12) master coordinates.
struct MortarSegment2DLinearization {
  MortarSegment2D<double> value;
  std::array<std::array<double, kSegment2DInputs>, 2> dD{};                 ///< dD[j][i]
  std::array<std::array<std::array<double, kSegment2DInputs>, 2>, 2> dM{};  ///< dM[j][l][i]
  std::array<std::array<double, kSegment2DInputs>, 2> dGap{};               ///< dGap[j][i]
  std::array<double, kSegment2DInputs> dLength{};                           ///< dLength[i]
};

/// @brief Values and derivatives with respect to all 12 inputs (Sacado SFad<12>).
/// The derivatives are those of the current overlap topology (which ends of the
/// overlap are slave nodes and which are projected master nodes).
MortarSegment2DLinearization linearizeSegment2D(const Line2Nodes<double>& xs, const Line2Nodes<double>& ns,
                                                const Line2Nodes<double>& xm, double relativeTolerance = 1e-10,
                                                bool axisymmetric = false);

}  // namespace coulomb::contact
