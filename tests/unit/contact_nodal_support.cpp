// S_j, the D_j a slave node's faces give under a covering master
// (NodalSupport.hpp): a face paired with itself by the mortar kernel, or,
// when the kernel cannot project a crumpled face onto the plane of one of its
// own pieces, int N~_j on the curved face. A geometry error there ended runs
// (neo_hookean_shear_3d on HEX27 with the block's sides in the slave surface:
// "a master face is twisted over itself ... (a bow-tie)") instead of leaving
// the kernels' real pairs to decide.
#include <gtest/gtest.h>

#include <cmath>

#include "QuadraticFaces.hpp"
#include "coulomb/contact/interface/NodalSupport.hpp"
#include "coulomb/contact/mortar/DualBasis.hpp"
#include "coulomb/contact/mortar/MortarSegmentQuadratic3D.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using mesh::FaceType;

/// Face f of type F on nodes 0..n-1 (global = interface index) at x.
template <FaceType F>
ContactFace faceOn(const FaceNodes<F, double>& x, InterfaceConfiguration& configuration) {
  ContactFace f;
  f.type = F;
  f.numNodes = FaceTraits<F>::nodes;
  configuration.dimension = 3;
  configuration.x.clear();
  for (int a = 0; a < f.numNodes; ++a) {
    f.nodes[a] = a;
    f.interfaceIndex[a] = a;
    for (int c = 0; c < 3; ++c) configuration.x.push_back(x[a][c]);
  }
  return f;
}

/// Crumpled faces on about [-1, 1]^2 (random node offsets up to 0.3 in the
/// plane and 0.6 out of it): the sub-facet kernel cannot pair them with
/// themselves.
FaceNodes<FaceType::Quad9, double> crumpledQuad9() {
  return {{{-1.18, -0.75, -0.49}, {1.06, -1.15, 0.10}, {0.71, 0.70, -0.50}, {-1.01, 1.29, -0.11}, {0.03, -0.91, -0.06},
           {1.19, 0.24, 0.55}, {0.28, 0.80, 0.59}, {-0.99, -0.21, -0.30}, {0.27, -0.26, 0.24}}};
}
FaceNodes<FaceType::Quad8, double> crumpledQuad8() {
  return {{{-0.77, -1.07, -0.37}, {0.84, -1.17, -0.36}, {0.77, 0.82, -0.42}, {-0.71, 0.71, -0.48}, {-0.23, -0.92, 0.33},
           {1.16, -0.03, 0.50}, {-0.11, 1.19, 0.44}, {-0.71, -0.24, -0.28}}};
}

template <FaceType F>
FaceNodes<F, double> upNormals() {
  FaceNodes<F, double> n{};
  for (auto& node : n) node = {0.0, 0.0, 1.0};
  return n;
}

/// The crumpled face's S is its int N~_j (the kernel itself throws), and
/// d S / d x matches central differences of S.
template <FaceType F>
void expectCurvedIntegralOfCrumpledFace(const FaceNodes<F, double>& x) {
  EXPECT_THROW((integrateQuadraticSegment3D<F, F, double>(x, upNormals<F>(), x, 1e-12)), Error);
  InterfaceConfiguration configuration;
  const ContactFace f = faceOn<F>(x, configuration);
  const auto S = faceSupportMeasures(f, configuration, false);
  const auto mass = faceMass<F, double>(x);
  for (int j = 0; j < f.numNodes; ++j) EXPECT_NEAR(S[j], mass.De[j], 1e-14 * std::abs(mass.De[j]) + 1e-15) << j;

  const double h = 1e-6;
  for (int corner : {0, f.numNodes - 1}) {
    DerivativeRow row;
    addFaceSupportMeasureDerivative(f, configuration, false, corner, row);
    double largest = 0.0;
    for (const auto& [key, value] : row) largest = std::max(largest, std::abs(value));
    ASSERT_GT(largest, 0.0);
    for (int a = 0; a < f.numNodes; ++a)
      for (int c = 0; c < 3; ++c) {
        InterfaceConfiguration plus = configuration, minus = configuration;
        plus.x[3 * a + c] += h;
        minus.x[3 * a + c] -= h;
        const double fd = (faceSupportMeasures(f, plus, false)[corner] - faceSupportMeasures(f, minus, false)[corner]) /
                          (2 * h);
        const auto it = row.find({a, c});
        const double exact = it == row.end() ? 0.0 : it->second;
        EXPECT_NEAR(exact, fd, 1e-7 * largest) << "corner " << corner << " node " << a << " component " << c;
      }
  }
}

TEST(NodalSupport, CrumpledQuad9FaceTakesItsCurvedIntegral) { expectCurvedIntegralOfCrumpledFace<FaceType::Quad9>(crumpledQuad9()); }

TEST(NodalSupport, CrumpledQuad8FaceTakesItsCurvedIntegral) { expectCurvedIntegralOfCrumpledFace<FaceType::Quad8>(crumpledQuad8()); }

// A face the kernel can pair with itself keeps the kernel's measure (the
// chords of the curved face, not int N~_j: they differ by 5e-4 or more on
// this Quad8, Mortar3DQuadratic.CurvedFaceUnderACoveringMasterHasItsSelfIntegral).
TEST(NodalSupport, CurvedQuad8FaceKeepsTheSelfPairedKernel) {
  const auto x = test::quad8(0.0, 0.0, 1.0, 1.0, 0.0, 0.2, 0.3);
  InterfaceConfiguration configuration;
  const ContactFace f = faceOn<FaceType::Quad8>(x, configuration);
  const auto S = faceSupportMeasures(f, configuration, false);
  const auto self = integrateQuadraticSegment3D<FaceType::Quad8, FaceType::Quad8, double>(
      x, upNormals<FaceType::Quad8>(), x, 1e-12);
  const auto mass = faceMass<FaceType::Quad8, double>(x);
  double fromMass = 0.0;
  for (int j = 0; j < 8; ++j) {
    EXPECT_DOUBLE_EQ(S[j], self.D[j]) << j;
    fromMass = std::max(fromMass, std::abs(S[j] - mass.De[j]) / mass.De[j]);
  }
  EXPECT_GT(fromMass, 5e-4);
}

}  // namespace
}  // namespace coulomb::contact
