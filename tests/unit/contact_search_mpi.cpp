// Contact interface, gather of the current interface coordinates, nodal normals
// and the R-tree candidate search on partitioned meshes (np = 1, 2, 3): two
// stacked non-matching bodies written by rank 0, and the shipped block meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <set>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "TestSupport.hpp"
#include "TwoBodies.hpp"
#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"
#include "coulomb/contact/interface/InterfaceBalance.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {
namespace {

using contact::ContactFace;
using contact::ContactInterface;
using contact::InterfaceConfiguration;
using contact::SearchResult;


std::unique_ptr<mesh::Mesh> shipped(const std::string& file) {
  auto global = std::make_shared<const mesh::GlobalMesh>(io::readExodus(shippedMesh(file)));
  return std::make_unique<mesh::Mesh>(global, worldComm());
}

// ------------------------------------------------------- brute-force checks

struct Box {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
};

Box boxOf(const ContactFace& f, const InterfaceConfiguration& x) {
  Box b;
  for (int c = 0; c < x.dimension; ++c) b.lo[c] = b.hi[c] = x.point(f.interfaceIndex[0])[c];
  for (int a = 1; a < f.numNodes; ++a)
    for (int c = 0; c < x.dimension; ++c) {
      b.lo[c] = std::min(b.lo[c], x.point(f.interfaceIndex[a])[c]);
      b.hi[c] = std::max(b.hi[c], x.point(f.interfaceIndex[a])[c]);
    }
  return b;
}

/// The documented criterion: on every axis the gap between the plain boxes is <= r.
bool withinRadius(const Box& s, const Box& m, int dim, double r) {
  for (int c = 0; c < dim; ++c)
    if (std::max(m.lo[c] - s.hi[c], s.lo[c] - m.hi[c]) > r) return false;
  return true;
}

/// The projections onto the contact plane (all axes but the last) overlap with positive measure.
bool projectionsOverlap(const Box& s, const Box& m, int dim) {
  for (int c = 0; c + 1 < dim; ++c)
    if (std::min(s.hi[c], m.hi[c]) - std::max(s.lo[c], m.lo[c]) <= 1e-12) return false;
  return true;
}

using PairTest = std::function<bool(const Box&, const Box&)>;

/// Expected candidates of slave face s by a double loop over the master faces.
std::vector<int> bruteForce(const ContactInterface& c, const InterfaceConfiguration& x, int s, const PairTest& test) {
  std::vector<int> found;
  const Box sb = boxOf(c.slaveFaces()[s], x);
  for (std::size_t m = 0; m < c.masterFaces().size(); ++m)
    if (test(sb, boxOf(c.masterFaces()[m], x))) found.push_back(static_cast<int>(m));
  return found;
}

/// Order-independent fingerprint of a pair, from element and side numbers only.
long long pairHash(const ContactFace& s, const ContactFace& m) {
  const unsigned long long a = (s.element + 1) * 1000003ULL + s.side * 31ULL;
  const unsigned long long b = (m.element + 1) * 998244353ULL + m.side * 17ULL;
  return static_cast<long long>(((a * 2654435761ULL) ^ (b * 40503ULL)) % 1000000007ULL);
}

long long globalSumLL(long long local) {
  long long total = 0;
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(total));
  return total;
}

/// Checks the search result on this rank against the brute force and the
/// global pair count and checksum against the brute force over all slave faces
/// (the same at every rank count). Returns the global pair count.
long long checkAgainstBruteForce(const ContactInterface& c, const InterfaceConfiguration& x, const SearchResult& r,
                                 const PairTest& test) {
  EXPECT_EQ(r.slaveFaces, c.ownedSlaveFaces());
  EXPECT_EQ(r.skippedFaces, 0);
  long long localHash = 0;
  for (std::size_t k = 0; k < r.slaveFaces.size(); ++k) {
    const int s = r.slaveFaces[k];
    EXPECT_EQ(r.candidates[k], bruteForce(c, x, s, test)) << "slave face " << s << " (element "
                                                          << c.slaveFaces()[s].element + 1 << ")";
    for (int m : r.candidates[k]) localHash += pairHash(c.slaveFaces()[s], c.masterFaces()[m]);
  }
  long long expectedCount = 0, expectedHash = 0;
  for (std::size_t s = 0; s < c.slaveFaces().size(); ++s)
    for (int m : bruteForce(c, x, static_cast<int>(s), test)) {
      ++expectedCount;
      expectedHash += pairHash(c.slaveFaces()[s], c.masterFaces()[m]);
    }
  const long long count = contact::globalPairCount(r, *worldComm());
  EXPECT_EQ(count, expectedCount);
  EXPECT_EQ(globalSumLL(localHash), expectedHash);
  return count;
}

/// Every slave face is owned (and searched) by exactly one rank, owned faces
/// are faces of the rank's elements, owned slave nodes are owned mesh nodes.
void checkOwnership(const mesh::Mesh& mesh, const ContactInterface& c) {
  const int rank = worldComm()->getRank();
  std::vector<int> owners(c.slaveFaces().size(), 0), total(c.slaveFaces().size(), 0);
  std::set<long long> myElements;
  for (std::size_t b = 0; b < mesh.global().blocks.size(); ++b)
    myElements.insert(mesh.localElements(b).begin(), mesh.localElements(b).end());
  for (int s : c.ownedSlaveFaces()) {
    owners[s] = 1;
    EXPECT_TRUE(myElements.count(c.slaveFaces()[s].element));
  }
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_SUM, static_cast<int>(owners.size()), owners.data(), total.data());
  for (std::size_t s = 0; s < total.size(); ++s) EXPECT_EQ(total[s], 1) << "slave face " << s;
  long long ownedNodes = 0;
  for (int i : c.ownedSlaveNodes()) {
    ++ownedNodes;
    EXPECT_EQ(mesh.nodeOwner(c.slaveNodes()[i]), rank);
  }
  EXPECT_EQ(globalSumLL(ownedNodes), static_cast<long long>(c.slaveNodes().size()));
}

/// A displacement vector on the owned DoF map with u(X) at every owned node.
Teuchos::RCP<Vector> displacement(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                  const std::function<std::array<double, 3>(const double*)>& u) {
  auto v = Teuchos::rcp(new Vector(dofs.ownedMap()));
  const int dim = mesh.dimension();
  for (int i = 0; i < mesh.numOwnedNodes(); ++i) {
    const long long node = mesh.localNodes()[i];
    const std::array<double, 3> value = u(&mesh.global().coordinates[node * dim]);
    for (int c = 0; c < dim; ++c) v->replaceGlobalValue(fem::DofMap::globalDof(node, c, dim), value[c]);
  }
  return v;
}

// ------------------------------------------------------------------- tests

class ContactSearchTwoBodies : public ::testing::TestWithParam<int> {};

TEST_P(ContactSearchTwoBodies, NonMatchingFacesFindTheirOverlappingMasters) {
  const int dim = GetParam();
  const double gap = 0.01;
  const auto mesh = twoBodies(dim, gap, "contact_search");
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  EXPECT_EQ(c.slaveFaces().size(), dim == 3 ? 9u : 3u);
  EXPECT_EQ(c.masterFaces().size(), dim == 3 ? 16u : 4u);
  EXPECT_EQ(c.slaveNodes().size(), dim == 3 ? 16u : 4u);
  EXPECT_EQ(c.interfaceNodes().size(), dim == 3 ? 16u + 25u : 4u + 5u);
  checkOwnership(*mesh, c);

  const InterfaceConfiguration x = contact::referenceConfiguration(c);
  // r = 0.05 > gap, below the lateral distance 1/12 between non-overlapping neighbours:
  // the candidates are exactly the masters whose projections overlap the slave face.
  const SearchResult r = contact::searchContactPairs(c, x, 0.05);
  const long long pairs = checkAgainstBruteForce(
      c, x, r, [dim](const Box& s, const Box& m) { return projectionsOverlap(s, m, dim); });
  EXPECT_EQ(pairs, dim == 3 ? 36 : 6);  // each third overlaps two quarters per direction
  checkAgainstBruteForce(c, x, r, [dim](const Box& s, const Box& m) { return withinRadius(s, m, dim, 0.05); });

  // Default radius: the largest slave face diameter (3D: face diagonal sqrt(2)/3).
  const double radius = contact::defaultSearchRadius(c, x);
  EXPECT_NEAR(radius, dim == 3 ? std::sqrt(2.0) / 3.0 : 1.0 / 3.0, 1e-12);
  const SearchResult wide = contact::searchContactPairs(c, x, radius);
  const long long widePairs = checkAgainstBruteForce(
      c, x, wide, [dim, radius](const Box& s, const Box& m) { return withinRadius(s, m, dim, radius); });
  EXPECT_GT(widePairs, pairs);
  EXPECT_EQ(wide.radius, radius);

  // Slave normals point from the slave (upper) body down to the master.
  for (const auto& n : contact::computeNodalNormals(c, x, false)) {
    EXPECT_NEAR(n.n[dim - 1], -1.0, 1e-14);
    EXPECT_NEAR(n.n[0], 0.0, 1e-14);
  }
}

TEST_P(ContactSearchTwoBodies, GapLargerThanTheRadiusFindsNothing) {
  const int dim = GetParam();
  const auto mesh = twoBodies(dim, 0.2, "contact_search");
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  const InterfaceConfiguration x = contact::referenceConfiguration(c);
  const SearchResult r = contact::searchContactPairs(c, x, 0.15);
  EXPECT_EQ(contact::globalPairCount(r, *worldComm()), 0);
  for (const auto& list : r.candidates) EXPECT_TRUE(list.empty());
  EXPECT_EQ(r.unpairedDepth, 0.0);  // the slave body is in front of the master
  // ... and everything on the contact plane once the radius covers the gap.
  const SearchResult all = contact::searchContactPairs(c, x, 0.25);
  checkAgainstBruteForce(c, x, all, [dim](const Box& s, const Box& m) { return withinRadius(s, m, dim, 0.25); });
}

// Bodies overlapping by 0.2 (the slave plane 0.2 below the master plane):
// with a radius 0.15 no face has a candidate, and the search reports the
// slave nodes inside the master at the depth 0.2 (every rank's share; the
// maximum over ranks is 0.2 on every slave node).
TEST_P(ContactSearchTwoBodies, OverlapBeyondTheRadiusGivesItsDepth) {
  const int dim = GetParam();
  const auto mesh = twoBodies(dim, -0.2, "contact_search");
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  const InterfaceConfiguration x = contact::referenceConfiguration(c);
  const SearchResult r = contact::searchContactPairs(c, x, 0.15);
  EXPECT_EQ(contact::globalPairCount(r, *worldComm()), 0);
  double depth = 0;
  Teuchos::reduceAll(*worldComm(), Teuchos::REDUCE_MAX, r.unpairedDepth, Teuchos::outArg(depth));
  EXPECT_NEAR(depth, 0.2, 1e-14);
  if (!r.slaveFaces.empty()) {
    EXPECT_NEAR(r.unpairedDepth, 0.2, 1e-14);
    EXPECT_GE(c.slaveNodeIndex(r.unpairedNode), 0);
  }
}

TEST_P(ContactSearchTwoBodies, PairsFollowTheCurrentConfiguration) {
  const int dim = GetParam();
  const auto mesh = twoBodies(dim, 0.01, "contact_search");
  const fem::DofMap dofs(*mesh);
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  const contact::InterfaceGather gather(c, dofs.ownedMap());
  const int v = dim - 1;
  const double r = 0.05;

  // Rigid translations: upper by (0.3, 0.1[, 0]), lower by (-0.05, 0.02[, 0]).
  auto shift = [v](double up0, double up1, double lo0, double lo1) {
    return [=](const double* X) {
      std::array<double, 3> u{0.0, 0.0, 0.0};
      const bool upper = X[v] > 0.005;
      u[0] = upper ? up0 : lo0;
      if (v == 2) u[1] = upper ? up1 : lo1;
      return u;
    };
  };
  const auto u = displacement(*mesh, dofs, shift(0.3, 0.1, -0.05, 0.02));
  const InterfaceConfiguration x = gather.gather(*u);
  // the gathered configuration is X + u at every interface node, on every rank
  double worst = 0.0;
  for (std::size_t i = 0; i < c.interfaceNodes().size(); ++i) {
    const double* X = &mesh->global().coordinates[c.interfaceNodes()[i] * dim];
    const auto expected = shift(0.3, 0.1, -0.05, 0.02)(X);
    for (int k = 0; k < dim; ++k) worst = std::max(worst, std::abs(x.point(static_cast<int>(i))[k] - (X[k] + expected[k])));
  }
  EXPECT_EQ(globalMax(worst), 0.0);

  const SearchResult moved = contact::searchContactPairs(c, x, r);
  checkAgainstBruteForce(c, x, moved, [dim, r](const Box& s, const Box& m) { return withinRadius(s, m, dim, r); });
  // Sanity of the test: the expected pairs of the shifted bodies differ from the
  // reference ones, so a search on X instead of X + u would fail above.
  const InterfaceConfiguration X0 = contact::referenceConfiguration(c);
  bool differs = false;
  for (std::size_t s = 0; s < c.slaveFaces().size(); ++s) {
    const auto test = [dim, r](const Box& a, const Box& b) { return withinRadius(a, b, dim, r); };
    differs = differs || bruteForce(c, x, static_cast<int>(s), test) != bruteForce(c, X0, static_cast<int>(s), test);
  }
  EXPECT_TRUE(differs);
  // The upper body lifted by 0.3: out of reach.
  const auto lifted = displacement(*mesh, dofs, [v](const double* X) {
    std::array<double, 3> u{0.0, 0.0, 0.0};
    if (X[v] > 0.005) u[v] = 0.3;
    return u;
  });
  EXPECT_EQ(contact::globalPairCount(contact::searchContactPairs(c, gather.gather(*lifted), r), *worldComm()), 0);
  // Pushed down into the master by 0.02 (penetration): still the overlap pairs.
  const auto pushed = displacement(*mesh, dofs, [v](const double* X) {
    std::array<double, 3> u{0.0, 0.0, 0.0};
    if (X[v] > 0.005) u[v] = -0.03;
    return u;
  });
  const InterfaceConfiguration xp = gather.gather(*pushed);
  checkAgainstBruteForce(c, xp, contact::searchContactPairs(c, xp, r),
                         [dim](const Box& s, const Box& m) { return projectionsOverlap(s, m, dim); });
}

TEST_P(ContactSearchTwoBodies, NormalsRotateWithTheSlaveBody) {
  const int dim = GetParam();
  const auto mesh = twoBodies(dim, 0.01, "contact_search");
  const fem::DofMap dofs(*mesh);
  const ContactInterface c(*mesh, "upper_bottom", "lower_top");
  const contact::InterfaceGather gather(c, dofs.ownedMap());
  const int v = dim - 1;
  // Rotation of the upper body by 0.3 rad in the (x, vertical) plane about its centre.
  const double a = 0.3, co = std::cos(a), si = std::sin(a);
  const double cx = 0.5, cv = 0.01 + 0.25;
  const auto u = displacement(*mesh, dofs, [&](const double* X) {
    std::array<double, 3> w{0.0, 0.0, 0.0};
    if (X[v] > 0.005) {
      const double px = X[0] - cx, pv = X[v] - cv;
      w[0] = co * px - si * pv + cx - X[0];
      w[v] = si * px + co * pv + cv - X[v];
    }
    return w;
  });
  const InterfaceConfiguration x = gather.gather(*u);
  // (0, -1) rotated: (si, -co) in the (x, vertical) plane.
  double worst = 0.0;
  const std::vector<int> nodes = contact::slaveNodesOfFaces(c, c.ownedSlaveFaces());
  const auto normals = contact::computeNodalNormals(c, x, true, &nodes);
  for (int i : nodes) {
    worst = std::max(worst, std::abs(normals[i].n[0] - si));
    worst = std::max(worst, std::abs(normals[i].n[v] + co));
    if (dim == 3) worst = std::max(worst, std::abs(normals[i].n[1]));
    // derivative columns only for nodes of the slave faces around the node
    for (const auto& d : normals[i].derivative) EXPECT_GE(c.slaveNodeIndex(d.node), 0);
    EXPECT_FALSE(normals[i].derivative.empty());
  }
  EXPECT_LT(globalMax(worst), 1e-13);
}

INSTANTIATE_TEST_SUITE_P(ContactSearch, ContactSearchTwoBodies, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

struct ShippedCase {
  const char* file;
  int dimension;
  std::size_t faces;  // per side (0: not checked, unstructured mesh)
  std::size_t nodes;  // per side (0: not checked)
  double area;        // of each side (2D: length)
};

/// Measure of a plane face: Line2 length, Tri3 / Quad4 area.
double faceMeasure(const ContactFace& f, const InterfaceConfiguration& x) {
  auto p = [&](int a, int c) { return x.point(f.interfaceIndex[a])[c]; };
  if (f.numNodes == 2) return std::hypot(p(1, 0) - p(0, 0), p(1, 1) - p(0, 1));
  // half the cross product of the diagonals (Quad4) or of two edges (Tri3)
  const int a0 = 0, a1 = f.numNodes == 4 ? 2 : 1, b0 = f.numNodes == 4 ? 1 : 0, b1 = f.numNodes == 4 ? 3 : 2;
  double u[3], v[3];
  for (int c = 0; c < 3; ++c) u[c] = p(a1, c) - p(a0, c), v[c] = p(b1, c) - p(b0, c);
  return 0.5 * std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) + std::pow(u[2] * v[0] - u[0] * v[2], 2) +
                         std::pow(u[0] * v[1] - u[1] * v[0], 2));
}

void PrintTo(const ShippedCase& c, std::ostream* out) { *out << c.file; }

class ContactSearchShipped : public ::testing::TestWithParam<ShippedCase> {};

TEST_P(ContactSearchShipped, OppositeSidesOfABlock) {
  const ShippedCase sc = GetParam();
  const auto mesh = shipped(sc.file);
  const ContactInterface c(*mesh, "bottom", "top");
  if (sc.faces) {
    EXPECT_EQ(c.slaveFaces().size(), sc.faces);
    EXPECT_EQ(c.masterFaces().size(), sc.faces);
    EXPECT_EQ(c.slaveNodes().size(), sc.nodes);
  }
  checkOwnership(*mesh, c);
  const InterfaceConfiguration x = contact::referenceConfiguration(c);
  double slaveArea = 0.0, masterArea = 0.0;
  for (const auto& f : c.slaveFaces()) slaveArea += faceMeasure(f, x);
  for (const auto& f : c.masterFaces()) masterArea += faceMeasure(f, x);
  EXPECT_NEAR(slaveArea, sc.area, 1e-12);
  EXPECT_NEAR(masterArea, sc.area, 1e-12);
  // Outward orientation of the shipped cell types' sides (bottom: -y / -z).
  for (const auto& n : contact::computeNodalNormals(c, x, false)) {
    for (int i = 0; i < sc.dimension; ++i) EXPECT_NEAR(n.n[i], i == sc.dimension - 1 ? -1.0 : 0.0, 1e-14);
  }
  // The sides are 1 apart, the blocks at most 2 wide. Slave faces and master
  // faces sit on different ranks at np >= 2: pairs across ranks need no communication.
  EXPECT_EQ(contact::globalPairCount(contact::searchContactPairs(c, x, 0.9), *worldComm()), 0);
  const SearchResult all = contact::searchContactPairs(c, x, 2.1);
  const long long numFaces = static_cast<long long>(c.slaveFaces().size());
  EXPECT_EQ(contact::globalPairCount(all, *worldComm()), numFaces * static_cast<long long>(c.masterFaces().size()));
  const int dim = sc.dimension;
  checkAgainstBruteForce(c, x, all, [dim](const Box& s, const Box& m) { return withinRadius(s, m, dim, 2.1); });
  // at np >= 2 some pairs join faces of elements owned by different ranks
  long long crossRank = 0;
  for (std::size_t k = 0; k < all.slaveFaces.size(); ++k)
    for (int m : all.candidates[k]) crossRank += c.slaveFaces()[all.slaveFaces[k]].owner != c.masterFaces()[m].owner;
  if (worldComm()->getSize() > 1) EXPECT_GT(globalSumLL(crossRank), 0);
  const SearchResult some = contact::searchContactPairs(c, x, 1.2);
  checkAgainstBruteForce(c, x, some, [dim](const Box& s, const Box& m) { return withinRadius(s, m, dim, 1.2); });
}

INSTANTIATE_TEST_SUITE_P(ContactSearch, ContactSearchShipped,
                         ::testing::Values(ShippedCase{"block2d.e", 2, 16, 17, 2.0},
                                           ShippedCase{"block2d_tri.e", 2, 8, 9, 2.0},
                                           ShippedCase{"block3d.e", 3, 64, 81, 1.0},
                                           ShippedCase{"block3d_tet.e", 3, 0, 0, 1.0}),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           return n.substr(0, n.find('.'));
                         });

void expectErrorMentioning(const std::function<void()>& f, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "expected coulomb::Error mentioning '" << text << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(ContactSearchBadInput, UnknownSameOrEmptySideSets) {
  const auto mesh = shipped("block3d.e");
  expectErrorMentioning([&] { ContactInterface probe(*mesh, "nosuch", "top", "Contact/punch"); }, "nosuch");
  expectErrorMentioning([&] { ContactInterface probe(*mesh, "bottom", "nosuch_master"); }, "nosuch_master");
  // A set in both lists when the lists differ (the same list is a
  // self-contact surface: under its name and its id alias too).
  expectErrorMentioning([&] { ContactInterface probe(*mesh, "top", "top, bottom"); }, "same set");
  EXPECT_TRUE(ContactInterface(*mesh, "top", "top").selfContact());
  int topId = -1;
  for (const auto& set : mesh->global().sideSets)
    if (set.name == "top") topId = set.id;
  ASSERT_GE(topId, 0);
  EXPECT_TRUE(ContactInterface(*mesh, "top", "sideset_" + std::to_string(topId)).selfContact());
  expectErrorMentioning([&] { ContactInterface probe(*mesh, "bottom, top", "sideset_" + std::to_string(topId)); }, "top");
  // an empty side set
  auto global = std::make_shared<mesh::GlobalMesh>(mesh->global());
  mesh::SideSet empty;
  empty.name = "nothing";
  empty.id = 99;
  global->sideSets.push_back(empty);
  const mesh::Mesh withEmpty(global, worldComm());
  expectErrorMentioning([&] { ContactInterface probe(withEmpty, "nothing", "top"); }, "'nothing' is empty");
  expectErrorMentioning([&] { ContactInterface probe(withEmpty, "top", "nothing"); }, "'nothing' is empty");
  // a negative radius
  const ContactInterface c(*mesh, "bottom", "top");
  EXPECT_THROW(contact::searchContactPairs(c, contact::referenceConfiguration(c), -1.0), Error);
}

}  // namespace
}  // namespace coulomb::test
