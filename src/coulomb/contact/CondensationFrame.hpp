#pragma once
/// @file CondensationFrame.hpp
/// @brief Kernel: how the rows of one active slave node are recombined when
/// its normal Lagrange multiplier is condensed out (dual mortar: D diagonal).
///
/// Frictionless contact with lambda_j = lambda_n n_j puts the force
/// k D_j lambda_n n_j on the slave node's displacement rows. Only the free
/// (not prescribed) components F of the node carry equilibrium equations;
/// let n_F be n restricted to F and a = n_F / |n_F|. Then
///   a . (rows F)   = a . r_F + k D lambda_n |n_F|   determines lambda_n,
///   b_i . (rows F) = b_i . r_F                      (b_i ⟂ a) do not involve it.
/// Condensation: lambda_n is eliminated with the a-row, which is then
/// replaced by the (scaled) weighted-gap constraint, and the b_i rows stay.
/// The rows are written back into the node's free component slots: the gap
/// row into the slot with the largest |n_c| (so its diagonal entry, about
/// -D n_slot, is far from zero and made positive by `gapRowSign`), the b_i
/// rows into the remaining slots, b_i built by Gram-Schmidt from the unit
/// vectors of those slots (so b_i ≈ e_slot when n is nearly along the gap
/// slot: diagonally dominant rows for the smoothers).
///
/// A node whose free components hardly see the normal (|n_F| small, e.g. a
/// node on a symmetry plane whose normal is perpendicular to the free
/// directions) cannot carry a normal multiplier: `usable` is false and the
/// caller leaves it inactive.
#include <array>

namespace coulomb::contact {

template <int dim>
struct CondensationFrame {
  bool usable = false;
  int numFree = 0;
  std::array<int, dim> free{};           ///< free components, increasing (first numFree)
  int gapSlot = -1;                      ///< component slot receiving the gap row
  double gapRowSign = 1.0;               ///< -sign(n_gapSlot): positive diagonal of the gap row
  double normFree = 0.0;                 ///< |n_F|
  std::array<double, dim> a{};           ///< n_F / |n_F| (zero on prescribed components)
  /// b[s] for every free slot s != gapSlot: unit, ⟂ a and to each other, zero
  /// on prescribed components; unused slots zero.
  std::array<std::array<double, dim>, dim> b{};
};

/// Smallest |n_F| for which a node is usable (about 78° between n and the free space).
inline constexpr double kMinimumFreeNormal = 0.2;

/// @brief The frame of a node with unit normal `n` and prescribed components
/// `prescribed[c]`.
template <int dim>
CondensationFrame<dim> condensationFrame(const std::array<double, dim>& n, const std::array<bool, dim>& prescribed);

extern template CondensationFrame<2> condensationFrame<2>(const std::array<double, 2>&, const std::array<bool, 2>&);
extern template CondensationFrame<3> condensationFrame<3>(const std::array<double, 3>&, const std::array<bool, 3>&);

}  // namespace coulomb::contact
