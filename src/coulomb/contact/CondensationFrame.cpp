#include "coulomb/contact/CondensationFrame.hpp"

#include <cmath>

namespace coulomb::contact {

template <int dim>
CondensationFrame<dim> condensationFrame(const std::array<double, dim>& n, const std::array<bool, dim>& prescribed) {
  CondensationFrame<dim> frame;
  double norm2 = 0.0;
  for (int c = 0; c < dim; ++c) {
    if (prescribed[c]) continue;
    frame.free[frame.numFree++] = c;
    norm2 += n[c] * n[c];
  }
  frame.normFree = std::sqrt(norm2);
  if (frame.numFree == 0 || frame.normFree < kMinimumFreeNormal) return frame;
  frame.usable = true;
  double largest = -1.0;
  for (int i = 0; i < frame.numFree; ++i) {
    const int c = frame.free[i];
    frame.a[c] = n[c] / frame.normFree;
    if (std::abs(n[c]) > largest) {
      largest = std::abs(n[c]);
      frame.gapSlot = c;
    }
  }
  frame.gapRowSign = n[frame.gapSlot] > 0 ? -1.0 : 1.0;
  // Gram-Schmidt of the unit vectors of the other free slots against a and the b's so far.
  std::array<std::array<double, dim>, dim> basis{};
  int done = 0;
  basis[done++] = frame.a;
  for (int i = 0; i < frame.numFree; ++i) {
    const int s = frame.free[i];
    if (s == frame.gapSlot) continue;
    std::array<double, dim> v{};
    v[s] = 1.0;
    for (int k = 0; k < done; ++k) {
      double dot = 0.0;
      for (int c = 0; c < dim; ++c) dot += v[c] * basis[k][c];
      for (int c = 0; c < dim; ++c) v[c] -= dot * basis[k][c];
    }
    double length = 0.0;
    for (int c = 0; c < dim; ++c) length += v[c] * v[c];
    length = std::sqrt(length);
    // |v| >= the distance of e_s from span(a, ...) > 0: e_s is not the largest
    // component of a, so it is not in that span (a has |a_slot| >= 1/sqrt(dim)).
    for (int c = 0; c < dim; ++c) v[c] /= length;
    frame.b[s] = v;
    basis[done++] = v;
  }
  return frame;
}

template CondensationFrame<2> condensationFrame<2>(const std::array<double, 2>&, const std::array<bool, 2>&);
template CondensationFrame<3> condensationFrame<3>(const std::array<double, 3>&, const std::array<bool, 3>&);

}  // namespace coulomb::contact
