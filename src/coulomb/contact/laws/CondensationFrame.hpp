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
#include <cmath>
#include <type_traits>

namespace coulomb::contact {

/// Scalar: double, or a Sacado forward-AD type when the frame's derivatives
/// with respect to n are needed (FrictionalNode.cpp); the slot choices are
/// made on the values.
template <int dim, class Scalar = double>
struct CondensationFrame {
  bool usable = false;
  int numFree = 0;
  std::array<int, dim> free{};           ///< free components, increasing (first numFree)
  int gapSlot = -1;                      ///< component slot receiving the gap row
  double gapRowSign = 1.0;               ///< -sign(n_gapSlot): positive diagonal of the gap row
  Scalar normFree = 0.0;                 ///< |n_F|
  std::array<Scalar, dim> a{};           ///< n_F / |n_F| (zero on prescribed components)
  /// b[s] for every free slot s != gapSlot: unit, ⟂ a and to each other, zero
  /// on prescribed components; unused slots zero.
  std::array<std::array<Scalar, dim>, dim> b{};
};

/// Smallest |n_F| for which a node is usable (about 78° between n and the free space).
inline constexpr double kMinimumFreeNormal = 0.2;

/// @brief The frame of a node with unit normal `n` and prescribed components
/// `prescribed[c]`.
template <int dim, class Scalar = double>
CondensationFrame<dim, Scalar> condensationFrame(const std::array<Scalar, dim>& n,
                                                 const std::array<bool, dim>& prescribed) {
  using std::abs;
  using std::sqrt;
  auto value = [](const Scalar& x) -> double {
    if constexpr (std::is_same_v<Scalar, double>) return x;
    else return x.val();
  };
  CondensationFrame<dim, Scalar> frame;
  Scalar norm2 = 0.0;
  for (int c = 0; c < dim; ++c) {
    if (prescribed[c]) continue;
    frame.free[frame.numFree++] = c;
    norm2 += n[c] * n[c];
  }
  frame.normFree = sqrt(norm2);
  if (frame.numFree == 0 || value(frame.normFree) < kMinimumFreeNormal) return frame;
  frame.usable = true;
  double largest = -1.0;
  for (int i = 0; i < frame.numFree; ++i) {
    const int c = frame.free[i];
    frame.a[c] = n[c] / frame.normFree;
    if (std::abs(value(n[c])) > largest) {
      largest = std::abs(value(n[c]));
      frame.gapSlot = c;
    }
  }
  frame.gapRowSign = value(n[frame.gapSlot]) > 0 ? -1.0 : 1.0;
  // Gram-Schmidt of the unit vectors of the other free slots against a and the b's so far.
  std::array<std::array<Scalar, dim>, dim> basis{};
  int done = 0;
  basis[done++] = frame.a;
  for (int i = 0; i < frame.numFree; ++i) {
    const int s = frame.free[i];
    if (s == frame.gapSlot) continue;
    std::array<Scalar, dim> v{};
    v[s] = 1.0;
    for (int k = 0; k < done; ++k) {
      Scalar dot = 0.0;
      for (int c = 0; c < dim; ++c) dot += v[c] * basis[k][c];
      for (int c = 0; c < dim; ++c) v[c] -= dot * basis[k][c];
    }
    Scalar length2 = 0.0;
    for (int c = 0; c < dim; ++c) length2 += v[c] * v[c];
    // |v| >= the distance of e_s from span(a, ...) > 0: e_s is not the largest
    // component of a, so it is not in that span (a has |a_slot| >= 1/sqrt(dim)).
    const Scalar length = sqrt(length2);
    for (int c = 0; c < dim; ++c) v[c] /= length;
    frame.b[s] = v;
    basis[done++] = v;
  }
  return frame;
}

extern template CondensationFrame<2> condensationFrame<2>(const std::array<double, 2>&, const std::array<bool, 2>&);
extern template CondensationFrame<3> condensationFrame<3>(const std::array<double, 3>&, const std::array<bool, 3>&);

}  // namespace coulomb::contact
