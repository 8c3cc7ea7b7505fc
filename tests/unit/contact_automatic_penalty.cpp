// The automatic nodal penalty eps_n,j = factor × E_j / h_j (AutomaticPenalty.hpp).
#include <gtest/gtest.h>

#include "coulomb/contact/laws/AutomaticPenalty.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

PenaltyFace line(int a, int b, double diameter, double modulus) {
  PenaltyFace f;
  f.numNodes = 2;
  f.nodes = {a, b, -1, -1};
  f.diameter = diameter;
  f.modulus = modulus;
  return f;
}

// A uniform chain: every node E / h, as the pair's single value was.
TEST(AutomaticPenalty, UniformFacesGiveEOverH) {
  const std::vector<PenaltyFace> faces = {line(0, 1, 0.5, 200.0), line(1, 2, 0.5, 200.0), line(2, 3, 0.5, 200.0)};
  const auto eps = automaticNodalPenalty(faces, 4, 200.0, 1.0, PenaltySize::LocalFaces);
  ASSERT_EQ(eps.size(), 4u);
  for (double e : eps) EXPECT_DOUBLE_EQ(e, 400.0);
}

// A graded chain (faces 1 and 4 long): each node takes the mean size of its
// own faces, the junction 2.5.
TEST(AutomaticPenalty, GradedFacesGiveTheLocalSize) {
  const std::vector<PenaltyFace> faces = {line(0, 1, 1.0, 10.0), line(1, 2, 4.0, 10.0)};
  const auto eps = automaticNodalPenalty(faces, 3, 10.0, 2.0, PenaltySize::LocalFaces);
  EXPECT_DOUBLE_EQ(eps[0], 2.0 * 10.0 / 1.0);
  EXPECT_DOUBLE_EQ(eps[1], 2.0 * 10.0 / 2.5);
  EXPECT_DOUBLE_EQ(eps[2], 2.0 * 10.0 / 4.0);
}

// The ALM's size: the pair's mean face, the same at every node of a graded chain.
TEST(AutomaticPenalty, PairMeanSizeIsTheSameAtEveryNode) {
  const std::vector<PenaltyFace> faces = {line(0, 1, 1.0, 10.0), line(1, 2, 4.0, 10.0)};
  const auto eps = automaticNodalPenalty(faces, 3, 10.0, 2.0, PenaltySize::PairMean);
  for (double e : eps) EXPECT_DOUBLE_EQ(e, 2.0 * 10.0 / 2.5);
  // The moduli stay per node.
  const auto mixed = automaticNodalPenalty({line(0, 1, 1.0, 1.0), line(1, 2, 3.0, 100.0)}, 3, 10.0, 1.0,
                                           PenaltySize::PairMean);
  EXPECT_DOUBLE_EQ(mixed[0], 1.0 / 2.0);
  EXPECT_DOUBLE_EQ(mixed[2], 10.0 / 2.0);
}

// Two slave materials (E 1 and 100) on a master of E 10: the softer side of
// each node, the stiffer slave element at the junction.
TEST(AutomaticPenalty, TheSofterSideGovernsEachNode) {
  const std::vector<PenaltyFace> faces = {line(0, 1, 1.0, 1.0), line(1, 2, 1.0, 100.0)};
  const auto eps = automaticNodalPenalty(faces, 3, 10.0, 1.0, PenaltySize::LocalFaces);
  EXPECT_DOUBLE_EQ(eps[0], 1.0);
  EXPECT_DOUBLE_EQ(eps[1], 10.0);
  EXPECT_DOUBLE_EQ(eps[2], 10.0);
  // No master modulus: the slave's own.
  const auto alone = automaticNodalPenalty(faces, 3, 0.0, 1.0, PenaltySize::LocalFaces);
  EXPECT_DOUBLE_EQ(alone[0], 1.0);
  EXPECT_DOUBLE_EQ(alone[2], 100.0);
}

// A quadrilateral face counts once at each of its four nodes; a node on no
// face (a master node of the interface) gets 0.
TEST(AutomaticPenalty, QuadFacesAndNodesOffTheSlaveSurface) {
  PenaltyFace quad;
  quad.numNodes = 4;
  quad.nodes = {0, 1, 2, 3};
  quad.diameter = 0.25;
  quad.modulus = 8.0;
  const auto eps = automaticNodalPenalty({quad}, 5, 8.0, 1.0, PenaltySize::LocalFaces);
  for (int j = 0; j < 4; ++j) EXPECT_DOUBLE_EQ(eps[j], 32.0);
  EXPECT_EQ(eps[4], 0.0);
}

TEST(AutomaticPenalty, RejectsBadInput) {
  const auto local = PenaltySize::LocalFaces;
  EXPECT_THROW(automaticNodalPenalty({line(0, 1, 0.0, 1.0)}, 2, 1.0, 1.0, local), Error);
  // A zero factor (the deck requires > 0) and a face node outside the interface: bugs, not inputs.
  EXPECT_THROW(automaticNodalPenalty({line(0, 1, 1.0, 1.0)}, 2, 1.0, 0.0, local), InternalError);
  EXPECT_THROW(automaticNodalPenalty({line(0, 2, 1.0, 1.0)}, 2, 1.0, 1.0, local), InternalError);
}

}  // namespace
}  // namespace coulomb::contact
