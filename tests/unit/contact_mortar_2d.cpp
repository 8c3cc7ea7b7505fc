// 2D mortar segment kernel (slave Line2 × master Line2): closed-form D, M and
// weighted gap, tiling and patch identities, and the Sacado derivatives against
// central finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coulomb/contact/mortar/MortarSegment2D.hpp"

namespace coulomb::contact {
namespace {

using L2 = Line2Nodes<double>;

L2 seg(double x0, double y0, double x1, double y1) { return {{{x0, y0}, {x1, y1}}}; }
const L2 kUp = seg(0.0, 1.0, 0.0, 1.0);  // both nodal normals +y
// Slave on the x axis from 0 to 2 (J = 1: dA = dxi, x = 1 + xi), normals +y.
const L2 kSlave = seg(0.0, 0.0, 2.0, 0.0);

std::array<double, 2> unitAt(double angle) { return {-std::sin(angle), std::cos(angle)}; }

// Closed forms of the dual basis of a Line2: Phi_0 = (1 - 3 xi)/2, Phi_1 = (1 + 3 xi)/2.
// int_a^b Phi_0 = [xi/2 - 3 xi^2/4]_a^b, int_a^b Phi_1 = [xi/2 + 3 xi^2/4]_a^b.
double intPhi(int j, double a, double b) {
  const double s = j == 0 ? -1.0 : 1.0;
  auto F = [s](double x) { return 0.5 * x + s * 0.75 * x * x; };
  return F(b) - F(a);
}

TEST(Mortar2D, MatchingParallelSegments) {
  const double g = 0.3;
  const auto r = integrateSegment2D<double>(kSlave, kUp, seg(2.0, g, 0.0, g));
  ASSERT_TRUE(r.contributes);
  // D_j = int Phi_j dA = int N_j dA = L/2; M = D on the matching nodes (master
  // node 1 sits on slave node 0); g~_j = g D_j.
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(r.D[j], 1.0, 1e-14);
    EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-14);
    EXPECT_NEAR(r.M[j][1 - j], r.D[j], 1e-14);
    EXPECT_NEAR(r.M[j][j], 0.0, 1e-14);
  }
  EXPECT_NEAR(r.length, 2.0, 1e-14);
  EXPECT_NEAR(r.slaveInterval[0], -1.0, 1e-15);
  EXPECT_NEAR(r.slaveInterval[1], 1.0, 1e-15);
}

TEST(Mortar2D, PenetrationGivesNegativeGap) {
  const auto r = integrateSegment2D<double>(kSlave, kUp, seg(2.0, -0.1, 0.0, -0.1));
  ASSERT_TRUE(r.contributes);
  EXPECT_NEAR(r.gap[0], -0.1, 1e-14);
  EXPECT_NEAR(r.gap[1], -0.1, 1e-14);
}

TEST(Mortar2D, MasterCoveringHalfTheSlave) {
  const double g = 0.2;
  // Master from x = 1 (node 0) to x = 0 (node 1): slave xi in [-1, 0].
  const auto r = integrateSegment2D<double>(kSlave, kUp, seg(1.0, g, 0.0, g));
  ASSERT_TRUE(r.contributes);
  EXPECT_NEAR(r.D[0], 5.0 / 4.0, 1e-14);  // int_{-1}^0 (1 - 3 xi)/2
  EXPECT_NEAR(r.D[1], -1.0 / 4.0, 1e-14);
  EXPECT_NEAR(r.D[0], intPhi(0, -1.0, 0.0), 1e-14);
  // N^2_0 = x = 1 + xi, N^2_1 = -xi on the overlap:
  // M_00 = int_{-1}^0 (1 - 3xi)(1 + xi)/2 = 1/2, M_10 = int (1 + 3xi)(1 + xi)/2 = 0,
  // M_01 = int (1 - 3xi)(-xi)/2 = 3/4, M_11 = int (1 + 3xi)(-xi)/2 = -1/4.
  EXPECT_NEAR(r.M[0][0], 0.5, 1e-14);
  EXPECT_NEAR(r.M[0][1], 0.75, 1e-14);
  EXPECT_NEAR(r.M[1][0], 0.0, 1e-14);
  EXPECT_NEAR(r.M[1][1], -0.25, 1e-14);
  EXPECT_NEAR(r.gap[0], g * 5.0 / 4.0, 1e-14);
  EXPECT_NEAR(r.gap[1], -g / 4.0, 1e-14);
  EXPECT_NEAR(r.length, 1.0, 1e-14);
  // Patch: sum_j M_jl = int N^2_l over the master (length 1) = 1/2.
  EXPECT_NEAR(r.M[0][0] + r.M[1][0], 0.5, 1e-14);
  EXPECT_NEAR(r.M[0][1] + r.M[1][1], 0.5, 1e-14);
}

TEST(Mortar2D, MastersTilingTheSlaveGiveTheFullD) {
  // Three master segments sharing nodes, the outer ones overhanging; slave nodal
  // normals tilted differently (the normal field is not constant): the projected
  // master nodes shared by neighbouring segments coincide, so the overlaps tile [-1, 1].
  const L2 normals{{unitAt(0.2), unitAt(-0.15)}};
  const std::vector<L2> masters{seg(0.6, 0.3, -0.5, 0.25), seg(1.3, 0.32, 0.6, 0.3), seg(2.7, 0.2, 1.3, 0.32)};
  std::array<double, 2> D{}, gapSum{};
  double length = 0.0;
  for (const L2& m : masters) {
    const auto r = integrateSegment2D<double>(kSlave, normals, m);
    ASSERT_TRUE(r.contributes);
    for (int j = 0; j < 2; ++j) {
      D[j] += r.D[j];
      EXPECT_NEAR(r.M[j][0] + r.M[j][1], r.D[j], 1e-14);
    }
    length += r.length;
  }
  EXPECT_NEAR(D[0], 1.0, 1e-14);  // int_{-1}^{1} Phi_j = int N_j = 1
  EXPECT_NEAR(D[1], 1.0, 1e-14);
  EXPECT_NEAR(length, 2.0, 1e-14);

  // Constant normals and a constant gap: sum of g~_j = g int N_j.
  const double g = 0.05;
  for (const L2& m : {seg(0.6, g, -0.5, g), seg(1.3, g, 0.6, g), seg(2.7, g, 1.3, g)}) {
    const auto r = integrateSegment2D<double>(kSlave, kUp, m);
    for (int j = 0; j < 2; ++j) gapSum[j] += r.gap[j];
  }
  EXPECT_NEAR(gapSum[0], g, 1e-14);
  EXPECT_NEAR(gapSum[1], g, 1e-14);
}

TEST(Mortar2D, TiltedMasterGivesLinearGapIntegral) {
  // Master on the line y = g0 + s x, from x = 2.5 (node 0) to x = -0.5 (node 1).
  const double g0 = 0.1, s = 0.15;
  const auto r = integrateSegment2D<double>(kSlave, kUp, seg(2.5, g0 + 2.5 * s, -0.5, g0 - 0.5 * s));
  ASSERT_TRUE(r.contributes);
  // g_n(x) = g0 + s x, x = 1 + xi: g~_j = int Phi_j (g0 + s + s xi) dxi with
  // int Phi_0 = int Phi_1 = 1, int Phi_0 xi = -1, int Phi_1 xi = 1.
  EXPECT_NEAR(r.gap[0], g0 + s - s, 1e-14);
  EXPECT_NEAR(r.gap[1], g0 + s + s, 1e-14);
  // A linear master function restricted to the slave is interpolated exactly by
  // N_k, so M_jl = N^2_l(x_j) D_j with N^2_0(x) = (x + 0.5)/3.
  EXPECT_NEAR(r.M[0][0], 0.5 / 3.0, 1e-14);
  EXPECT_NEAR(r.M[0][1], 2.5 / 3.0, 1e-14);
  EXPECT_NEAR(r.M[1][0], 2.5 / 3.0, 1e-14);
  EXPECT_NEAR(r.M[1][1], 0.5 / 3.0, 1e-14);
}

TEST(Mortar2D, PartialOverlapPatchIdentities) {
  // Master strictly inside the slave, parallel, constant normals: both ends are
  // projected master nodes at x = 0.4 and 1.5 (xi = -0.6, 0.5).
  const auto r = integrateSegment2D<double>(kSlave, kUp, seg(1.5, 0.2, 0.4, 0.2));
  ASSERT_TRUE(r.contributes);
  EXPECT_NEAR(r.D[0], intPhi(0, -0.6, 0.5), 1e-14);
  EXPECT_NEAR(r.D[1], intPhi(1, -0.6, 0.5), 1e-14);
  EXPECT_NEAR(r.D[0] + r.D[1], 1.1, 1e-14);  // overlap length
  EXPECT_NEAR(r.length, 1.1, 1e-14);
  for (int l = 0; l < 2; ++l) EXPECT_NEAR(r.M[0][l] + r.M[1][l], 0.55, 1e-14);  // int N^2_l = 1.1/2
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(r.M[j][0] + r.M[j][1], r.D[j], 1e-14);
}

TEST(Mortar2D, DisjointOrTouchingSegmentsDoNotContribute) {
  const auto apart = integrateSegment2D<double>(kSlave, kUp, seg(3.0, 0.1, 2.4, 0.1));
  EXPECT_FALSE(apart.contributes);
  EXPECT_EQ(apart.D[0], 0.0);
  EXPECT_EQ(apart.M[1][1], 0.0);
  EXPECT_EQ(apart.gap[0], 0.0);
  const auto touching = integrateSegment2D<double>(kSlave, kUp, seg(3.0, 0.1, 2.0, 0.1));
  EXPECT_FALSE(touching.contributes);
}

// A generic configuration: slave not axis-aligned, different nodal normals,
// master partially overlapping and tilted.
struct Config {
  L2 xs, ns, xm;
};

Config tilted(const L2& xm) {
  const L2 xs = seg(0.1, -0.05, 2.0, 0.12);
  const double base = std::atan2(0.17, 1.9);
  return {xs, L2{{unitAt(base + 0.12), unitAt(base - 0.08)}}, xm};
}

TEST(Mortar2D, InvariantUnderRigidMotion) {
  const Config c = tilted(seg(1.3, 0.3, -0.4, 0.25));
  const double a = 0.7, tx = -1.2, ty = 3.4;
  auto rot = [&](const std::array<double, 2>& p, bool translate) {
    return std::array<double, 2>{std::cos(a) * p[0] - std::sin(a) * p[1] + (translate ? tx : 0.0),
                                 std::sin(a) * p[0] + std::cos(a) * p[1] + (translate ? ty : 0.0)};
  };
  const L2 xs{{rot(c.xs[0], true), rot(c.xs[1], true)}}, ns{{rot(c.ns[0], false), rot(c.ns[1], false)}},
      xm{{rot(c.xm[0], true), rot(c.xm[1], true)}};
  const auto r0 = integrateSegment2D<double>(c.xs, c.ns, c.xm);
  const auto r1 = integrateSegment2D<double>(xs, ns, xm);
  ASSERT_TRUE(r0.contributes && r1.contributes);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(r1.D[j], r0.D[j], 1e-13);
    EXPECT_NEAR(r1.gap[j], r0.gap[j], 1e-13);
    for (int l = 0; l < 2; ++l) EXPECT_NEAR(r1.M[j][l], r0.M[j][l], 1e-13);
  }
}

// Central differences of the double kernel against the Sacado derivatives, for
// every input. The configurations are away from topology changes (no master
// node projects within 1e-2 of a slave node), so the step h = 1e-6 keeps the
// overlap topology.
void checkDerivatives(const Config& c, bool axisymmetric = false) {
  const double tol = 1e-10;
  const MortarSegment2DLinearization lin = linearizeSegment2D(c.xs, c.ns, c.xm, tol, axisymmetric);
  const auto ref = integrateSegment2D<double>(c.xs, c.ns, c.xm, tol, axisymmetric);
  ASSERT_TRUE(lin.value.contributes);
  for (int j = 0; j < 2; ++j) {
    EXPECT_DOUBLE_EQ(lin.value.D[j], ref.D[j]);
    EXPECT_DOUBLE_EQ(lin.value.gap[j], ref.gap[j]);
  }
  const double h = 1e-6;
  auto near = [](double ad, double fd) { return std::abs(ad - fd) <= 1e-6 * std::max(std::abs(ad), std::abs(fd)) + 1e-9; };
  int nonZero = 0;
  for (int i = 0; i < kSegment2DInputs; ++i) {
    Config p = c, m = c;
    L2* arrays[2][3] = {{&p.xs, &p.ns, &p.xm}, {&m.xs, &m.ns, &m.xm}};
    (*arrays[0][i / 4])[(i % 4) / 2][i % 2] += h;
    (*arrays[1][i / 4])[(i % 4) / 2][i % 2] -= h;
    const auto rp = integrateSegment2D<double>(p.xs, p.ns, p.xm, tol, axisymmetric);
    const auto rm = integrateSegment2D<double>(m.xs, m.ns, m.xm, tol, axisymmetric);
    ASSERT_TRUE(rp.contributes && rm.contributes);
    for (int j = 0; j < 2; ++j) {
      const double fdD = (rp.D[j] - rm.D[j]) / (2 * h), fdG = (rp.gap[j] - rm.gap[j]) / (2 * h);
      EXPECT_PRED2(near, lin.dD[j][i], fdD) << "dD[" << j << "]/dinput " << i;
      EXPECT_PRED2(near, lin.dGap[j][i], fdG) << "dGap[" << j << "]/dinput " << i;
      nonZero += std::abs(lin.dGap[j][i]) > 1e-8;
      for (int l = 0; l < 2; ++l) {
        const double fdM = (rp.M[j][l] - rm.M[j][l]) / (2 * h);
        EXPECT_PRED2(near, lin.dM[j][l][i], fdM) << "dM[" << j << "][" << l << "]/dinput " << i;
      }
    }
    EXPECT_PRED2(near, lin.dLength[i], (rp.length - rm.length) / (2 * h)) << "dLength/dinput " << i;
  }
  EXPECT_GT(nonZero, 12);  // the gap depends on (almost) every input
}

TEST(Mortar2DLinearization, OneEndProjectedMasterNode) { checkDerivatives(tilted(seg(1.3, 0.3, -0.4, 0.25))); }

TEST(Mortar2DLinearization, BothEndsProjectedMasterNodes) { checkDerivatives(tilted(seg(1.5, 0.2, 0.4, 0.35))); }

TEST(Mortar2DLinearization, MasterCoveringTheSlave) { checkDerivatives(tilted(seg(2.6, 0.4, -0.7, 0.05))); }

TEST(Mortar2DLinearization, PenetratingMaster) { checkDerivatives(tilted(seg(1.7, -0.1, 0.3, 0.15))); }

// Axisymmetric (x = r): the same configurations, the 2 pi r weight and the
// dual basis of the ring measure differentiated too (the slave lies at r 0.1 to 2).
TEST(Mortar2DLinearization, AxisymmetricRings) {
  checkDerivatives(tilted(seg(1.3, 0.3, -0.4, 0.25)), true);
  checkDerivatives(tilted(seg(2.6, 0.4, -0.7, 0.05)), true);
}

// The ring's dual basis is biorthogonal in the measure r ds: a master covering
// the slave (a ring from r = 1 to 3, gap g) gives D_j = 2 pi \int N_j r ds,
// M = diag(D) for the matching master, g~_j = g D_j, and sum_l M_jl = D_j.
TEST(Mortar2D, AxisymmetricDualBasisIsBiorthogonalInTheRingMeasure) {
  const double g = 0.05, twoPi = 2 * M_PI;
  const L2 xs = seg(3.0, 0.0, 1.0, 0.0);  // slave normal (0, 1) towards the master above
  const auto r = integrateSegment2D<double>(xs, kUp, seg(3.0, g, 1.0, g), 1e-10, true);
  ASSERT_TRUE(r.contributes);
  const double D[2] = {twoPi * 2.0 * (2 * 3.0 + 1.0) / 6.0, twoPi * 2.0 * (3.0 + 2 * 1.0) / 6.0};
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(r.D[j], D[j], 1e-12 * D[j]);
    EXPECT_NEAR(r.gap[j], g * D[j], 1e-12 * D[j]);
    EXPECT_NEAR(r.M[j][j], D[j], 1e-12 * D[j]);
    EXPECT_NEAR(r.M[j][1 - j], 0.0, 1e-12 * D[j]);
  }
  // A master half as long: sum_l M_jl = D_j still (partition of unity).
  const auto half = integrateSegment2D<double>(xs, kUp, seg(2.0, g, 1.0, g), 1e-10, true);
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(half.M[j][0] + half.M[j][1], half.D[j], 1e-12 * D[j]);
  // Equal radii would be the plane basis: the coefficients.
  const auto A = axisymmetricDual<double>(seg(2.0, 0.0, 2.0, 1.0));
  EXPECT_NEAR(A[0][0], 2.0, 1e-14);
  EXPECT_NEAR(A[0][1], -1.0, 1e-14);
}

}  // namespace
}  // namespace coulomb::contact
