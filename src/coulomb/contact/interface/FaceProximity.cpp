/// @file FaceProximity.cpp
/// @brief Point-to-face distance, signed normal distance and footprint test (see the header).
#include "coulomb/contact/interface/FaceProximity.hpp"

#include <algorithm>
#include <cmath>

namespace coulomb::contact {
namespace {

using Vec = std::array<double, 3>;

Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Distance from p to the segment [a, b].
double segmentDistance(const Vec& a, const Vec& b, const Vec& p) {
  const Vec ab = minus(b, a), ap = minus(p, a);
  const double length2 = dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(dot(ap, ab) / length2, 0.0, 1.0) : 0.0;
  const Vec q = {a[0] + t * ab[0] - p[0], a[1] + t * ab[1] - p[1], a[2] + t * ab[2] - p[2]};
  return std::sqrt(dot(q, q));
}

}  // namespace

bool faceOutwardNormal(int dim, int numNodes, const std::array<std::array<double, 3>, 4>& nodes, Vec& normal) {
  Vec x[4];
  for (int a = 0; a < numNodes; ++a) x[a] = {nodes[a][0], nodes[a][1], dim == 3 ? nodes[a][2] : 0.0};
  normal = {0.0, 0.0, 0.0};
  if (dim == 2) {
    const Vec t = minus(x[1], x[0]);
    normal = {t[1], -t[0], 0.0};
  } else {
    // Newell's normal: twice the area vector of the polygon.
    for (int a = 0; a < numNodes; ++a) {
      const Vec area = cross(x[a], x[(a + 1) % numNodes]);
      for (int c = 0; c < 3; ++c) normal[c] += area[c];
    }
  }
  const double length = std::sqrt(dot(normal, normal));
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  for (double& c : normal) c /= length;
  return true;
}

FaceProximity faceProximity(int dim, int numNodes, const std::array<std::array<double, 3>, 4>& nodes,
                            const std::array<double, 3>& p) {
  FaceProximity result;
  Vec x[4];
  for (int a = 0; a < numNodes; ++a) x[a] = {nodes[a][0], nodes[a][1], dim == 3 ? nodes[a][2] : 0.0};
  const Vec q = {p[0], p[1], dim == 3 ? p[2] : 0.0};
  // Distance to the boundary (2D: to the segment itself).
  double boundary = segmentDistance(x[0], x[1 % numNodes], q);
  for (int a = 1; a < numNodes && dim == 3; ++a)
    boundary = std::min(boundary, segmentDistance(x[a], x[(a + 1) % numNodes], q));
  result.distance = boundary;

  // The plane through x[0] (2D) or the node average (3D).
  Vec normal{0.0, 0.0, 0.0};
  Vec origin = x[0];
  if (dim == 3) {
    origin = {0.0, 0.0, 0.0};
    for (int a = 0; a < numNodes; ++a)
      for (int c = 0; c < 3; ++c) origin[c] += x[a][c] / numNodes;
  }
  if (!faceOutwardNormal(dim, numNodes, nodes, normal)) return result;
  result.normalDistance = dot(minus(q, origin), normal);

  if (dim == 2) {
    const Vec t = minus(x[1], x[0]);
    const double s = dot(minus(q, x[0]), t) / dot(t, t);
    result.overFace = s >= 0.0 && s <= 1.0;
  } else {
    // The projection is on the face when it is on the inner side of every edge
    // (counter-clockwise seen from the outward normal).
    const Vec projected = {q[0] - result.normalDistance * normal[0], q[1] - result.normalDistance * normal[1],
                           q[2] - result.normalDistance * normal[2]};
    result.overFace = true;
    for (int a = 0; a < numNodes; ++a) {
      const Vec edge = minus(x[(a + 1) % numNodes], x[a]);
      if (dot(cross(edge, minus(projected, x[a])), normal) < -1e-12 * dot(edge, edge)) result.overFace = false;
    }
  }
  if (result.overFace) result.distance = std::abs(result.normalDistance);
  return result;
}

}  // namespace coulomb::contact
