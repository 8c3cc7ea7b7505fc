#pragma once
/// @file ElementKernel.hpp
/// @brief Residual and consistent tangent of one bulk cell (small-strain linear
/// elasticity or total-Lagrangian compressible neo-Hookean).
///
/// Kernels work on fixed-size arrays: no allocation, no MPI, no I/O. Node order is
/// the Exodus order; nodal vectors are node-major (x0 y0 [z0] x1 ...).
#include <array>

#include "coulomb/fem/Material.hpp"
#include "coulomb/fem/ShapeFunctions.hpp"
#include "coulomb/mesh/CellType.hpp"

namespace coulomb::fem {

/// @brief Compile-time sizes of a bulk cell type.
template <mesh::CellType T>
struct CellTraits {
  static constexpr int nodes = mesh::numNodes(T);
  static constexpr int dim = mesh::spatialDimension(T);
  static constexpr int dofs = nodes * dim;
  static constexpr ReferenceShape shape = referenceShape(T);
};

/// @brief Outcome of a cell kernel; outputs are zero-filled unless Ok.
enum class KernelStatus {
  Ok,
  InvertedReference,  ///< det J of the reference map <= 0 at a quadrature point
  InvertedCurrent     ///< det F <= 0 at a quadrature point (finite strain only)
};

/// @brief Human-readable name of a kernel status ("ok", "inverted reference cell", ...).
const char* toString(KernelStatus status);

/// @brief Internal-minus-external residual of one cell and its consistent tangent.
///
/// Small strain (LinearElastic):
///   r_{a i} = \int_\Omega (B_a^T sigma)_i dV - \int_\Omega N_a b_i dV,
///   sigma = lambda' tr(eps) I + 2 mu eps, eps = sym(grad u)   (lambda' see inPlaneLambda),
///   K_{a i, b k} = \int lambda' G_{a i} G_{b k} + mu G_{a k} G_{b i} + mu delta_{ik} G_a . G_b dV,
///   which is B^T C B written out for isotropic C (G_a = dN_a/dX).
/// Neo-Hookean (total Lagrangian, reference configuration Omega_0):
///   r_{a i} = \int_{Omega_0} P_{iJ} G_{a J} dV_0 - \int_{Omega_0} N_a b_i dV_0,
///   P = mu (F - F^{-T}) + lambda ln(J) F^{-T},  F = I + grad_X u,
///   K_{a i, b k} = \int G_{a J} (dP_{iJ}/dF_{kL}) G_{b L} dV_0, with dP/dF by Sacado forward AD.
/// b is a dead body force per reference volume. In 2D all integrals are multiplied by the
/// thickness. residual and *tangent (row-major dofs x dofs; may be null) are overwritten.
/// Throws coulomb::Error for NeoHookean with plane stress.
template <mesh::CellType T>
KernelStatus cellResidualTangent(const MaterialParameters& material,
                                 const std::array<double, CellTraits<T>::dofs>& X,
                                 const std::array<double, CellTraits<T>::dofs>& u,
                                 const std::array<double, CellTraits<T>::dim>& bodyForce,
                                 std::array<double, CellTraits<T>::dofs>& residual,
                                 std::array<double, CellTraits<T>::dofs * CellTraits<T>::dofs>* tangent);

}  // namespace coulomb::fem
