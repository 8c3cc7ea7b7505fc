// The roles of a self-contact surface's faces (SelfContactRoles.hpp): which
// faces are linked, and how linked regions become slave and master.
// Hand-made 2D surfaces of Line2 faces, no MPI.
#include <gtest/gtest.h>

#include <vector>

#include "coulomb/contact/interface/SelfContactRoles.hpp"

namespace coulomb::contact {
namespace {

/// A surface of Line2 faces given as node pairs; node k at points[k] (the
/// interface index is the node number).
struct Surface {
  std::vector<ContactFace> faces;
  InterfaceConfiguration x;
  Surface(const std::vector<std::array<double, 2>>& points, const std::vector<std::array<int, 2>>& lines) {
    x.dimension = 2;
    for (const auto& p : points) x.x.insert(x.x.end(), p.begin(), p.end());
    for (const auto& l : lines) {
      ContactFace f;
      f.type = mesh::FaceType::Line2;
      f.numNodes = 2;
      f.element = static_cast<long long>(faces.size());
      for (int a = 0; a < 2; ++a) f.nodes[a] = f.interfaceIndex[a] = l[a];
      faces.push_back(f);
    }
  }
};

// The inner surface of a C, as c_ring2d.geo: the lower face of the top arm
// (y = gap, outward normal -y), the column face (x = 0, normal +x) and the
// upper face of the bottom arm (y = 0, normal +y); each face runs so that
// (dy, -dx) points out of the body. Nodes 0..3 on the top (x = 3, 2, 1,
// 0), 4..7 on the bottom (x = 0..3); faces 0..2 top (from x = 3), 3 the
// column, 4..6 bottom (from x = 0).
Surface cSurface(double gap) {
  return Surface({{3, gap}, {2, gap}, {1, gap}, {0, gap}, {0, 0}, {1, 0}, {2, 0}, {3, 0}},
                 {{1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, 4}, {6, 5}, {7, 6}});
}

TEST(SelfContactRoles, FacingArmsAreLinkedButNotNeighboursNorTheColumn) {
  const Surface s = cSurface(0.5);
  EXPECT_TRUE(selfContactFacesFaceEachOther(2, s.faces[0], s.faces[6], s.x));
  EXPECT_TRUE(selfContactFacesFaceEachOther(2, s.faces[6], s.faces[0], s.x));
  EXPECT_FALSE(selfContactFacesFaceEachOther(2, s.faces[0], s.faces[1], s.x)) << "neighbours";
  EXPECT_FALSE(selfContactFacesFaceEachOther(2, s.faces[2], s.faces[3], s.x)) << "neighbours";
  EXPECT_FALSE(selfContactFacesFaceEachOther(2, s.faces[1], s.faces[3], s.x)) << "perpendicular: a corner";
}

TEST(SelfContactRoles, APenetrationWithinAQuarterFaceLinksTheThicknessOfAWallDoesNot) {
  // The arms overlapping by 0.2 of a face (1 long): still linked.
  const Surface pressed = cSurface(-0.2);
  EXPECT_TRUE(selfContactFacesFaceEachOther(2, pressed.faces[0], pressed.faces[6], pressed.x));
  // By 0.3: the top face lies behind the bottom one beyond kSelfContactBehind.
  const Surface through = cSurface(-0.3);
  EXPECT_FALSE(selfContactFacesFaceEachOther(2, through.faces[0], through.faces[6], through.x));
  // The two sides of a wall 0.5 thick: opposed normals, each behind the other.
  const Surface wall({{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}}, {{0, 1}, {2, 3}});
  // Face 0 runs +x: normal (0, -1), out of the bottom; face 1 runs -x: (0, 1), out of the top.
  EXPECT_FALSE(selfContactFacesFaceEachOther(2, wall.faces[0], wall.faces[1], wall.x));
}

TEST(SelfContactRoles, TheRegionWithTheLowestFaceIsSlaveItsPartnerMaster) {
  const Surface s = cSurface(0.5);
  // Top faces 0, 1 face bottom faces 6, 5.
  const SelfContactRoles roles = decideSelfContactRoles(s.faces, {{6, 0}, {5, 1}, {0, 6}});
  const std::vector<SelfContactRole> expected{SelfContactRole::Slave,  SelfContactRole::Slave, SelfContactRole::None,
                                              SelfContactRole::None,   SelfContactRole::None,  SelfContactRole::Master,
                                              SelfContactRole::Master};
  EXPECT_EQ(roles.role, expected);
  EXPECT_EQ(roles.droppedLinks, 0);
}

TEST(SelfContactRoles, ALinkInsideOneRegionIsDropped) {
  const Surface s = cSurface(0.5);
  // Faces 2, 3 and 4 linked (as if the corner folded): through their shared
  // nodes one region, so the link 2-4 has nothing to split; face 0, linked
  // to the column face 3, is a region of its own and the slave.
  const SelfContactRoles roles = decideSelfContactRoles(s.faces, {{2, 4}, {3, 0}});
  EXPECT_EQ(roles.droppedLinks, 1);
  const std::vector<SelfContactRole> expected{SelfContactRole::Slave,  SelfContactRole::None,   SelfContactRole::Master,
                                              SelfContactRole::Master, SelfContactRole::Master, SelfContactRole::None,
                                              SelfContactRole::None};
  EXPECT_EQ(roles.role, expected);
}

TEST(SelfContactRoles, AnOddLoopOfRegionsDropsOneLink) {
  const Surface s = cSurface(0.5);
  // Regions {0}, {2}, {5}, each linked to the other two: 0 slave, 2 and 5
  // master, and their link cannot be split.
  const SelfContactRoles roles = decideSelfContactRoles(s.faces, {{0, 2}, {2, 5}, {0, 5}});
  EXPECT_EQ(roles.droppedLinks, 1);
  EXPECT_EQ(roles.role[0], SelfContactRole::Slave);
  EXPECT_EQ(roles.role[2], SelfContactRole::Master);
  EXPECT_EQ(roles.role[5], SelfContactRole::Master);
  // A chain of three regions alternates: {0} slave, {2} master, {5} slave.
  const SelfContactRoles chain = decideSelfContactRoles(s.faces, {{0, 2}, {2, 5}});
  EXPECT_EQ(chain.droppedLinks, 0);
  EXPECT_EQ(chain.role[0], SelfContactRole::Slave);
  EXPECT_EQ(chain.role[2], SelfContactRole::Master);
  EXPECT_EQ(chain.role[5], SelfContactRole::Slave);
}

}  // namespace
}  // namespace coulomb::contact
