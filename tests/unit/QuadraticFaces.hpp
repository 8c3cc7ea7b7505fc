#pragma once
// Quadratic contact faces for the tests of the sub-facet mortar kernel
// (MortarSegmentQuadratic3D.hpp): Quad9, Quad8 and Tri6 faces on
// rectangles and triangles of a plane z = const, optionally curved (`bow`
// lifts the mid-side and centre nodes) and sheared (`skew`), the same face
// seen from the body facing it, and nodal normals.
#include <array>
#include <cmath>

#include "coulomb/contact/mortar/DualBasis.hpp"

namespace coulomb::contact::test {

using Q9 = FaceNodes<mesh::FaceType::Quad9, double>;
using Q8 = FaceNodes<mesh::FaceType::Quad8, double>;
using T6 = FaceNodes<mesh::FaceType::Tri6, double>;

/// The Quad9 of the rectangle [x0, x0 + a] x [y0, y0 + b] at height z, its
/// nodes at the Exodus reference positions mapped affinely; `bow` lifts the
/// mid-sides by bow / 2 and the centre by bow, `skew` shears x by y. Normal +z.
inline Q9 quad9(double x0, double y0, double a, double b, double z, double bow = 0.0, double skew = 0.0) {
  Q9 x{};
  for (int k = 0; k < 9; ++k) {
    const double s = kQuad9Node[k][0], t = kQuad9Node[k][1];
    const double lift = k < 4 ? 0.0 : bow * (k == 8 ? 1.0 : 0.5);
    x[k] = {x0 + a * (s + 1) / 2 + skew * (t + 1) / 2, y0 + b * (t + 1) / 2, z + lift};
  }
  return x;
}

/// The Quad8 of the same rectangle (the Quad9 without its centre).
inline Q8 quad8(double x0, double y0, double a, double b, double z, double bow = 0.0, double skew = 0.0) {
  const Q9 full = quad9(x0, y0, a, b, z, bow, skew);
  Q8 x{};
  for (int k = 0; k < 8; ++k) x[k] = full[k];
  return x;
}

/// The Tri6 of the triangle p0 p1 p2 at height z, normal +z for a
/// counter-clockwise p; `bow` lifts the mid-sides.
inline T6 tri6(std::array<double, 2> p0, std::array<double, 2> p1, std::array<double, 2> p2, double z,
               double bow = 0.0) {
  const std::array<std::array<double, 2>, 3> p{p0, p1, p2};
  T6 x{};
  for (int c = 0; c < 3; ++c) x[c] = {p[c][0], p[c][1], z};
  for (int e = 0; e < 3; ++e) {
    const auto& a = p[kTri6Edge[e][1]];
    const auto& b = p[kTri6Edge[e][2]];
    x[kTri6Edge[e][0]] = {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, z + bow};
  }
  return x;
}

/// The same face seen from a body facing it (orientation reversed).
inline Q9 reversed(const Q9& x) { return {x[0], x[3], x[2], x[1], x[7], x[6], x[5], x[4], x[8]}; }
inline Q8 reversed(const Q8& x) { return {x[0], x[3], x[2], x[1], x[7], x[6], x[5], x[4]}; }
inline T6 reversed(const T6& x) { return {x[0], x[2], x[1], x[5], x[4], x[3]}; }

/// Nodal normals +z.
template <mesh::FaceType F>
FaceNodes<F, double> up() {
  FaceNodes<F, double> n{};
  for (auto& v : n) v = {0.0, 0.0, 1.0};
  return n;
}

/// Slightly tilted nodal normals, a different tilt at each node.
template <mesh::FaceType F>
FaceNodes<F, double> tilted() {
  FaceNodes<F, double> ns{};
  for (int k = 0; k < FaceTraits<F>::nodes; ++k) {
    const double tilt = 0.05 * (k % 3) - 0.04 * (k / 3);
    const double n = std::sqrt(1 + 2 * tilt * tilt);
    ns[k] = {tilt / n, -tilt / n, 1 / n};
  }
  return ns;
}

}  // namespace coulomb::contact::test
