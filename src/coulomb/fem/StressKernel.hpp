#pragma once
/// @file StressKernel.hpp
/// @brief Cauchy stress of a cell, volume-weighted at its nodes for a lumped
/// L2 projection, and the von Mises equivalent stress.
#include <array>

#include "coulomb/fem/ElementKernel.hpp"

namespace coulomb::fem {

/// @brief Volume-weighted nodal Cauchy stress of one cell.
///
/// weightedStress[a*6+k] = \int_{Omega_0} N_a sigma_k dV_0, weight[a] = \int_{Omega_0} N_a dV_0,
/// so that the lumped L2 projection at a node is (sum over cells of weightedStress) / (sum of
/// weight). Quadratic cells use N_a^2 in place of N_a in both (a diagonally scaled lumping):
/// \int N_a is zero at the corners of a straight TRI6 and negative at those of QUAD8, HEX20
/// and TET10, which would leave a corner without a weight or divide by a negative sum;
/// N_a^2 weights are positive for every node, and a constant stress is still recovered exactly. Voigt order xx yy zz xy yz xz. Linear elastic: sigma = C : eps (2D plane strain
/// sigma_zz = nu (sigma_xx + sigma_yy), plane stress sigma_zz = 0). Neo-Hookean: Cauchy
/// sigma = P F^T / J. 2D integrals are multiplied by the thickness (it cancels in the ratio).
/// Outputs are overwritten; zero-filled unless Ok.
template <mesh::CellType T>
KernelStatus cellNodalStress(const MaterialParameters& material, const std::array<double, CellTraits<T>::dofs>& X,
                             const std::array<double, CellTraits<T>::dofs>& u,
                             std::array<double, CellTraits<T>::nodes * 6>& weightedStress,
                             std::array<double, CellTraits<T>::nodes>& weight);

/// @brief Von Mises stress sqrt(3/2 s:s), s = deviator of the Voigt stress (xx yy zz xy yz xz).
double vonMises(const std::array<double, 6>& voigtStress);

}  // namespace coulomb::fem
