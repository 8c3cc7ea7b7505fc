// The quick reject before the segment kernels (OverlapBound.hpp): on random
// face pairs of every kind MortarPass integrates (2D Line2/Line3, 3D Tri3,
// Quad4, Tri6, Quad8, Quad9; curved quadratic faces, tilted nodal normals,
// masters from on top of the slave to three face sizes beside it, in front
// and behind), it must never reject a pair the kernel finds overlapping, and
// (3D) must reject most of those that lie beside the slave near its plane
// (else it saves nothing).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "coulomb/contact/mortar/MortarSegment2D.hpp"
#include "coulomb/contact/mortar/MortarSegment3D.hpp"
#include "coulomb/contact/mortar/MortarSegmentCurved2D.hpp"
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"
#include "coulomb/contact/mortar/OverlapBound.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;

/// Reference coordinates of a face's nodes (Exodus order: corners, then mid-side nodes, then the centre).
template <FaceType F>
std::array<double, 2> referenceNode(int a) {
  static const double line[3] = {-1.0, 1.0, 0.0};
  static const double tri[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  static const double quad[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
  if constexpr (FaceTraits<F>::line) return {line[a], 0.0};
  else if constexpr (F == FaceType::Tri3 || F == FaceType::Tri6) return {2.0 * tri[a][0] - 0.5, 2.0 * tri[a][1] - 0.5};
  else return {quad[a][0], quad[a][1]};
}

using V = std::array<double, 3>;

/// A random face of size `size` around `centre`, in the plane of the unit
/// vectors e1, e2 (normal e1 x e2), curved by `bulge` out of it, its
/// in-plane nodes jittered by 5 %; `reversed`: the node order of the other
/// orientation (corners mirrored).
template <FaceType F>
FaceNodes<F, double> randomFace(std::mt19937& rng, const V& centre, const V& e1, const V& e2, double size, double bulge,
                                bool reversed) {
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  const V n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  FaceNodes<F, double> x{};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a) {
    auto [xi, eta] = referenceNode<F>(a);
    if (reversed) eta = -eta;  // mirrored: the same nodes, the opposite orientation
    if (reversed && FaceTraits<F>::line) xi = -xi;
    const double u = xi + jitter(rng), v = eta + jitter(rng);
    const double z = bulge * (u * u + v * v);
    for (int c = 0; c < FaceTraits<F>::spaceDim; ++c) x[a][c] = centre[c] + 0.5 * size * (u * e1[c] + v * e2[c]) + size * z * n[c];
  }
  return x;
}

/// The kernel MortarPass uses for the pair: does it find an overlap?
template <FaceType S, FaceType M>
bool kernelOverlaps(const FaceNodes<S, double>& xs, const FaceNodes<S, double>& ns, const FaceNodes<M, double>& xm) {
  if constexpr (FaceTraits<S>::line) {
    if constexpr (S == FaceType::Line2 && M == FaceType::Line2) return integrateSegment2D<double>(xs, ns, xm, 1e-12).contributes;
    else return integrateCurvedSegment2D<S, M, double>(xs, ns, xm, 1e-12, false).contributes;
  } else if constexpr (S == FaceType::Tri3 || S == FaceType::Quad4) {
    if constexpr (M == FaceType::Tri3 || M == FaceType::Quad4) return integrateSegment3D<S, M, double>(xs, ns, xm, 1e-12).contributes;
    else return integrateQuadraticSegment3D<S, M, double>(xs, ns, xm, 1e-12).contributes;
  } else {
    return integrateQuadraticSegment3D<S, M, double>(xs, ns, xm, 1e-12).contributes;
  }
}

/// 3000 random pairs: (overlapping pairs, pairs beside the slave, of those rejected).
template <FaceType S, FaceType M>
void checkRandomPairs(unsigned seed) {
  constexpr bool twoD = FaceTraits<S>::line;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto normalized = [](V v) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return V{v[0] / l, v[1] / l, v[2] / l};
  };
  int overlapping = 0, beside = 0, rejectedBeside = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double size = 1.0;
    const double tilt = 0.3 * unit(rng);
    const V e1 = normalized({1.0, twoD ? tilt : 0.2 * unit(rng), twoD ? 0.0 : tilt});
    const V e2 = twoD ? V{0.0, 0.0, 1.0} : normalized({0.2 * unit(rng), 1.0, 0.3 * unit(rng)});
    const double bulge = (mesh::numNodes(S) > mesh::numCorners(S) ? 0.08 : 0.0) * unit(rng);
    const auto xs = randomFace<S>(rng, {0.0, 0.0, 0.0}, e1, e2, size, bulge, false);
    // Nodal normals: the face normal (up, +y in 2D, +z in 3D) tilted by up to 30 degrees.
    FaceNodes<S, double> ns{};
    for (auto& n : ns) {
      const V v = normalized({0.5 * unit(rng), twoD ? 1.0 : 0.5 * unit(rng), twoD ? 0.0 : 1.0});
      for (int c = 0; c < FaceTraits<S>::spaceDim; ++c) n[c] = v[c];
    }
    // The master: facing down, from on top of the slave to three sizes beside it.
    const double lateral = 3.0 * unit(rng), lateral2 = twoD ? 0.0 : 3.0 * unit(rng);
    const double height = 0.2 + 0.8 * unit(rng);
    const V centre = twoD ? V{lateral, height, 0.0} : V{lateral, lateral2, height};
    const double mBulge = (mesh::numNodes(M) > mesh::numCorners(M) ? 0.08 : 0.0) * unit(rng);
    const V m1 = normalized({1.0, twoD ? 0.2 * unit(rng) : 0.2 * unit(rng), twoD ? 0.0 : 0.2 * unit(rng)});
    const V m2 = twoD ? V{0.0, 0.0, 1.0} : normalized({0.2 * unit(rng), 1.0, 0.2 * unit(rng)});
    const auto xm = randomFace<M>(rng, centre, m1, m2, size * (0.5 + 0.5 * std::abs(unit(rng))), mBulge, true);

    const bool overlaps = kernelOverlaps<S, M>(xs, ns, xm);
    const bool may = projectionsMayOverlap<S, M>(xs, xm);
    if (overlaps) {
      ++overlapping;
      ASSERT_TRUE(may) << "trial " << trial << ": a pair the kernel integrates was rejected (master at " << lateral
                       << ", " << lateral2 << ", height " << height << "; xs0 " << xs[0][0] << "," << xs[0][1] << " xs1 "
                       << xs[1][0] << "," << xs[1][1] << " ns0 " << ns[0][0] << "," << ns[0][1] << " ns1 " << ns[1][0]
                       << "," << ns[1][1] << " xm0 " << xm[0][0] << "," << xm[0][1] << " xm1 " << xm[1][0] << ","
                       << xm[1][1] << ")";
    }
    if (std::max(std::abs(lateral), std::abs(lateral2)) > 2.5 && std::abs(height) < 0.3) {
      ++beside;
      rejectedBeside += may ? 0 : 1;
    }
  }
  EXPECT_GT(overlapping, 150) << "the random pairs must overlap often enough to test anything";
  if constexpr (twoD)
    EXPECT_EQ(rejectedBeside, 0) << "2D pairs are never rejected";
  else
    EXPECT_GT(rejectedBeside, 0.9 * beside) << "a master 2.5 face sizes beside the slave and near its plane should be rejected";
}

TEST(OverlapBound, NeverRejectsAnOverlapping2DPair) {
  checkRandomPairs<FaceType::Line2, FaceType::Line2>(1);
  checkRandomPairs<FaceType::Line3, FaceType::Line3>(2);
  checkRandomPairs<FaceType::Line3, FaceType::Line2>(3);
  checkRandomPairs<FaceType::Line2, FaceType::Line3>(4);
}

TEST(OverlapBound, NeverRejectsAnOverlappingLinear3DPair) {
  checkRandomPairs<FaceType::Quad4, FaceType::Quad4>(5);
  checkRandomPairs<FaceType::Tri3, FaceType::Quad4>(6);
  checkRandomPairs<FaceType::Quad4, FaceType::Tri3>(7);
}

TEST(OverlapBound, NeverRejectsAnOverlappingQuadratic3DPair) {
  checkRandomPairs<FaceType::Quad9, FaceType::Quad9>(8);
  checkRandomPairs<FaceType::Quad8, FaceType::Quad8>(9);
  checkRandomPairs<FaceType::Tri6, FaceType::Tri6>(10);
  checkRandomPairs<FaceType::Tri6, FaceType::Tri3>(11);
  checkRandomPairs<FaceType::Quad8, FaceType::Quad4>(12);
}

}  // namespace
}  // namespace coulomb::contact
