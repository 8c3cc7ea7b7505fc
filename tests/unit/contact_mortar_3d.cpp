// 3D mortar segment kernel (slave Tri3/Quad4 × master Tri3/Quad4 on the auxiliary
// plane): closed-form D, M and weighted gap, tiling and patch identities, and the
// Sacado derivatives against central finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "coulomb/contact/mortar/MortarSegment3D.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using V3 = std::array<double, 3>;
using Tri = FaceNodes<FaceType::Tri3, double>;
using Quad = FaceNodes<FaceType::Quad4, double>;

// A rigid motion x -> R x + c (R: rotation about a fixed oblique axis), applied to
// coordinates (with c) and to normals (without), so that the tests do not run on
// axis-aligned data only.
struct Motion {
  double R[3][3]{};
  V3 c{};
  Motion(double angle, V3 axis, V3 shift) : c(shift) {
    const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    for (double& a : axis) a /= n;
    const double co = std::cos(angle), si = std::sin(angle);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R[i][j] = (i == j ? co : 0.0) + (1.0 - co) * axis[i] * axis[j];
    R[0][1] -= si * axis[2];
    R[0][2] += si * axis[1];
    R[1][0] += si * axis[2];
    R[1][2] -= si * axis[0];
    R[2][0] -= si * axis[1];
    R[2][1] += si * axis[0];
  }
  V3 point(const V3& x) const { return add(vector(x), c); }
  V3 vector(const V3& x) const {
    V3 y{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[i] += R[i][j] * x[j];
    return y;
  }
  static V3 add(V3 a, const V3& b) {
    for (int i = 0; i < 3; ++i) a[i] += b[i];
    return a;
  }
  template <typename Nodes>
  Nodes points(Nodes x) const {
    for (auto& p : x) p = point(p);
    return x;
  }
  template <typename Nodes>
  Nodes vectors(Nodes x) const {
    for (auto& p : x) p = vector(p);
    return x;
  }
};
const Motion kIdentity(0.0, {0.0, 0.0, 1.0}, {0.0, 0.0, 0.0});
const Motion kOblique(0.9, {0.3, -0.5, 0.8}, {1.5, -0.7, 2.2});

template <FaceType F>
FaceNodes<F, double> constantNormals(const V3& n) {
  FaceNodes<F, double> ns{};
  for (auto& v : ns) v = n;
  return ns;
}

V3 unit(V3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

Quad rect(double x0, double y0, double x1, double y1, double z) {
  return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}};
}

// ---------------------------------------------------------------- matching faces

TEST(Mortar3D, MatchingTrianglesAtConstantGap) {
  for (const Motion* mo : {&kIdentity, &kOblique}) {
    const double g = 0.25;
    const Tri xs = mo->points(Tri{{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.0, 1.5, 0.0}}});
    // The master faces the slave: reversed node order, master node l on slave node 2 - l.
    const Tri xm = mo->points(Tri{{{0.0, 1.5, g}, {2.0, 0.0, g}, {0.0, 0.0, g}}});
    const auto ns = mo->vectors(constantNormals<FaceType::Tri3>({0.0, 0.0, 1.0}));
    const auto r = integrateSegment3D<FaceType::Tri3, FaceType::Tri3, double>(xs, ns, xm);
    ASSERT_TRUE(r.contributes);
    EXPECT_NEAR(r.area, 1.5, 1e-14);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(r.D[j], 0.5, 1e-14);  // int N_j dA = area/3
      EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-14);
      for (int l = 0; l < 3; ++l) EXPECT_NEAR(r.M[j][l], l == 2 - j ? r.D[j] : 0.0, 1e-14);
    }
  }
}

TEST(Mortar3D, MatchingQuadrilateralsAtConstantGap) {
  for (const Motion* mo : {&kIdentity, &kOblique}) {
    const double g = -0.05;  // penetration
    const Quad xs = mo->points(rect(0.0, 0.0, 2.0, 1.0, 0.0));
    const Quad xm = mo->points(Quad{{{0.0, 0.0, g}, {0.0, 1.0, g}, {2.0, 1.0, g}, {2.0, 0.0, g}}});
    const int masterOf[4] = {0, 3, 2, 1};  // master node on slave node j
    const auto ns = mo->vectors(constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}));
    const auto r = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(xs, ns, xm);
    ASSERT_TRUE(r.contributes);
    EXPECT_NEAR(r.area, 2.0, 1e-14);
    for (int j = 0; j < 4; ++j) {
      EXPECT_NEAR(r.D[j], 0.5, 1e-14);
      EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-14);
      for (int l = 0; l < 4; ++l) EXPECT_NEAR(r.M[j][l], l == masterOf[j] ? r.D[j] : 0.0, 1e-14);
    }
  }
}

// ------------------------------------------------------------- partial overlaps

TEST(Mortar3D, MasterCoveringHalfTheSlaveQuad) {
  // Slave: unit square (dA = dxi deta / 4), Phi_(a,b) = phi_a(xi) phi_b(eta) with
  // phi_-/+ = (1 -/+ 3 s)/2. The master [-0.5,0.5]x[-0.5,1.5] covers xi in [-1,0]:
  // D = (1/4) int_{-1}^0 phi_a int_{-1}^1 phi_b = 5/16 (xi = -1 nodes), -1/16 (xi = +1).
  const double g = 0.1;
  const auto r = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(
      rect(0.0, 0.0, 1.0, 1.0, 0.0), constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}),
      rect(-0.5, -0.5, 0.5, 1.5, g));
  ASSERT_TRUE(r.contributes);
  const double expected[4] = {5.0 / 16.0, -1.0 / 16.0, -1.0 / 16.0, 5.0 / 16.0};
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(r.D[j], expected[j], 1e-14);
    EXPECT_NEAR(r.gap[j], g * expected[j], 1e-14);
    EXPECT_NEAR(r.M[j][0] + r.M[j][1] + r.M[j][2] + r.M[j][3], r.D[j], 1e-14);
  }
  EXPECT_NEAR(r.area, 0.5, 1e-14);
  // sum_j M_jl = int_overlap N^2_l: master shape functions on x in [0,0.5], y in [0,1]:
  // int (0.5 - x) = 1/8, int (x + 0.5) = 3/8; int (1.5 - y)/2 = int (y + 0.5)/2 = 1/2.
  const double masterIntegral[4] = {1.0 / 16.0, 3.0 / 16.0, 3.0 / 16.0, 1.0 / 16.0};
  for (int l = 0; l < 4; ++l)
    EXPECT_NEAR(r.M[0][l] + r.M[1][l] + r.M[2][l] + r.M[3][l], masterIntegral[l], 1e-14);
}

TEST(Mortar3D, MasterTriangleInsideSlaveQuad) {
  const Tri xm{{{0.3, 0.2, 0.1}, {0.2, 0.8, 0.1}, {0.9, 0.5, 0.1}}};  // area 0.5 |(-0.1,0.6)x(0.6,0.3)| = 0.195
  const auto r = integrateSegment3D<FaceType::Quad4, FaceType::Tri3, double>(
      rect(0.0, 0.0, 1.0, 1.0, 0.0), constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}), xm);
  ASSERT_TRUE(r.contributes);
  EXPECT_EQ(r.polygonVertices, 3);
  EXPECT_NEAR(r.area, 0.195, 1e-14);
  EXPECT_NEAR(r.D[0] + r.D[1] + r.D[2] + r.D[3], 0.195, 1e-14);
  for (int l = 0; l < 3; ++l) EXPECT_NEAR(r.M[0][l] + r.M[1][l] + r.M[2][l] + r.M[3][l], 0.065, 1e-14);
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(r.M[j][0] + r.M[j][1] + r.M[j][2], r.D[j], 1e-14);
    EXPECT_NEAR(r.gap[j], 0.1 * r.D[j], 1e-14);
  }
}

// -------------------------------------------------------------------- tiling

// Master faces tiling the plane region [-0.3,1.3]x[-0.2,1.3] in a 2x2 grid offset
// from the slave; optionally each cell split into two triangles; slightly above.
std::vector<Quad> masterGrid(double z) {
  const double xs[3] = {-0.3, 0.45, 1.3}, ys[3] = {-0.2, 0.6, 1.3};
  std::vector<Quad> cells;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) cells.push_back(rect(xs[i], ys[j], xs[i + 1], ys[j + 1], z));
  return cells;
}

template <FaceType S>
void checkTiling(const FaceNodes<S, double>& xs, const FaceNodes<S, double>& ns, const Motion& mo, double gap,
                 double tolerance) {
  constexpr int n = FaceTraits<S>::nodes;
  std::array<double, n> D{}, G{}, Dq{}, Gq{};
  double area = 0.0;
  const FaceNodes<S, double> mxs = mo.points(xs), mns = mo.vectors(ns);
  for (const Quad& q : masterGrid(gap)) {
    const auto r = integrateSegment3D<S, FaceType::Quad4, double>(mxs, mns, mo.points(q));
    for (int j = 0; j < n; ++j) {
      D[j] += r.D[j];
      G[j] += r.gap[j];
      EXPECT_NEAR(r.M[j][0] + r.M[j][1] + r.M[j][2] + r.M[j][3], r.D[j], 1e-14);
    }
    area += r.area;
    // The same cell as two triangles (one with reversed orientation).
    for (const Tri& t : {Tri{{q[0], q[1], q[2]}}, Tri{{q[3], q[2], q[0]}}}) {
      const auto rt = integrateSegment3D<S, FaceType::Tri3, double>(mxs, mns, mo.points(t));
      for (int j = 0; j < n; ++j) {
        Dq[j] += rt.D[j];
        Gq[j] += rt.gap[j];
        EXPECT_NEAR(rt.M[j][0] + rt.M[j][1] + rt.M[j][2], rt.D[j], 1e-14);
      }
    }
  }
  const FaceMass<S, double> mass = faceMass<S, double>(mxs);
  double faceArea = 0.0;
  for (int j = 0; j < n; ++j) faceArea += mass.De[j];
  EXPECT_NEAR(area, faceArea, tolerance);
  for (int j = 0; j < n; ++j) {
    EXPECT_NEAR(D[j], mass.De[j], tolerance) << "node " << j;
    EXPECT_NEAR(Dq[j], mass.De[j], tolerance) << "node " << j;
  }
  if (ns[0] == ns[n - 1] && ns[0] == V3{0.0, 0.0, 1.0} && xs[0][2] == 0.0)
    for (int j = 0; j < n; ++j) {
      EXPECT_NEAR(G[j], gap * mass.De[j], tolerance);
      EXPECT_NEAR(Gq[j], gap * mass.De[j], tolerance);
    }
}

TEST(Mortar3D, MasterGridTilingSlaveQuadGivesFullD) {
  const Quad square = rect(0.0, 0.0, 1.0, 1.0, 0.0);
  checkTiling<FaceType::Quad4>(square, constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}), kIdentity, 0.2, 1e-14);
  checkTiling<FaceType::Quad4>(square, constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}), kOblique, 0.2, 1e-14);
  // A parallelogram (affine map: exact) with different nodal normals (D does not
  // depend on the normals).
  const Quad parallelogram{{{0.05, 0.1, 0.0}, {0.95, 0.2, 0.0}, {1.15, 1.1, 0.0}, {0.25, 1.0, 0.0}}};
  const Quad normals{{unit({0.1, 0.0, 1.0}), unit({0.0, 0.2, 1.0}), unit({-0.1, -0.1, 1.0}), unit({0.05, 0.0, 1.0})}};
  checkTiling<FaceType::Quad4>(parallelogram, normals, kOblique, 0.1, 1e-14);
}

TEST(Mortar3D, MasterGridTilingSlaveTriangleGivesFullD) {
  const Tri tri{{{0.1, 0.0, 0.0}, {1.2, 0.3, 0.0}, {0.2, 1.1, 0.0}}};
  checkTiling<FaceType::Tri3>(tri, constantNormals<FaceType::Tri3>({0.0, 0.0, 1.0}), kIdentity, 0.3, 1e-14);
  checkTiling<FaceType::Tri3>(tri, constantNormals<FaceType::Tri3>({0.0, 0.0, 1.0}), kOblique, 0.3, 1e-14);
}

TEST(Mortar3D, TilingOfDistortedQuadIsApproximate) {
  // Non-parallelogram plane quad: the inverse bilinear map is not polynomial, the
  // Gauss rule on the integration cells is approximate (documented limitation).
  const Quad distorted{{{0.0, 0.0, 0.0}, {1.1, 0.1, 0.0}, {0.9, 1.05, 0.0}, {0.05, 0.9, 0.0}}};
  checkTiling<FaceType::Quad4>(distorted, constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}), kOblique, 0.1, 5e-8);
  // Warped quad (nodes off a plane by +-0.04): projected overlap and measure ratio.
  const Quad warped{{{0.0, 0.0, 0.04}, {1.0, 0.0, -0.04}, {1.0, 1.0, 0.04}, {0.0, 1.0, -0.04}}};
  checkTiling<FaceType::Quad4>(warped, constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}), kIdentity, 0.2, 5e-8);
}

// ------------------------------------------------------------- tilted master

TEST(Mortar3D, TiltedMasterGivesLinearGapIntegral) {
  // Master plane z = g0 + a x + b y covering the slave, normals +z: g_n = g0 + a x + b y
  // is linear, hence interpolated exactly by the slave N_k, and by biorthogonality
  // g~_j = g(x_j) int N_j dA. A master triangle's N^2_l is affine too: M_jl = N^2_l(x_j) D_j.
  const double g0 = 0.1, a = 0.05, b = -0.08;
  auto onPlane = [&](double x, double y) { return V3{x, y, g0 + a * x + b * y}; };
  const Tri master{{onPlane(-1.0, -1.0), onPlane(3.0, -0.5), onPlane(-0.5, 3.0)}};
  // Barycentric coordinates of the master triangle (its shape functions) at (x, y).
  auto N2 = [&](double x, double y) {
    const double x0 = -1.0, y0 = -1.0, ax = 4.0, ay = 0.5, bx = 0.5, by = 4.0, det = ax * by - ay * bx;
    const double s = (by * (x - x0) - bx * (y - y0)) / det, t = (ax * (y - y0) - ay * (x - x0)) / det;
    return std::array<double, 3>{1.0 - s - t, s, t};
  };
  for (const Motion* mo : {&kIdentity, &kOblique}) {
    const Quad sq = rect(0.0, 0.0, 1.0, 1.0, 0.0);
    const auto rq = integrateSegment3D<FaceType::Quad4, FaceType::Tri3, double>(
        mo->points(sq), mo->vectors(constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0})), mo->points(master));
    ASSERT_TRUE(rq.contributes);
    for (int j = 0; j < 4; ++j) {
      EXPECT_NEAR(rq.D[j], 0.25, 1e-14);
      EXPECT_NEAR(rq.gap[j], 0.25 * (g0 + a * sq[j][0] + b * sq[j][1]), 1e-14);
      const auto N = N2(sq[j][0], sq[j][1]);
      for (int l = 0; l < 3; ++l) EXPECT_NEAR(rq.M[j][l], N[l] * rq.D[j], 1e-14);
    }
    const Tri tri{{{0.1, 0.0, 0.0}, {1.2, 0.3, 0.0}, {0.2, 1.1, 0.0}}};
    const double triArea = 0.5 * (1.1 * 1.1 - 0.3 * 0.1);
    const auto rt = integrateSegment3D<FaceType::Tri3, FaceType::Tri3, double>(
        mo->points(tri), mo->vectors(constantNormals<FaceType::Tri3>({0.0, 0.0, 1.0})), mo->points(master));
    ASSERT_TRUE(rt.contributes);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(rt.D[j], triArea / 3.0, 1e-14);
      EXPECT_NEAR(rt.gap[j], triArea / 3.0 * (g0 + a * tri[j][0] + b * tri[j][1]), 1e-14);
      const auto N = N2(tri[j][0], tri[j][1]);
      for (int l = 0; l < 3; ++l) EXPECT_NEAR(rt.M[j][l], N[l] * rt.D[j], 1e-14);
    }
  }
}

// ------------------------------------------------------------ no contribution

TEST(Mortar3D, DisjointTouchingOrEdgeOnFacesDoNotContribute) {
  const Quad slave = rect(0.0, 0.0, 1.0, 1.0, 0.0);
  const auto ns = constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0});
  auto contributes = [&](const Quad& m) {
    return integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(slave, ns, m).contributes;
  };
  EXPECT_FALSE(contributes(rect(1.5, 0.0, 2.5, 1.0, 0.1)));   // disjoint
  EXPECT_FALSE(contributes(rect(1.0, 0.0, 2.0, 1.0, 0.1)));   // sharing an edge
  EXPECT_FALSE(contributes(rect(1.0, 1.0, 2.0, 2.0, 0.1)));   // sharing a corner
  EXPECT_FALSE(contributes(Quad{{{0.2, 0.5, 0.0}, {0.8, 0.5, 0.0}, {0.8, 0.5, 1.0}, {0.2, 0.5, 1.0}}}));  // edge-on
  EXPECT_TRUE(contributes(rect(0.999, 0.0, 2.0, 1.0, 0.1)));  // a thin strip still counts
  const auto none = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(slave, ns, rect(3, 3, 4, 4, 0));
  EXPECT_EQ(none.D[0], 0.0);
  EXPECT_EQ(none.M[2][3], 0.0);
  EXPECT_EQ(none.gap[1], 0.0);
  EXPECT_EQ(none.polygonVertices, 0);
}

// ------------------------------------------------------------- derivatives

// Distorted, non-matching, tilted pairs with different nodal normals. In these
// pairs no projected node lies within 1.4e-2 of the other projected face's
// boundary (checked with an independent script), so the step h = 1e-6 does not
// change the clip topology; the vertex count of the clip polygon is checked for
// every perturbed evaluation.
Quad slaveQuad() { return {{{0.0, 0.0, 0.0}, {1.1, 0.05, 0.06}, {1.0, 0.95, -0.04}, {-0.05, 1.0, 0.02}}}; }
Tri slaveTri() { return {{{0.0, 0.0, 0.0}, {1.2, 0.1, 0.05}, {0.2, 1.0, -0.04}}}; }
Quad masterQuad() { return {{{0.35, -0.25, 0.2}, {0.3, 0.8, 0.12}, {1.3, 0.9, 0.25}, {1.25, 0.1, 0.3}}}; }
Tri masterTri() { return {{{0.3, -0.2, 0.12}, {0.45, 1.15, 0.1}, {1.4, 0.4, 0.2}}}; }
// Master faces turned by about 45 degrees against the slave: clip octagons/hexagons.
Quad turnedQuad() {
  return {{{1.2034, 0.5946, 0.1}, {0.4312, 1.2031, 0.14}, {-0.1236, 0.4081, 0.12}, {0.626, -0.1833, 0.08}}};
}
Tri turnedTri() { return {{{0.9669, 0.06, 0.1}, {0.43, 1.02, 0.14}, {-0.0896, 0.07, 0.12}}}; }
template <FaceType F>
FaceNodes<F, double> tiltedNormals() {
  const V3 all[4] = {unit({0.1, -0.05, 1.0}), unit({-0.08, 0.02, 1.0}), unit({0.03, 0.12, 1.0}),
                     unit({-0.02, -0.1, 1.0})};
  FaceNodes<F, double> n{};
  for (int a = 0; a < FaceTraits<F>::nodes; ++a) n[a] = all[a];
  return n;
}

template <FaceType S, FaceType Mf>
void checkDerivatives(const FaceNodes<S, double>& xs, const FaceNodes<Mf, double>& xm, int expectedVertices,
                      const Motion& mo = kIdentity) {
  constexpr int nS = FaceTraits<S>::nodes, nM = FaceTraits<Mf>::nodes, nI = segment3DInputs<S, Mf>;
  const FaceNodes<S, double> ns = mo.vectors(tiltedNormals<S>());
  const auto lin = linearizeSegment3D<S, Mf>(xs, ns, xm);
  const auto ref = integrateSegment3D<S, Mf, double>(xs, ns, xm);
  ASSERT_TRUE(lin.value.contributes);
  EXPECT_EQ(lin.value.polygonVertices, expectedVertices);
  for (int j = 0; j < nS; ++j) {
    EXPECT_DOUBLE_EQ(lin.value.D[j], ref.D[j]);
    EXPECT_DOUBLE_EQ(lin.value.gap[j], ref.gap[j]);
  }
  const double h = 1e-6;
  auto near = [](double ad, double fd) {
    return std::abs(ad - fd) <= 1e-6 * std::max(std::abs(ad), std::abs(fd)) + 1e-9;
  };
  int nonZero = 0;
  for (int i = 0; i < nI; ++i) {
    auto perturbed = [&](double step) {
      FaceNodes<S, double> pxs = xs, pns = ns;
      FaceNodes<Mf, double> pxm = xm;
      if (i < 3 * nS) pxs[i / 3][i % 3] += step;
      else if (i < 6 * nS) pns[(i - 3 * nS) / 3][i % 3] += step;
      else pxm[(i - 6 * nS) / 3][i % 3] += step;
      return integrateSegment3D<S, Mf, double>(pxs, pns, pxm);
    };
    const auto rp = perturbed(h), rm = perturbed(-h);
    ASSERT_EQ(rp.polygonVertices, expectedVertices);
    ASSERT_EQ(rm.polygonVertices, expectedVertices);
    for (int j = 0; j < nS; ++j) {
      EXPECT_PRED2(near, lin.dD[j][i], (rp.D[j] - rm.D[j]) / (2 * h)) << "dD[" << j << "]/dinput " << i;
      EXPECT_PRED2(near, lin.dGap[j][i], (rp.gap[j] - rm.gap[j]) / (2 * h)) << "dGap[" << j << "]/dinput " << i;
      nonZero += std::abs(lin.dGap[j][i]) > 1e-8;
      for (int l = 0; l < nM; ++l)
        EXPECT_PRED2(near, lin.dM[j][l][i], (rp.M[j][l] - rm.M[j][l]) / (2 * h))
            << "dM[" << j << "][" << l << "]/dinput " << i;
    }
    EXPECT_PRED2(near, lin.dArea[i], (rp.area - rm.area) / (2 * h)) << "dArea/dinput " << i;
  }
  EXPECT_GT(nonZero, nI);  // the gap depends on (almost) every input
}

TEST(Mortar3DLinearization, Quad4OnQuad4) {
  checkDerivatives<FaceType::Quad4, FaceType::Quad4>(slaveQuad(), masterQuad(), 4);
  checkDerivatives<FaceType::Quad4, FaceType::Quad4>(slaveQuad(), turnedQuad(), 8);
}
TEST(Mortar3DLinearization, Quad4OnTri3) {
  checkDerivatives<FaceType::Quad4, FaceType::Tri3>(slaveQuad(), masterTri(), 6);
  checkDerivatives<FaceType::Quad4, FaceType::Tri3>(slaveQuad(), turnedTri(), 5);
}
TEST(Mortar3DLinearization, Tri3OnQuad4) {
  checkDerivatives<FaceType::Tri3, FaceType::Quad4>(slaveTri(), masterQuad(), 4);
  checkDerivatives<FaceType::Tri3, FaceType::Quad4>(slaveTri(), turnedQuad(), 6);
}
TEST(Mortar3DLinearization, Tri3OnTri3) {
  checkDerivatives<FaceType::Tri3, FaceType::Tri3>(slaveTri(), masterTri(), 4);
  checkDerivatives<FaceType::Tri3, FaceType::Tri3>(slaveTri(), turnedTri(), 6);
}

// A master Quad4 whose projection is not convex (a dart, reflex vertex C
// = (0.3, 0.3)) is integrated as the two triangles either side of the
// diagonal through C: the overlap area is the analytic one.
Quad dart(double z0, double tilt) {
  auto at = [&](double x, double y) { return V3{x, y, z0 + tilt * (x + 0.5 * y)}; };
  return {{at(-1.0, -1.0), at(2.0, -1.0), at(0.3, 0.3), at(-1.0, 2.0)}};
}

double shoelace(const std::vector<std::array<double, 2>>& p) {
  double a = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& u = p[k];
    const auto& v = p[(k + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}

TEST(Mortar3D, NonConvexMasterQuadIsIntegratedAsTwoTriangles) {
  const double g = 0.05;
  const auto r = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(
      rect(0.0, 0.0, 1.0, 1.0, 0.0), constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0}), dart(g, 0.0));
  ASSERT_TRUE(r.contributes);
  // Overlap = square ∩ {x + y <= 1} minus square ∩ triangle BCD, the notch:
  // the polygon C, (9/13, 0), (1, 0), (0, 1), (0, 9/13).
  const double notch = shoelace({{0.3, 0.3}, {9.0 / 13.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.0, 9.0 / 13.0}});
  const double area = 0.5 - notch;  // = the quadrilateral (0,0), (9/13,0), C, (0,9/13)
  EXPECT_NEAR(area, 0.5 * 2 * (9.0 / 13.0) * 0.3, 1e-15);
  EXPECT_NEAR(r.area, area, 1e-13);
  double sumD = 0.0;
  for (int j = 0; j < 4; ++j) {
    sumD += r.D[j];
    EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-14);
    EXPECT_NEAR(r.M[j][0] + r.M[j][1] + r.M[j][2] + r.M[j][3], r.D[j], 1e-14);
  }
  EXPECT_NEAR(sumD, area, 1e-13);
  // By the symmetry x <-> y of the dart and the square: D of (1,0) equals D
  // of (0,1), and M of master nodes B and D swap.
  EXPECT_NEAR(r.D[1], r.D[3], 1e-14);
  EXPECT_NEAR(r.M[1][1], r.M[3][3], 1e-14);
}

// Even-odd point-in-polygon count on an m x m grid of the unit square: an
// estimate of |unit square ∩ Q| for a simple (not self-intersecting)
// quadrilateral Q, within about (perimeter + 4) / m.
double gridOverlap(const Quad& q, int m) {
  int inside = 0;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const double x = (i + 0.5) / m, y = (j + 0.5) / m;
      bool in = false;
      for (int a = 0, c = 3; a < 4; c = a++)
        if ((q[a][1] > y) != (q[c][1] > y) && x < (q[c][0] - q[a][0]) * (y - q[a][1]) / (q[c][1] - q[a][1]) + q[a][0])
          in = !in;
      inside += in;
    }
  return double(inside) / (double(m) * m);
}

bool selfIntersecting(const Quad& q) {
  int positive = 0;
  for (int k = 0; k < 4; ++k) {
    const V3 &a = q[k], &b = q[(k + 1) % 4], &c = q[(k + 2) % 4];
    positive += (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) > 0;
  }
  return positive == 2;
}

TEST(Mortar3D, RandomMasterQuadsAreIntegratedWithoutFailure) {
  // Random master quadrilaterals over the unit slave square, convex or not,
  // as a large predictor leaves them: before, 46 of 3000 such quads (not
  // self-intersecting) stopped the run with "the inversion of a Quad4 face
  // map did not converge". Every simple one must integrate, with the overlap
  // area of an independent grid count; a bow-tie that reaches the slave is a
  // geometry failure of the iterate (coulomb::Error, the step is cut back).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.5, 2.5);
  const auto ns = constantNormals<FaceType::Quad4>({0.0, 0.0, 1.0});
  int simple = 0, bowTies = 0;
  while (simple < 150) {
    Quad xm;
    for (auto& p : xm) p = {coordinate(random), coordinate(random), 0.05};
    if (selfIntersecting(xm)) {
      ++bowTies;
      try {
        const auto r = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(rect(0, 0, 1, 1, 0), ns, xm);
        EXPECT_FALSE(r.contributes);  // only a bow-tie that misses the slave returns
      } catch (const Error&) {
      }
      continue;
    }
    ++simple;
    const auto r = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(rect(0, 0, 1, 1, 0), ns, xm);
    EXPECT_NEAR(r.area, gridOverlap(xm, 400), 1e-2) << "quad " << simple;
    double sumD = 0.0;
    for (int j = 0; j < 4; ++j) {
      sumD += r.D[j];
      EXPECT_NEAR(r.M[j][0] + r.M[j][1] + r.M[j][2] + r.M[j][3], r.D[j], 1e-12);
    }
    EXPECT_NEAR(sumD, r.area, 1e-12);
  }
  EXPECT_GT(bowTies, 0);
}

TEST(Mortar3DLinearization, NonConvexMasterQuad) {
  // A tilted dart: the gap varies over the overlap; the derivatives of the
  // two-triangle integration against central differences.
  const auto probe = integrateSegment3D<FaceType::Quad4, FaceType::Quad4, double>(
      slaveQuad(), tiltedNormals<FaceType::Quad4>(), dart(0.1, 0.05));
  ASSERT_TRUE(probe.contributes);
  checkDerivatives<FaceType::Quad4, FaceType::Quad4>(slaveQuad(), dart(0.1, 0.05), probe.polygonVertices);
}

TEST(Mortar3DLinearization, ObliqueMasterTriangleInsideSlave) {
  // The whole master triangle inside the slave quad (all clip vertices are
  // projected master nodes), everything rotated to an oblique plane.
  const Tri inner{{{0.3, 0.2, 0.15}, {0.25, 0.8, 0.1}, {0.85, 0.45, 0.2}}};
  checkDerivatives<FaceType::Quad4, FaceType::Tri3>(kOblique.points(slaveQuad()), kOblique.points(inner), 3,
                                                     kOblique);
}

}  // namespace
}  // namespace coulomb::contact
