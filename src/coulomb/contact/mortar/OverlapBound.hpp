#pragma once
/// @file OverlapBound.hpp
/// @brief A quick, conservative test whether a slave face and a master face
/// can give a mortar segment at all, before a segment kernel clips them.
///
/// Why: the search pairs a slave face with every master face within the
/// search radius (a multiple of the largest slave face), so on a graded mesh
/// a fine slave face near the contact has hundreds of candidates, of which
/// a handful overlap it; clipping each (16 sub-facet pairs for a quadratic
/// face) was most of a contact iterate on the TET10 Hertz mesh.
///
/// The test (3D): the slave face's plane (its corners' normal n0 at their
/// centre, the auxiliary plane of the linear kernel), both faces' nodes
/// projected orthogonally onto it, and their bounding boxes in the plane
/// compared with a margin. The linear kernel projects orthogonally onto
/// this very plane; the sub-facet kernel of a curved face onto the plane of
/// each sub-facet, tilted from n0 by at most about 4 b / s (b: the largest
/// distance of a slave node from the plane, s: the face's size). A point at
/// height h above the plane lands at most h tan(theta) from its orthogonal
/// projection on a plane tilted by theta, so the margin is 0.1 of the two
/// faces' sizes (a curved face's edges bulge past its nodes) plus
/// (0.5 + 4 b / s) h, the largest h of both faces' nodes.
/// 2D pairs are never rejected: the 2D kernels project along the
/// interpolated nodal normals, which fan out widely at a corner (a master
/// behind a corner is reached from far aside), and 2D interfaces are small.
#include <algorithm>
#include <array>
#include <cmath>

#include "coulomb/contact/mortar/DualBasis.hpp"

namespace coulomb::contact {

/// @brief False only if no segment kernel can find an overlap of the slave
/// face (nodes `xs`, nodal normals `ns`) with the master face `xm`.
template <mesh::FaceType S, mesh::FaceType M>
bool projectionsMayOverlap(const FaceNodes<S, double>& xs, const FaceNodes<M, double>& xm) {
  if constexpr (FaceTraits<S>::line) {
    return true;
  } else {
    constexpr int corners = mesh::numCorners(S);
    using V = std::array<double, 3>;
    auto sub = [](const auto& a, const auto& b) { return V{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto cross = [](const V& a, const V& b) {
      return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    // The plane: centre c of the corners, unit normal n0, tangents t0, t1.
    V c{0.0, 0.0, 0.0};
    for (int a = 0; a < corners; ++a)
      for (int i = 0; i < 3; ++i) c[i] += xs[a][i] / corners;
    V n0 = corners == 3 ? cross(sub(xs[1], xs[0]), sub(xs[2], xs[0])) : cross(sub(xs[2], xs[0]), sub(xs[3], xs[1]));
    const double nNorm = std::sqrt(dot(n0, n0));
    if (!(nNorm > 0.0) || !std::isfinite(nNorm)) return true;
    for (double& v : n0) v /= nNorm;
    V t0 = sub(xs[1], xs[0]);
    const double tn = dot(t0, n0);
    for (int i = 0; i < 3; ++i) t0[i] -= tn * n0[i];
    const double tNorm = std::sqrt(dot(t0, t0));
    if (!(tNorm > 0.0)) return true;
    for (double& v : t0) v /= tNorm;
    const V t1 = cross(n0, t0);

    // Boxes on the plane, the slave's bulge and both faces' largest height.
    struct Box {
      double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, height = 0.0;
      double size() const { return std::max(hi[0] - lo[0], hi[1] - lo[1]); }
    };
    auto add = [&](Box& box, const auto& x) {
      const V r = sub(x, c);
      const double s[2] = {dot(r, t0), dot(r, t1)};
      for (int k = 0; k < 2; ++k) {
        box.lo[k] = std::min(box.lo[k], s[k]);
        box.hi[k] = std::max(box.hi[k], s[k]);
      }
      box.height = std::max(box.height, std::abs(dot(r, n0)));
    };
    Box slave, master;
    for (const auto& x : xs) add(slave, x);
    for (const auto& x : xm) add(master, x);
    if (!(slave.size() > 0.0)) return true;
    const double tilt = 0.5 + 4.0 * slave.height / slave.size();
    const double margin = 0.1 * (slave.size() + master.size()) + tilt * std::max(slave.height, master.height);
    if (!std::isfinite(margin)) return true;
    for (int k = 0; k < 2; ++k)
      if (master.lo[k] > slave.hi[k] + margin || slave.lo[k] > master.hi[k] + margin) return false;
    return true;
  }
}

}  // namespace coulomb::contact
