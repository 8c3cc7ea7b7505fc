// 3D mortar segments with a Quad8 or Tri6 face (issue 18, item 2): the
// transformed slave basis N~ (DualBasis.hpp, faceTrialValues) and its dual
// basis (D > 0 where the standard one has D <= 0 at the corners), the patch
// identities on plane parallel faces segmented on sub-facets
// (MortarSegmentQuadratic3D.hpp), and the Sacado derivatives against
// central finite differences on curved faces.
#include <gtest/gtest.h>

#include <cmath>

#include "QuadraticFaces.hpp"
#include "QuadraticSegmentChecks.hpp"
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using test::Q8;
using test::T6;
using Q4 = FaceNodes<FaceType::Quad4, double>;
using T3 = FaceNodes<FaceType::Tri3, double>;
using test::quad8;
using test::reversed;
using test::tri6;
using test::up;
using test::tilted;
constexpr double kAlpha = kTransformedBasisAlpha;

/// A = D_e M_e^-1: int Phi_j N~_k = delta_jk D_e[j].
template <FaceType F>
void expectBiorthogonal(const FaceNodes<F, double>& x) {
  constexpr int n = FaceTraits<F>::nodes;
  const auto mass = faceMass<F, double>(x);
  const auto A = dualCoefficients<F, double>(x);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) {
      double integral = 0;
      for (int m = 0; m < n; ++m) integral += A[j][m] * mass.Me[m][k];
      EXPECT_NEAR(integral, j == k ? mass.De[j] : 0.0, 1e-13) << j << " " << k;
    }
}

// int N~_j dA on a plane face of area A: Quad8 corners A (-1/12 + 2 alpha/3)
// = A/20, edges A (1 - 2 alpha)/3 = A/5; Tri6 corners 2 alpha A/3 = 2A/15,
// edges A/5 — all positive, where the standard ones are -A/12 and 0 at the
// corners; the dual basis is biorthogonal to N~.
TEST(Mortar3DTransformed, TransformedBasisHasPositiveD) {
  const Q8 q = quad8(0.0, 0.0, 2.0, 1.5, 0.0, 0.0, 0.3);
  const auto quadMass = faceMass<FaceType::Quad8, double>(q);
  for (int k = 0; k < 8; ++k) EXPECT_NEAR(quadMass.De[k], k < 4 ? 3.0 / 20 : 3.0 / 5, 1e-13) << k;
  expectBiorthogonal<FaceType::Quad8>(q);
  const T6 t = tri6({0.0, 0.0}, {2.0, 0.2}, {0.5, 1.5}, 0.0);
  const double area = 0.5 * (2.0 * 1.5 - 0.2 * 0.5);
  const auto triMass = faceMass<FaceType::Tri6, double>(t);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(triMass.De[k], k < 3 ? 2 * area / 15 : area / 5, 1e-13) << k;
  expectBiorthogonal<FaceType::Tri6>(t);
}

// N~ spans the space of N: sum_j N~_j = 1, and N~ interpolates the
// transformed nodal values (d_c = d~_c, d_e = (1 - 2 alpha) d~_e + alpha
// (d~_a + d~_b)) to the same field as N the plain ones.
TEST(Mortar3DTransformed, TransformedBasisSpansTheSameSpace) {
  const std::array<double, 8> d{0.3, -1.2, 0.7, 2.0, 0.1, -0.4, 1.1, 0.5};
  std::array<double, 8> dt = d;  // d~ = T^-1 d
  for (const auto& e : kQuad8Edge) dt[e[0]] = (d[e[0]] - kAlpha * (d[e[1]] + d[e[2]])) / (1 - 2 * kAlpha);
  for (const std::array<double, 2> xi : {std::array<double, 2>{0.3, -0.6}, {-0.9, 0.2}, {0.0, 0.0}, {1.0, 1.0}}) {
    const auto N = faceShapeValues<FaceType::Quad8, double>(xi);
    const auto Nt = faceTrialValues<FaceType::Quad8, double>(xi);
    double sum = 0, plain = 0, transformed = 0;
    for (int k = 0; k < 8; ++k) {
      sum += Nt[k];
      plain += N[k] * d[k];
      transformed += Nt[k] * dt[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_NEAR(transformed, plain, 1e-13);
  }
}

// Plane parallel faces at the gap g, the master covering part of the slave,
// then all of it (D_j = int N~_j: the covered support's whole weight).
TEST(Mortar3DTransformed, PlaneParallelFacesGiveThePatchIdentities) {
  const double g = 0.2;
  const Q8 slave = quad8(0.0, 0.0, 2.0, 2.0, 0.0, 0.0, 0.2);
  test::expectPatchIdentities(integrateQuadraticSegment3D<FaceType::Quad8, FaceType::Quad8, double>(
                            slave, up<FaceType::Quad8>(), reversed(quad8(0.7, -1.0, 2.3, 2.3, g)), 1e-12),
                        8, g, 1.3 * 1.3 + 0.05 * 1.3 * 1.3);
  const auto covering = integrateQuadraticSegment3D<FaceType::Quad8, FaceType::Quad8, double>(
      slave, up<FaceType::Quad8>(), reversed(quad8(-1.0, -1.0, 4.0, 4.0, g)), 1e-12);
  test::expectPatchIdentities(covering, 8, g, 4.0);
  const auto mass = faceMass<FaceType::Quad8, double>(slave);
  for (int j = 0; j < 8; ++j) EXPECT_NEAR(covering.D[j], mass.De[j], 1e-12) << j;
  const Q4 linear{{{0.7, -1.0, g}, {0.7, 1.3, g}, {3.0, 1.3, g}, {3.0, -1.0, g}}};
  test::expectPatchIdentities(
      integrateQuadraticSegment3D<FaceType::Quad8, FaceType::Quad4, double>(slave, up<FaceType::Quad8>(), linear, 1e-12),
      8, g, 1.3 * 1.3 + 0.05 * 1.3 * 1.3);

  const T6 triangle = tri6({0.0, 0.0}, {2.0, 0.0}, {0.0, 2.0}, 0.0);
  const auto tri = integrateQuadraticSegment3D<FaceType::Tri6, FaceType::Tri6, double>(
      triangle, up<FaceType::Tri6>(), reversed(tri6({-1.0, -1.0}, {5.0, -1.0}, {-1.0, 5.0}, g)), 1e-12);
  test::expectPatchIdentities(tri, 6, g, 2.0);
  const auto triMass = faceMass<FaceType::Tri6, double>(triangle);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(tri.D[j], triMass.De[j], 1e-12) << j;
  // A Quad8 master over the part x < 1 of the triangle: area 2 - 0.5.
  test::expectPatchIdentities(integrateQuadraticSegment3D<FaceType::Tri6, FaceType::Quad8, double>(
                            triangle, up<FaceType::Tri6>(), reversed(quad8(-1.0, -1.0, 2.0, 4.0, g)), 1e-12),
                        6, g, 1.5);
  // A linear slave under a Tri6 master: D_j = int N_j of the Quad4 (1/4 each).
  const Q4 linearSlave{{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}}};
  const auto onTri = integrateQuadraticSegment3D<FaceType::Quad4, FaceType::Tri6, double>(
      linearSlave, up<FaceType::Quad4>(), reversed(tri6({-1.0, -1.0}, {5.0, -1.0}, {-1.0, 5.0}, g)), 1e-12);
  test::expectPatchIdentities(onTri, 4, g, 1.0);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(onTri.D[j], 0.25, 1e-12) << j;
}


TEST(Mortar3DTransformedLinearization, CurvedQuad8AndTri6Faces) {
  test::checkQuadraticSegmentDerivatives<FaceType::Quad8, FaceType::Quad8>(quad8(0.0, 0.0, 2.0, 2.0, 0.0, 0.08, 0.1), tilted<FaceType::Quad8>(),
                                                      reversed(quad8(0.6, -0.5, 2.2, 1.9, 0.15, -0.05)));
  test::checkQuadraticSegmentDerivatives<FaceType::Tri6, FaceType::Tri6>(tri6({0.0, 0.0}, {2.0, 0.1}, {0.2, 1.8}, 0.0, 0.06),
                                                    tilted<FaceType::Tri6>(),
                                                    reversed(tri6({0.3, -0.4}, {2.5, 0.3}, {-0.2, 2.1}, 0.15, -0.04)));
  const T3 master{{{0.3, -0.4, 0.15}, {-0.2, 2.1, 0.12}, {2.5, 0.3, 0.2}}};
  test::checkQuadraticSegmentDerivatives<FaceType::Tri6, FaceType::Tri3>(tri6({0.0, 0.0}, {2.0, 0.1}, {0.2, 1.8}, 0.0, 0.06),
                                                    tilted<FaceType::Tri6>(), master);
}

}  // namespace
}  // namespace coulomb::contact
