#pragma once
/// @file MortarSegmentCurved2D.hpp
/// @brief Mortar integration of one slave against one master face in 2D when
/// either is a quadratic Line3 (issue 18, item 2): the same quantities as
/// MortarSegment2D.hpp (D_j, M_jl, g~_j and their derivatives), on curved
/// faces.
///
/// Equations (seed eq. 4.63, MortarSegment2D.hpp for the notation), with
///   slave   x^1(xi) = sum_k N_k(xi) x_k,   normal field n(xi) = sum_k N_k(xi) n_k,
///   master  x^2(eta) = sum_l N^2_l(eta) x^2_l,
/// N the Line2 or Line3 shape functions (DualBasis.hpp). The dual basis of a
/// Line3 slave is the standard quadratic one, Phi_j = sum_k A_jk N_k with
/// A = D_e M_e^-1: its D_e = int N_j dA is positive at every node (h/6, h/6,
/// 2h/3 on a straight face), so D stays diagonal and positive and the
/// condensation works as for Line2 (in 3D only the biquadratic Quad9 keeps
/// that property; Quad8 and Tri6 take a transformed basis, DualBasis.hpp).
///
/// Projections along the normal field, each solved by Newton in doubles and
/// finished by one Newton step in the scalar type (the implicit function
/// theorem gives the exact derivative):
///   master corner l -> xi:   (x^2_l - x^1(xi)) × n(xi) = 0   (quartic for Line3),
///   slave point  -> eta:     (x^2(eta) - x^1(xi)) × n(xi) = 0 (quadratic for Line3).
/// The overlap is the slave interval between the projections of the master's
/// corners (nodes 0 and 1 of either face type), cut to [-1, 1]. 5-point Gauss
/// on it: exact for straight faces with equal nodal normals (the patch tests),
/// an approximation otherwise, the same one in value and derivative.
/// Axisymmetric (x = r): dA = 2 pi r ds and the dual basis biorthogonal in it.
#include <array>

#include "coulomb/contact/mortar/DualBasis.hpp"

namespace coulomb::contact {

/// Number of inputs of the kernel: slave coordinates, slave normals, master coordinates.
template <mesh::FaceType S, mesh::FaceType Mf>
inline constexpr int curved2DInputs = 4 * FaceTraits<S>::nodes + 2 * FaceTraits<Mf>::nodes;

/// @brief Contribution of one (slave S, master Mf) pair.
template <mesh::FaceType S, mesh::FaceType Mf, typename T>
struct MortarSegmentCurved2D {
  static constexpr int nS = FaceTraits<S>::nodes, nM = FaceTraits<Mf>::nodes;
  bool contributes = false;
  std::array<T, nS> D{};
  std::array<std::array<T, nM>, nS> M{};
  std::array<T, nS> gap{};
  T length{};
  std::array<double, 2> slaveInterval{};
};

/// @brief D_e and M_e of a Line2/Line3 face in the measure dA (ds, or 2 pi r ds
/// when `axisymmetric`), 5-point Gauss.
template <mesh::FaceType S, typename T>
FaceMass<S, T> lineMass(const FaceNodes<S, T>& xs, bool axisymmetric);

/// @brief Integrates one pair (see the file comment). `relativeTolerance` as
/// in integrateSegment2D.
template <mesh::FaceType S, mesh::FaceType Mf, typename T>
MortarSegmentCurved2D<S, Mf, T> integrateCurvedSegment2D(const FaceNodes<S, T>& xs, const FaceNodes<S, T>& ns,
                                                         const FaceNodes<Mf, T>& xm, double relativeTolerance,
                                                         bool axisymmetric);

/// @brief Values and first derivatives (Sacado SFad over the inputs; index:
/// [0, 2 nS) slave coordinates node-major, [2 nS, 4 nS) slave normals,
/// then the master coordinates).
template <mesh::FaceType S, mesh::FaceType Mf>
struct MortarSegmentCurved2DLinearization {
  static constexpr int N = curved2DInputs<S, Mf>;
  static constexpr int nS = FaceTraits<S>::nodes, nM = FaceTraits<Mf>::nodes;
  MortarSegmentCurved2D<S, Mf, double> value;
  std::array<std::array<double, N>, nS> dD{};
  std::array<std::array<std::array<double, N>, nM>, nS> dM{};
  std::array<std::array<double, N>, nS> dGap{};
  std::array<double, N> dLength{};
};

template <mesh::FaceType S, mesh::FaceType Mf>
MortarSegmentCurved2DLinearization<S, Mf> linearizeCurvedSegment2D(const FaceNodes<S, double>& xs,
                                                                   const FaceNodes<S, double>& ns,
                                                                   const FaceNodes<Mf, double>& xm,
                                                                   double relativeTolerance, bool axisymmetric);

}  // namespace coulomb::contact
