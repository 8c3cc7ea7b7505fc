// Slave surfaces with sharp edges (SharpEdges.hpp): the contact patch tests
// with the punch's sides in the slave surface as well as its bottom. The
// sides touch nothing, so the answer must be the plain patch test's — the
// uniform stress, to round-off, every bottom node at the same pressure — and
// no side node in contact. With the normals averaged across the edge
// ('Feature Angle' = 180: the search's facing test off as well) the edge
// nodes' normals point 45 degrees out of the bottom, the side faces pair with
// the master sideways (a zero diagonal in the condensed tangent: the linear
// solve fails) and the uniform state is lost: the test's own control that it
// can fail. np = 1, 2, 3 (ctest MpiTests.np*).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"
#include "coulomb/contact/interface/SharpEdges.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {
namespace {

constexpr double kE = 210000, kNu = 0.3, kDelta = 0.01;

/// The patch deck with `sides` added to the slave surface `slave`, and the
/// pair's Feature Angle when `featureAngle` > 0.
ShippedDeck sharpPatchDeck(const std::string& name, const std::string& mesh, const std::string& sides,
                           double featureAngle) {
  ShippedDeck deck(name, mesh);
  deck.replace("name=\"Slave\" type=\"string\" value=\"slave\"/>",
               "name=\"Slave\" type=\"string\" value=\"slave, " + sides + "\"/>" +
                   (featureAngle > 0 ? "<Parameter name=\"Feature Angle\" type=\"double\" value=\"" +
                                           std::to_string(featureAngle) + "\"/>"
                                     : std::string()));
  deck.solveToRoundOff();
  return deck;
}

/// Largest |u - u_exact| of the 2D patch (plane strain, free to expand along x).
double patch2dError(const ContactRun& run) {
  double error = 0;
  forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[1] + kDelta * X[1]), std::abs(u[0] - kNu / (1 - kNu) * kDelta * X[0])});
  });
  return globalMax(error);
}

/// Largest |u - u_exact| of the 3D patch (uniaxial stress).
double patch3dError(const ContactRun& run) {
  double error = 0;
  forOwnedNodes(*run.simulation, [&](long long, const double* X, const double* u) {
    error = std::max({error, std::abs(u[2] + kDelta * X[2]), std::abs(u[0] - kNu * kDelta * X[0]),
                      std::abs(u[1] - kNu * kDelta * X[1])});
  });
  return globalMax(error);
}

/// The run's error relative to delta, or infinity when Newton fails (the
/// error is thrown on every rank) for the reason `reason` (a part of the
/// message); any other error fails the test.
double relativeErrorOrFailure(const std::string& name, const std::string& deck, double (*error)(const ContactRun&),
                              const std::string& reason = "Newton did not converge") {
  try {
    auto run = runDeckText(name, deck);
    return error(run) / kDelta;
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(reason), std::string::npos) << what;
    return std::numeric_limits<double>::infinity();
  }
}

}  // namespace

// 2D: the punch's bottom and both its sides in one slave surface; the two
// bottom corners are on sharp edges (90 degrees), their normals those of the
// bottom, which faces the base.
TEST(SharpEdges, Patch2DWithThePunchSidesInTheSlaveSurface) {
  auto run = runDeckText("sharp_patch_2d",
                         sharpPatchDeck("contact_patch_2d", "contact_patch2d.e", "punch_left, punch_right", 0).text);
  EXPECT_LT(patch2dError(run), 1e-9 * kDelta);
  if (worldComm()->getRank() != 0) return;
  const double sigma = kE * kDelta / (1 - kNu * kNu);
  const double current = sigma / (1 + kNu / (1 - kNu) * kDelta);  // per current length
  expectUniformPressure(run, current, 8, "y", sigma);  // the 8 bottom nodes, no side node
}

TEST(SharpEdges, Patch2DWithNormalsAveragedAcrossTheEdgesLosesTheUniformState) {
  EXPECT_GT(relativeErrorOrFailure(
                "sharp_patch_2d_averaged",
                sharpPatchDeck("contact_patch_2d", "contact_patch2d.e", "punch_left, punch_right", 180).text,
                patch2dError,
                // Each try of the step ends in Belos (a zero diagonal): the
                // iterate is rejected and the message says so (NewtonSolver).
                "an iterate was rejected: the linear solve failed: Belos"),
            1e-3);
}

// 3D: the punch's bottom and its four sides; the 16 bottom-edge nodes are on
// sharp edges, the 4 bottom corners on corners of three faces. HEX8 (QUAD4
// faces) and HEX20 (QUAD8 faces with the transformed basis, whose rows mix a
// node with its edges' mid-side nodes on the sides as well).
TEST(SharpEdges, Patch3DWithThePunchSidesInTheSlaveSurface) {
  for (const auto& [mesh, slaveNodes] :
       {std::pair<std::string, int>{"contact_patch3d_sides.e", 25}, {"contact_patch3d_sides_hex20.e", 65}}) {
    SCOPED_TRACE(mesh);
    ShippedDeck deck = sharpPatchDeck("contact_patch_3d", "contact_patch3d.e", "punch_sides", 0);
    deck.replace(shippedMesh("contact_patch3d.e"), shippedMesh(mesh));
    auto run = runDeckText("sharp_patch_3d_" + mesh.substr(0, mesh.size() - 2), deck.text);
    EXPECT_LT(patch3dError(run), 1e-9 * kDelta);
    if (worldComm()->getRank() != 0) continue;
    const double sigma = kE * kDelta;
    const double current = sigma / ((1 + kNu * kDelta) * (1 + kNu * kDelta));  // per current area
    expectUniformPressure(run, current, slaveNodes, "z", sigma);
  }
}

TEST(SharpEdges, Patch3DWithNormalsAveragedAcrossTheEdgesLosesTheUniformState) {
  ShippedDeck deck = sharpPatchDeck("contact_patch_3d", "contact_patch3d.e", "punch_sides", 180);
  deck.replace(shippedMesh("contact_patch3d.e"), shippedMesh("contact_patch3d_sides.e"));
  EXPECT_GT(relativeErrorOrFailure("sharp_patch_3d_averaged", deck.text, patch3dError), 1e-3);
}

// The pieces on the 3D patch at its reference configuration (the punch's
// bottom on the base's top, slave set = bottom + sides, 4 x 4 bottom faces,
// 3 layers of side faces): which nodes are sharp, which faces make their
// normals, the normals, the search's facing test, and the same choice for a
// node whether a rank examines every slave node or a few.
TEST(SharpEdges, ChoiceNormalsAndFacingTestOnThePatch) {
  using namespace contact;
  auto global = std::make_shared<const mesh::GlobalMesh>(io::readExodus(shippedMesh("contact_patch3d_sides.e")));
  const mesh::Mesh mesh(global, worldComm());
  const ContactInterface c(mesh, "slave, punch_sides", "master");
  const InterfaceConfiguration x = referenceConfiguration(c);
  const double radius = defaultSearchRadius(c, x);
  const SlaveNormalFaces all = chooseSlaveNormalFaces(c, x, 60, radius);
  // Sharp: the 16 nodes around the bottom (4 corners of three faces, 12 on
  // its edges) and the 4 x 3 on the vertical edges above them (two sides
  // at 90 degrees). Facing the base: the 16 around the bottom.
  EXPECT_EQ(all.sharpNodes.size(), 28u);
  EXPECT_EQ(all.facingNodes.size(), 16u);
  const auto normals = computeNodalNormals(c, x, true, nullptr, &all);
  int bottomFacing = 0, verticalEdges = 0;
  for (std::size_t i = 0; i < c.slaveNodes().size(); ++i) {
    const double* X = x.point(c.interfaceNodeIndex(c.slaveNodes()[i]));
    const bool onBottom = std::abs(X[2] - 0.5) < 1e-12;
    const bool onVerticalEdge = (std::abs(X[0]) < 1e-12 || std::abs(X[0] - 1) < 1e-12) &&
                                (std::abs(X[1]) < 1e-12 || std::abs(X[1] - 1) < 1e-12);
    const auto& n = normals[i].n;
    if (onBottom) {
      // Every bottom node points down, the edge and corner nodes as well.
      EXPECT_NEAR(n[2], -1.0, 1e-14) << "node " << c.slaveNodes()[i] + 1;
      bottomFacing += !all.allFaces(static_cast<int>(i));
    } else if (onVerticalEdge) {
      // Above the bottom a vertical edge faces nothing: the two sides' average.
      EXPECT_NEAR(std::abs(n[0]), std::sqrt(0.5), 1e-14);
      EXPECT_NEAR(std::abs(n[1]), std::sqrt(0.5), 1e-14);
      EXPECT_TRUE(all.allFaces(static_cast<int>(i)));
      ++verticalEdges;
    }
    ASSERT_FALSE(normals[i].derivative.empty());
  }
  EXPECT_EQ(bottomFacing, 16);
  EXPECT_EQ(verticalEdges, 12);
  // A rank that examines a few nodes makes the same choice for them.
  const std::vector<int> some{0, 5, 17, static_cast<int>(c.slaveNodes().size()) - 1};
  const SlaveNormalFaces few = chooseSlaveNormalFaces(c, x, 60, radius, &some);
  for (int i : some) {
    const auto& expected = all.allFaces(i) ? std::vector<int>{} : all.faces[static_cast<std::size_t>(i)];
    const auto& got = few.allFaces(i) ? std::vector<int>{} : few.faces[static_cast<std::size_t>(i)];
    EXPECT_EQ(got, expected) << "slave node " << i;
  }
  // The facing test: no side face pairs with the base's top; without it
  // the side faces of the bottom layer find candidates.
  std::vector<int> every(c.slaveFaces().size());
  std::iota(every.begin(), every.end(), 0);
  const SearchResult facing = searchContactPairs(c, x, radius, every, facingNormalDot(60));
  const SearchResult plain = searchContactPairs(c, x, radius, every, facingNormalDot(180));
  int sideFacesWithCandidates = 0, sideFacesWithoutTest = 0;
  for (std::size_t k = 0; k < every.size(); ++k) {
    const auto& f = c.slaveFaces()[static_cast<std::size_t>(every[k])];
    bool side = false;
    for (int a = 0; a < f.numNodes; ++a) side = side || x.point(f.interfaceIndex[a])[2] > 0.5 + 1e-12;
    if (!side) {
      EXPECT_EQ(facing.candidates[k], plain.candidates[k]);  // the bottom keeps every candidate
      continue;
    }
    sideFacesWithCandidates += !facing.candidates[k].empty();
    sideFacesWithoutTest += !plain.candidates[k].empty();
  }
  EXPECT_EQ(sideFacesWithCandidates, 0);
  EXPECT_GT(sideFacesWithoutTest, 0);
}

}  // namespace coulomb::test
