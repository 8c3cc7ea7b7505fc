// 3D mortar segments pairing a Quad9 with a Quad8 or a Tri6 (a HEX27 body on
// a HEX20 or TET10 one; issue 18, items 1 and 2): the slave keeps its own
// dual basis (standard for a Quad9, on the transformed N~ for a Quad8 / Tri6),
// the master its standard shape functions. Checked: the patch identities on
// plane parallel faces, D_j = int N~_j under a covering master, and the
// Sacado derivatives against central finite differences on curved faces.
#include <gtest/gtest.h>

#include "QuadraticFaces.hpp"
#include "QuadraticSegmentChecks.hpp"
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;
using namespace test;

/// The identities of a slave S under a master covering part of it (`partial`,
/// overlap `area`) and one covering all of it (D_j = faceMass's D_e).
template <FaceType S, FaceType Mf>
void expectMixedPatch(const FaceNodes<S, double>& slave, const FaceNodes<Mf, double>& partial, double area,
                      const FaceNodes<Mf, double>& covering, double slaveArea, double g) {
  constexpr int n = FaceTraits<S>::nodes;
  expectPatchIdentities(integrateQuadraticSegment3D<S, Mf, double>(slave, up<S>(), partial, 1e-12), n, g, area);
  const auto all = integrateQuadraticSegment3D<S, Mf, double>(slave, up<S>(), covering, 1e-12);
  expectPatchIdentities(all, n, g, slaveArea);
  const auto mass = faceMass<S, double>(slave);
  for (int j = 0; j < n; ++j) EXPECT_NEAR(all.D[j], mass.De[j], 1e-12) << j;
}

TEST(Mortar3DMixedQuadratic, PlaneParallelFacesGiveThePatchIdentities) {
  const double g = 0.2;
  // Quad9 slave [0, 2]^2 (area 4): a Tri6 master on its lower-left half
  // (area 2), then one covering it.
  const Q9 q9 = quad9(0.0, 0.0, 2.0, 2.0, 0.0);
  const T6 lowerLeft = reversed(tri6({0.0, 0.0}, {2.0, 0.0}, {0.0, 2.0}, g));
  const T6 coveringTri = reversed(tri6({-1.0, -1.0}, {6.0, -1.0}, {-1.0, 6.0}, g));
  expectMixedPatch<FaceType::Quad9, FaceType::Tri6>(q9, lowerLeft, 2.0, coveringTri, 4.0, g);
  // Quad8 master over x in [0.7, 3], y in [-1, 1.3].
  expectMixedPatch<FaceType::Quad9, FaceType::Quad8>(q9, reversed(quad8(0.7, -1.0, 2.3, 2.3, g)), 1.3 * 1.3,
                                                     reversed(quad8(-1.0, -1.0, 4.0, 4.0, g)), 4.0, g);
  // Tri6 and Quad8 slaves (transformed basis) under Quad9 masters.
  const T6 t6 = tri6({0.0, 0.0}, {2.0, 0.0}, {0.0, 2.0}, 0.0);
  expectMixedPatch<FaceType::Tri6, FaceType::Quad9>(t6, reversed(quad9(-1.0, -1.0, 2.0, 4.0, g)), 1.5,
                                                    reversed(quad9(-1.0, -1.0, 4.0, 4.0, g)), 2.0, g);
  const Q8 q8 = quad8(0.0, 0.0, 2.0, 2.0, 0.0);
  expectMixedPatch<FaceType::Quad8, FaceType::Quad9>(q8, reversed(quad9(0.7, -1.0, 2.3, 2.3, g)), 1.3 * 1.3,
                                                     reversed(quad9(-1.0, -1.0, 4.0, 4.0, g)), 4.0, g);
}

TEST(Mortar3DMixedQuadraticLinearization, CurvedQuad9WithQuad8AndTri6) {
  const Q9 q9 = quad9(0.0, 0.0, 2.0, 2.0, 0.0, 0.08, 0.1);
  const T6 t6 = tri6({0.0, 0.0}, {2.0, 0.1}, {0.2, 1.8}, 0.0, 0.06);
  const Q8 q8 = quad8(0.0, 0.0, 2.0, 2.0, 0.0, 0.08, 0.1);
  checkQuadraticSegmentDerivatives<FaceType::Quad9, FaceType::Tri6>(
      q9, tilted<FaceType::Quad9>(), reversed(tri6({0.3, -0.4}, {2.5, 0.3}, {-0.2, 2.1}, 0.15, -0.04)));
  checkQuadraticSegmentDerivatives<FaceType::Quad9, FaceType::Quad8>(q9, tilted<FaceType::Quad9>(),
                                                                     reversed(quad8(0.6, -0.5, 2.2, 1.9, 0.15, -0.05)));
  checkQuadraticSegmentDerivatives<FaceType::Tri6, FaceType::Quad9>(t6, tilted<FaceType::Tri6>(),
                                                                    reversed(quad9(0.3, -0.4, 2.2, 1.9, 0.15, -0.05)));
  checkQuadraticSegmentDerivatives<FaceType::Quad8, FaceType::Quad9>(q8, tilted<FaceType::Quad8>(),
                                                                     reversed(quad9(0.6, -0.5, 2.2, 1.9, 0.15, -0.05)));
}

}  // namespace
}  // namespace coulomb::contact
