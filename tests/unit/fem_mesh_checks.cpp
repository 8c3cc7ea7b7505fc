// The mesh checks before a solve (fem/MeshChecks.hpp): cell measures against
// the exact areas and volumes, the zero-volume rule, coincident nodes with
// and without the contact-surface exemption, faces inside a body.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/MeshChecks.hpp"

namespace {

using coulomb::mesh::CellType;

// Exodus order: bottom face counter-clockwise, then the top face.
std::array<double, 24> boxHex(double a, double b, double c) {
  return {0, 0, 0, a, 0, 0, a, b, 0, 0, b, 0, 0, 0, c, a, 0, c, a, b, c, 0, b, c};
}

TEST(MeshChecks, MeasuresAreExactAreasAndVolumes) {
  const double tri[] = {0, 0, 2, 0, 0, 3};
  EXPECT_DOUBLE_EQ(coulomb::fem::cellMeasure(CellType::Tri3, tri), 3.0);
  const double quad[] = {0, 0, 2, 0, 2.5, 1, 0.5, 1};  // a parallelogram, base 2, height 1
  EXPECT_DOUBLE_EQ(coulomb::fem::cellMeasure(CellType::Quad4, quad), 2.0);
  const double quadClockwise[] = {0, 0, 0.5, 1, 2.5, 1, 2, 0};
  EXPECT_DOUBLE_EQ(coulomb::fem::cellMeasure(CellType::Quad4, quadClockwise), -2.0);
  const double tet[] = {0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3};
  EXPECT_DOUBLE_EQ(coulomb::fem::cellMeasure(CellType::Tet4, tet), 1.0);
  auto hex = boxHex(2, 3, 4);
  EXPECT_NEAR(coulomb::fem::cellMeasure(CellType::Hex8, hex.data()), 24.0, 1e-13);
  // A sheared brick keeps its volume (planar faces).
  for (int a = 4; a < 8; ++a) hex[3 * a] += 1.5;
  EXPECT_NEAR(coulomb::fem::cellMeasure(CellType::Hex8, hex.data()), 24.0, 1e-13);
  EXPECT_NEAR(coulomb::fem::cellDiameter(CellType::Tet4, tet), std::sqrt(13.0), 1e-15);
}

TEST(MeshChecks, ZeroVolumeIsAFlatCellNotASmallOne) {
  const auto tiny = boxHex(1e-6, 1e-6, 1e-6);
  EXPECT_FALSE(coulomb::fem::hasZeroVolume(CellType::Hex8, tiny.data()));
  // All eight nodes distinct, in the plane z = 0.
  const double flat[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.25, 0.25, 0, 0.75, 0.25, 0, 0.75, 0.75, 0, 0.25, 0.75, 0};
  EXPECT_TRUE(coulomb::fem::hasZeroVolume(CellType::Hex8, flat));
  const double collinear[] = {0, 0, 1, 1, 2, 2};
  EXPECT_TRUE(coulomb::fem::hasZeroVolume(CellType::Tri3, collinear));
  // A sliver of aspect 1e-4 is bad but has a volume.
  const double sliver[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1e-4};
  EXPECT_FALSE(coulomb::fem::hasZeroVolume(CellType::Tet4, sliver));
}

/// Two unit squares along x, each with its own four nodes (1-4, 5-8);
/// `gap` moves the second one away from x = 1.
coulomb::mesh::GlobalMesh twoSquares(double gap) {
  coulomb::mesh::GlobalMesh m;
  m.dimension = 2;
  m.coordinates = {0, 0, 1, 0, 1, 1, 0, 1, 1 + gap, 0, 2 + gap, 0, 2 + gap, 1, 1 + gap, 1};
  coulomb::mesh::ElementBlock b;
  b.name = "body";
  b.cellType = CellType::Quad4;
  b.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  m.blocks.push_back(b);
  return m;
}

TEST(MeshChecks, CoincidentNodesOfAnUnmergedMesh) {
  const auto touching = twoSquares(0.0);
  const auto pair = coulomb::fem::findCoincidentNodes(touching, {});
  EXPECT_EQ(pair[0], 1);  // (1, 0): nodes 1 and 4 (0-based)
  EXPECT_EQ(pair[1], 4);
  // Within 1e-10 of the diagonal is coincident; 1e-8 apart is not.
  EXPECT_EQ(coulomb::fem::findCoincidentNodes(twoSquares(1e-12), {})[0], 1);
  EXPECT_EQ(coulomb::fem::findCoincidentNodes(twoSquares(1e-8), {})[0], -1);
  // Nodes of a contact surface are exempt (bodies meshed touching).
  std::vector<char> exempt(8, 0);
  exempt[1] = exempt[2] = 1;
  EXPECT_EQ(coulomb::fem::findCoincidentNodes(touching, exempt)[0], -1);
  exempt[2] = 0;
  EXPECT_EQ(coulomb::fem::findCoincidentNodes(touching, exempt)[0], 2);
  EXPECT_THROW(coulomb::fem::checkCoincidentNodes(touching, {}, "m.e"), coulomb::Error);
  try {
    coulomb::fem::checkCoincidentNodes(touching, {}, "m.e");
  } catch (const coulomb::Error& e) {
    EXPECT_NE(std::string(e.what()).find("nodes 2 and 5 are at the same point (1, 0)"), std::string::npos) << e.what();
  }
}

TEST(MeshChecks, CoincidentNodesOfOneCellAreLeftToTheVolumeCheck) {
  coulomb::mesh::GlobalMesh m = twoSquares(0.5);
  m.coordinates[2 * 2] = 0, m.coordinates[2 * 2 + 1] = 1;  // node 2 onto node 3 (element 1 collapsed)
  EXPECT_EQ(coulomb::fem::findCoincidentNodes(m, {})[0], -1);
}

TEST(MeshChecks, FaceInsideABodyHasAnElementAcross) {
  // Merged: the second square uses nodes 1 and 2 of the first.
  coulomb::mesh::GlobalMesh m;
  m.dimension = 2;
  m.coordinates = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};
  coulomb::mesh::ElementBlock b;
  b.cellType = CellType::Quad4;
  b.connectivity = {0, 1, 2, 3, 1, 4, 5, 2};
  m.blocks.push_back(b);
  const auto adjacency = coulomb::fem::nodeElementAdjacency(m);
  EXPECT_EQ(coulomb::fem::elementAcrossFace(m, adjacency, 0, 1), 1);  // side 2 of element 1: x = 1
  EXPECT_EQ(coulomb::fem::elementAcrossFace(m, adjacency, 1, 3), 0);  // side 4 of element 2: x = 1
  for (int side : {0, 2, 3}) EXPECT_EQ(coulomb::fem::elementAcrossFace(m, adjacency, 0, side), -1);
}

}  // namespace
