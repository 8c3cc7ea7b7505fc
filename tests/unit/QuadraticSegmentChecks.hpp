#pragma once
// Checks shared by the tests of the sub-facet mortar kernel
// (MortarSegmentQuadratic3D.hpp): the patch identities on plane parallel
// faces and the Sacado derivatives against central differences.
#include <gtest/gtest.h>

#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"

namespace coulomb::contact::test {

/// Plane parallel faces at the gap g: sum_l M_jl = D_j (no weighted relative
/// displacement under a translation), g~_j = g D_j, sum_j D_j = the overlap
/// `area`, over the `nodes` slave nodes.
template <class Segment>
void expectPatchIdentities(const Segment& r, int nodes, double g, double area) {
  ASSERT_TRUE(r.contributes);
  double sumD = 0;
  for (int j = 0; j < nodes; ++j) {
    double sumM = 0;
    for (double m : r.M[j]) sumM += m;
    EXPECT_NEAR(sumM, r.D[j], 1e-12) << j;
    EXPECT_NEAR(r.gap[j], g * r.D[j], 1e-12) << j;
    sumD += r.D[j];
  }
  EXPECT_NEAR(sumD, area, 1e-12);
}

/// Central differences of every output against every input (h = 1e-6): the
/// Sacado derivatives match to 1e-7.
template <mesh::FaceType S, mesh::FaceType Mf>
void checkQuadraticSegmentDerivatives(const FaceNodes<S, double>& xs, const FaceNodes<S, double>& ns,
                                      const FaceNodes<Mf, double>& xm) {
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

}  // namespace coulomb::contact::test
