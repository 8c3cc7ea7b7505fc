// 2D mortar segments with quadratic Line3 faces (issue 18, item 2;
// MortarSegmentCurved2D.hpp): the Line3 dual basis (biorthogonal, D > 0),
// the general kernel against the closed-form Line2 one, patch identities on
// straight Line3 faces, and the Sacado derivatives against central finite
// differences on curved faces.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "coulomb/contact/mortar/MortarSegment2D.hpp"
#include "coulomb/contact/mortar/MortarSegmentCurved2D.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using L2 = FaceNodes<FaceType::Line2, double>;
using L3 = FaceNodes<FaceType::Line3, double>;

/// A Line3 from a to b whose mid node is moved off the chord by `bow`
/// (along the left normal of a -> b) and along it by `shift`.
L3 line3(std::array<double, 2> a, std::array<double, 2> b, double bow = 0.0, double shift = 0.0) {
  const std::array<double, 2> d{b[0] - a[0], b[1] - a[1]};
  const double L = std::hypot(d[0], d[1]);
  const std::array<double, 2> t{d[0] / L, d[1] / L}, n{-t[1], t[0]};
  return {{a, b, {0.5 * (a[0] + b[0]) + bow * n[0] + shift * t[0], 0.5 * (a[1] + b[1]) + bow * n[1] + shift * t[1]}}};
}

L3 upNormals() { return {{{0.0, 1.0}, {0.0, 1.0}, {0.0, 1.0}}}; }

// The Line3 dual basis: int Phi_j N_k dA = delta_jk int N_k dA (with the rule
// of lineMass), sum_j Phi_j = 1, and D_e = (h/6, h/6, 2h/3) > 0 on a straight
// face; a bowed face keeps every D_e positive.
TEST(Mortar2DCurved, Line3DualBasisIsBiorthogonalWithPositiveD) {
  for (const double bow : {0.0, 0.3}) {
    SCOPED_TRACE(bow);
    const L3 x = line3({0.0, 0.0}, {2.0, 0.5}, bow, 0.1 * bow);
    const auto mass = lineMass<FaceType::Line3, double>(x, false);
    const double h = std::hypot(2.0, 0.5);
    if (bow == 0.0) {
      EXPECT_NEAR(mass.De[0], h / 6, 1e-14);
      EXPECT_NEAR(mass.De[1], h / 6, 1e-14);
      EXPECT_NEAR(mass.De[2], 2 * h / 3, 1e-14);
    }
    for (double d : mass.De) EXPECT_GT(d, 0.0);
    // Biorthogonality through the integrals: A M_e = D_e (A from a fresh
    // segment over the whole face: D_j of a covering master is int Phi_j = D_e[j]).
    const L3 master = line3({2.5, 3.0}, {-0.5, 3.0});
    const auto seg = integrateCurvedSegment2D<FaceType::Line3, FaceType::Line3, double>(x, upNormals(), master, 1e-12,
                                                                                         false);
    ASSERT_TRUE(seg.contributes);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(seg.D[j], mass.De[j], 1e-12 * h) << j;
  }
}

// With Line2 faces the general kernel is the closed-form one (the same
// projections and rule): values and derivatives to round-off, tilted
// normals, partial overlap.
TEST(Mortar2DCurved, Line2FacesGiveTheClosedFormKernel) {
  const L2 xs{{{0.0, 0.0}, {2.0, 0.2}}};
  const L2 ns{{{-std::sin(0.1), std::cos(0.1)}, {-std::sin(-0.15), std::cos(-0.15)}}};
  const L2 xm{{{1.5, 0.3}, {-0.4, 0.25}}};
  const auto closed = linearizeSegment2D(xs, ns, xm);
  const auto general = linearizeCurvedSegment2D<FaceType::Line2, FaceType::Line2>(xs, ns, xm, 1e-10, false);
  ASSERT_TRUE(closed.value.contributes);
  ASSERT_TRUE(general.value.contributes);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(general.value.D[j], closed.value.D[j], 1e-13);
    EXPECT_NEAR(general.value.gap[j], closed.value.gap[j], 1e-13);
    for (int l = 0; l < 2; ++l) EXPECT_NEAR(general.value.M[j][l], closed.value.M[j][l], 1e-13);
    for (int i = 0; i < kSegment2DInputs; ++i) {
      EXPECT_NEAR(general.dD[j][i], closed.dD[j][i], 1e-12);
      EXPECT_NEAR(general.dGap[j][i], closed.dGap[j][i], 1e-12);
      for (int l = 0; l < 2; ++l) EXPECT_NEAR(general.dM[j][l][i], closed.dM[j][l][i], 1e-12);
    }
  }
}

// Straight Line3 faces at a uniform gap g, the master covering part of the
// slave: sum_l M_jl = D_j (a rigid translation has no weighted relative
// displacement), g~_j = g D_j, sum_j D_j = the overlap length.
TEST(Mortar2DCurved, StraightLine3PatchIdentities) {
  const double g = 0.2;
  const L3 xs = line3({0.0, 0.0}, {2.0, 0.0});
  for (const bool quadraticMaster : {true, false}) {
    SCOPED_TRACE(quadraticMaster ? "Line3 master" : "Line2 master");
    auto check = [&](const auto& r) {
      ASSERT_TRUE(r.contributes);
      double sumD = 0;
      for (int j = 0; j < 3; ++j) {
        double sumM = 0;
        for (double m : r.M[j]) sumM += m;
        EXPECT_NEAR(sumM, r.D[j], 1e-13);
        EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-13);
        sumD += r.D[j];
      }
      EXPECT_NEAR(sumD, 1.3, 1e-13);  // master over x in [0.7, 2]
      EXPECT_NEAR(r.length, 1.3, 1e-13);
    };
    if (quadraticMaster)
      check(integrateCurvedSegment2D<FaceType::Line3, FaceType::Line3, double>(xs, upNormals(),
                                                                               line3({2.5, g}, {0.7, g}), 1e-12, false));
    else
      check(integrateCurvedSegment2D<FaceType::Line3, FaceType::Line2, double>(
          xs, upNormals(), L2{{{2.5, g}, {0.7, g}}}, 1e-12, false));
  }
}

// A master seven times as long as the slave face covers it (tests/zoo
// dissimilar_patch_2d at order 2: base faces of 1/7, punch faces of 1/22):
// its far corner projects to s ~ 5 on the slave, where the projection's
// Newton steps stall at ~1e-13, above a round-off criterion of 1e-14 (1 + |s|).
// The pair must still count in full: D_j = int N_j, the M rows sum to D_j.
TEST(Mortar2DCurved, LongMasterCoveringTheSlaveCountsInFull) {
  const L3 xs = line3({0.86363636363636365, 0.5}, {0.90909090909090906, 0.5});
  const L3 xm = line3({1.0, 0.5}, {0.8571428571428571, 0.5});
  const auto mass = lineMass<FaceType::Line3, double>(xs, false);
  const auto r = integrateCurvedSegment2D<FaceType::Line3, FaceType::Line3, double>(xs, upNormals(), xm, 1e-12, false);
  ASSERT_TRUE(r.contributes);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(r.D[j], mass.De[j], 1e-15) << j;
    double sumM = 0;
    for (double m : r.M[j]) sumM += m;
    EXPECT_NEAR(sumM, r.D[j], 1e-15) << j;
    EXPECT_NEAR(r.gap[j], 0.0, 1e-15) << j;
  }
  const auto lin = linearizeCurvedSegment2D<FaceType::Line3, FaceType::Line3>(xs, upNormals(), xm, 1e-12, false);
  ASSERT_TRUE(lin.value.contributes);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(lin.value.D[j], mass.De[j], 1e-15) << j;
}

/// Central differences of every output against every input of a curved
/// configuration (h = 1e-6): the Sacado derivatives match to 1e-7.
template <FaceType S, FaceType Mf>
void checkDerivatives(const FaceNodes<S, double>& xs, const FaceNodes<S, double>& ns, const FaceNodes<Mf, double>& xm,
                      bool axisymmetric) {
  using Lin = MortarSegmentCurved2DLinearization<S, Mf>;
  const Lin lin = linearizeCurvedSegment2D<S, Mf>(xs, ns, xm, 1e-10, axisymmetric);
  ASSERT_TRUE(lin.value.contributes);
  auto input = [](FaceNodes<S, double>& a, FaceNodes<S, double>& b, FaceNodes<Mf, double>& c, int i) -> double& {
    if (i < 2 * Lin::nS) return a[i / 2][i % 2];
    if (i < 4 * Lin::nS) return b[(i - 2 * Lin::nS) / 2][i % 2];
    return c[(i - 4 * Lin::nS) / 2][i % 2];
  };
  const double h = 1e-6;
  for (int i = 0; i < Lin::N; ++i) {
    auto a = xs, b = ns;
    auto c = xm;
    input(a, b, c, i) += h;
    const auto plus = integrateCurvedSegment2D<S, Mf, double>(a, b, c, 1e-10, axisymmetric);
    input(a, b, c, i) -= 2 * h;
    const auto minus = integrateCurvedSegment2D<S, Mf, double>(a, b, c, 1e-10, axisymmetric);
    for (int j = 0; j < Lin::nS; ++j) {
      EXPECT_NEAR((plus.D[j] - minus.D[j]) / (2 * h), lin.dD[j][i], 1e-7) << "D " << j << " input " << i;
      EXPECT_NEAR((plus.gap[j] - minus.gap[j]) / (2 * h), lin.dGap[j][i], 1e-7) << "gap " << j << " input " << i;
      for (int l = 0; l < Lin::nM; ++l)
        EXPECT_NEAR((plus.M[j][l] - minus.M[j][l]) / (2 * h), lin.dM[j][l][i], 1e-7)
            << "M " << j << l << " input " << i;
    }
  }
}

TEST(Mortar2DCurvedLinearization, BowedLine3Faces) {
  const L3 xs = line3({0.0, 0.0}, {2.0, 0.2}, 0.15, 0.05);
  const L3 ns{{{-std::sin(0.2), std::cos(0.2)}, {-std::sin(-0.25), std::cos(-0.25)}, {0.0, 1.0}}};
  checkDerivatives<FaceType::Line3, FaceType::Line3>(xs, ns, line3({1.6, 0.35}, {-0.3, 0.2}, -0.1), false);
}

TEST(Mortar2DCurvedLinearization, MixedFacesAndRings) {
  const L3 xs = line3({1.0, 0.0}, {3.0, 0.2}, 0.15);
  const L3 ns{{{-std::sin(0.2), std::cos(0.2)}, {-std::sin(-0.25), std::cos(-0.25)}, {0.0, 1.0}}};
  checkDerivatives<FaceType::Line3, FaceType::Line2>(xs, ns, L2{{{2.6, 0.35}, {0.7, 0.2}}}, true);
  const L2 xs2{{{1.0, 0.0}, {3.0, 0.2}}};
  const L2 ns2{{{-std::sin(0.2), std::cos(0.2)}, {-std::sin(-0.25), std::cos(-0.25)}}};
  checkDerivatives<FaceType::Line2, FaceType::Line3>(xs2, ns2, line3({2.6, 0.35}, {0.7, 0.2}, -0.1), false);
}

}  // namespace
}  // namespace coulomb::contact
