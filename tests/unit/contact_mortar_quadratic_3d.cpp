// 3D mortar segments with a quadratic Quad9 face (issue 18, item 2;
// MortarSegmentQuadratic3D.hpp): the Quad9 dual basis (D > 0), the patch
// identities on plane parallel faces segmented on sub-facets, and the Sacado
// derivatives against central finite differences on curved faces.
#include <gtest/gtest.h>

#include <cmath>

#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using Q9 = FaceNodes<FaceType::Quad9, double>;
using Q4 = FaceNodes<FaceType::Quad4, double>;

/// The Quad9 of the rectangle [x0, x0 + a] x [y0, y0 + b] at height z, its
/// nodes at the Exodus reference positions mapped affinely; `bow` lifts the
/// mid-side and centre nodes (a curved face), `skew` shears x by y.
Q9 quad9(double x0, double y0, double a, double b, double z, double bow = 0.0, double skew = 0.0) {
  Q9 x{};
  for (int k = 0; k < 9; ++k) {
    const double s = kQuad9Node[k][0], t = kQuad9Node[k][1];
    const bool corner = k < 4;
    x[k] = {x0 + a * (s + 1) / 2 + skew * (t + 1) / 2, y0 + b * (t + 1) / 2, z + (corner ? 0.0 : bow * (k == 8 ? 1.0 : 0.5))};
  }
  return x;
}

Q9 up() {
  Q9 n{};
  for (auto& v : n) v = {0.0, 0.0, 1.0};
  return n;
}

/// The master seen from the slave: the same face with its orientation reversed
/// (nodes 0 3 2 1, 7 6 5 4, 8), as a body facing the slave has.
Q9 reversed(const Q9& x) { return {x[0], x[3], x[2], x[1], x[7], x[6], x[5], x[4], x[8]}; }

/// Plane parallel faces at the gap g: sum_l M_jl = D_j (no weighted relative
/// displacement under a translation), g~_j = g D_j, sum_j D_j = the overlap `area`.
template <class Segment>
void expectPatchIdentities(const Segment& r, double g, double area) {
  ASSERT_TRUE(r.contributes);
  double sumD = 0;
  for (int j = 0; j < 9; ++j) {
    double sumM = 0;
    for (double m : r.M[j]) sumM += m;
    EXPECT_NEAR(sumM, r.D[j], 1e-12) << j;
    EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-12) << j;
    sumD += r.D[j];
  }
  EXPECT_NEAR(sumD, area, 1e-12);
}

// D_e = int N_j dA of a Quad9 on a rectangle of area A: A/36 at corners,
// A/9 at mid-sides, 4A/9 at the centre (positive: the condensation applies),
// and A = D_e M_e^-1 makes int Phi_j N_k = delta_jk D_e[j].
TEST(Mortar3DQuadratic, Quad9DualBasisHasPositiveD) {
  const Q9 x = quad9(0.0, 0.0, 2.0, 1.5, 0.0, 0.0, 0.3);
  const auto mass = faceMass<FaceType::Quad9, double>(x);
  const double A = 3.0;
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(mass.De[k], k < 4 ? A / 36 : k < 8 ? A / 9 : 4 * A / 9, 1e-13) << k;
  const auto coefficients = dualCoefficients<FaceType::Quad9, double>(x);
  for (int j = 0; j < 9; ++j)
    for (int k = 0; k < 9; ++k) {
      double integral = 0;
      for (int m = 0; m < 9; ++m) integral += coefficients[j][m] * mass.Me[m][k];
      EXPECT_NEAR(integral, j == k ? mass.De[j] : 0.0, 1e-13) << j << " " << k;
    }
}

// Plane parallel faces at the gap g, the master covering part of the slave:
// sum_l M_jl = D_j (no weighted relative displacement under a translation),
// g~_j = g D_j, sum_j D_j = the overlap area; a master covering the whole
// slave gives D_j = int N_j dA (biorthogonality).
TEST(Mortar3DQuadratic, PlaneParallelFacesGiveThePatchIdentities) {
  const double g = 0.2;
  const Q9 slave = quad9(0.0, 0.0, 2.0, 2.0, 0.0, 0.0, 0.2);
  auto check = [&](const auto& r, double area) { expectPatchIdentities(r, g, area); };
  // A Quad9 master over x in [0.7, 3], y in [-1, 1.3] (a part), then one covering all.
  check(integrateQuadraticSegment3D<FaceType::Quad9, FaceType::Quad9, double>(
            slave, up(), reversed(quad9(0.7, -1.0, 2.3, 2.3, g)), 1e-12),
        1.3 * 1.3 + 0.05 * 1.3 * 1.3);
  const auto covering = integrateQuadraticSegment3D<FaceType::Quad9, FaceType::Quad9, double>(
      slave, up(), reversed(quad9(-1.0, -1.0, 4.0, 4.0, g)), 1e-12);
  check(covering, 4.0);
  const auto mass = faceMass<FaceType::Quad9, double>(slave);
  for (int j = 0; j < 9; ++j) EXPECT_NEAR(covering.D[j], mass.De[j], 1e-12) << j;
  // A linear master over the same part.
  const Q4 master{{{0.7, -1.0, g}, {0.7, 1.3, g}, {3.0, 1.3, g}, {3.0, -1.0, g}}};
  check(integrateQuadraticSegment3D<FaceType::Quad9, FaceType::Quad4, double>(slave, up(), master, 1e-12),
        1.3 * 1.3 + 0.05 * 1.3 * 1.3);
}

// A master quadrilateral that is not convex (a dart inside the slave) is
// integrated as the two triangles either side of its reflex diagonal, as the
// linear kernel does: the overlap is its area (0.96), the identities hold.
TEST(Mortar3DQuadratic, NonConvexMasterIsTwoTriangles) {
  const double g = 0.1;
  const Q9 slave = quad9(0.0, 0.0, 2.0, 2.0, 0.0);
  const Q4 dart{{{0.2, 1.8, g}, {0.8, 0.8, g}, {1.8, 0.2, g}, {0.2, 0.2, g}}};  // facing the slave
  const auto r = integrateQuadraticSegment3D<FaceType::Quad9, FaceType::Quad4, double>(slave, up(), dart, 1e-12);
  expectPatchIdentities(r, g, 0.96);
}

/// Central differences of every output against every input (h = 1e-6): the
/// Sacado derivatives match to 1e-7.
template <FaceType S, FaceType Mf>
void checkDerivatives(const FaceNodes<S, double>& xs, const FaceNodes<S, double>& ns, const FaceNodes<Mf, double>& xm) {
  constexpr int nS = FaceTraits<S>::nodes, nM = FaceTraits<Mf>::nodes, N = segment3DInputs<S, Mf>;
  const auto lin = linearizeQuadraticSegment3D<S, Mf>(xs, ns, xm, 1e-10);
  ASSERT_TRUE(lin.value.contributes);
  const double h = 1e-6;
  for (int i = 0; i < N; ++i) {
    auto a = xs, b = ns;
    auto c = xm;
    auto input = [&]() -> double& {
      if (i < 3 * nS) return a[i / 3][i % 3];
      if (i < 6 * nS) return b[(i - 3 * nS) / 3][i % 3];
      return c[(i - 6 * nS) / 3][i % 3];
    };
    input() += h;
    const auto plus = integrateQuadraticSegment3D<S, Mf, double>(a, b, c, 1e-10);
    input() -= 2 * h;
    const auto minus = integrateQuadraticSegment3D<S, Mf, double>(a, b, c, 1e-10);
    for (int j = 0; j < nS; ++j) {
      EXPECT_NEAR((plus.D[j] - minus.D[j]) / (2 * h), lin.dD[j][i], 1e-7) << "D " << j << " input " << i;
      EXPECT_NEAR((plus.gap[j] - minus.gap[j]) / (2 * h), lin.dGap[j][i], 1e-7) << "gap " << j << " input " << i;
      for (int l = 0; l < nM; ++l)
        EXPECT_NEAR((plus.M[j][l] - minus.M[j][l]) / (2 * h), lin.dM[j][l][i], 1e-7) << "M " << j << l << " input " << i;
    }
  }
}

TEST(Mortar3DQuadraticLinearization, CurvedQuad9Faces) {
  Q9 ns = up();
  for (int k = 0; k < 9; ++k) {
    const double tilt = 0.05 * (k % 3) - 0.04 * (k / 3);
    const double n = std::sqrt(1 + 2 * tilt * tilt);
    ns[k] = {tilt / n, -tilt / n, 1 / n};
  }
  checkDerivatives<FaceType::Quad9, FaceType::Quad9>(quad9(0.0, 0.0, 2.0, 2.0, 0.0, 0.08, 0.1), ns,
                                                      reversed(quad9(0.6, -0.5, 2.2, 1.9, 0.15, -0.05)));
  const Q4 master{{{0.6, -0.5, 0.15}, {0.7, 1.4, 0.12}, {2.8, 1.4, 0.2}, {2.8, -0.5, 0.1}}};
  checkDerivatives<FaceType::Quad9, FaceType::Quad4>(quad9(0.0, 0.0, 2.0, 2.0, 0.0, 0.08, 0.1), ns, master);
}

}  // namespace
}  // namespace coulomb::contact
