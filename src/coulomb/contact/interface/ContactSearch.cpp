/// @file ContactSearch.cpp
/// @brief Bounding-box R-tree search of candidate contact pairs (see the header).
#include "coulomb/contact/interface/ContactSearch.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include <Teuchos_CommHelpers.hpp>

#include "coulomb/contact/interface/FaceBoxTree.hpp"
#include "coulomb/contact/interface/FaceProximity.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using namespace facebox;

/// Bounding box of a face enlarged by `margin` on every side (2D: z = 0);
/// false if a coordinate is not finite.
bool enlargedBox(const ContactFace& face, const InterfaceConfiguration& x, double margin, Box& box) {
  const int dim = x.dimension;
  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
  for (int c = 0; c < dim; ++c) lo[c] = hi[c] = x.point(face.interfaceIndex[0])[c];
  for (int a = 0; a < face.numNodes; ++a) {
    const double* p = x.point(face.interfaceIndex[a]);
    for (int c = 0; c < dim; ++c) {
      if (!std::isfinite(p[c])) return false;
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  }
  for (int c = 0; c < dim; ++c) {
    lo[c] -= margin;
    hi[c] += margin;
  }
  box = Box(Point(lo[0], lo[1], lo[2]), Point(hi[0], hi[1], hi[2]));
  return true;
}

void requireRadius(double value, const char* what) {
  COULOMB_REQUIRE(std::isfinite(value) && value >= 0.0,
                  "contact search: the " << what << " must be finite and >= 0, got " << value);
}

/// A slave face with no candidate: are its nodes inside the master body,
/// deeper than the radius reaches? For each node, the nearest master face
/// (R-tree nearest query in increasing box distance, stopped once a box is
/// farther than the best exact distance: the enlarged box contains its face,
/// so no later face can be nearer); a node behind that face with its
/// projection on it is inside, at the depth -normalDistance.
template <typename Tree>
void recordUnpairedDepth(const ContactInterface& contact, const InterfaceConfiguration& x, const Tree& tree,
                         const ContactFace& slave, SearchResult& result) {
  const auto& masters = contact.masterFaces();
  for (int a = 0; a < slave.numNodes; ++a) {
    const double* p = x.point(slave.interfaceIndex[a]);
    const std::array<double, 3> point{p[0], p[1], x.dimension == 3 ? p[2] : 0.0};
    const Point query(point[0], point[1], point[2]);
    double best = std::numeric_limits<double>::infinity();
    FaceProximity nearest;
    for (auto it = tree.qbegin(bgi::nearest(query, static_cast<unsigned>(tree.size()))); it != tree.qend(); ++it) {
      if (bg::distance(query, it->first) > best) break;
      const ContactFace& master = masters[it->second];
      const FaceProximity near = faceProximity(x.dimension, mesh::numCorners(master.type), faceCorners(master, x), point);
      if (near.distance < best) {
        best = near.distance;
        nearest = near;
      }
    }
    if (nearest.overFace && nearest.normalDistance < 0.0 && -nearest.normalDistance > result.unpairedDepth) {
      result.unpairedDepth = -nearest.normalDistance;
      result.unpairedNode = slave.nodes[a];
    }
  }
}

}  // namespace

double defaultSearchRadius(const ContactInterface& contact, const InterfaceConfiguration& x, double factor) {
  requireRadius(factor, "search radius factor");
  const int dim = x.dimension;
  double diameter = 0.0;
  for (const ContactFace& face : contact.slaveFaces())
    for (int a = 0; a < face.numNodes; ++a)
      for (int b = a + 1; b < face.numNodes; ++b) {
        const double* p = x.point(face.interfaceIndex[a]);
        const double* q = x.point(face.interfaceIndex[b]);
        double d2 = 0.0;
        for (int c = 0; c < dim; ++c) d2 += (p[c] - q[c]) * (p[c] - q[c]);
        if (std::isfinite(d2)) diameter = std::max(diameter, std::sqrt(d2));
      }
  return factor * diameter;
}

long long SearchResult::numLocalPairs() const {
  long long n = 0;
  for (const auto& c : candidates) n += static_cast<long long>(c.size());
  return n;
}

SearchResult searchContactPairs(const ContactInterface& contact, const InterfaceConfiguration& x, double radius) {
  return searchContactPairs(contact, x, radius, contact.ownedSlaveFaces());
}

SearchResult searchContactPairs(const ContactInterface& contact, const InterfaceConfiguration& x, double radius,
                                const std::vector<int>& slaveFaces, double maximumNormalDot) {
  requireRadius(radius, "search radius");
  COULOMB_CHECK(x.dimension == contact.dimension() &&
                      x.x.size() == contact.interfaceNodes().size() * static_cast<std::size_t>(x.dimension),
                  "interface configuration does not match the contact interface");
  const double margin = 0.5 * radius;
  SearchResult result;
  result.radius = radius;
  result.slaveFaces = slaveFaces;
  result.candidates.resize(slaveFaces.size());

  const auto& masters = contact.masterFaces();
  std::vector<Entry> entries;
  entries.reserve(masters.size());
  // The facing test's master normals (a degenerate face passes it: the
  // mortar kernel reports it).
  const bool facingTest = maximumNormalDot < 1.0;
  std::vector<std::array<double, 3>> masterNormal(facingTest ? masters.size() : 0);
  std::vector<char> masterNormalValid(masterNormal.size(), 0);
  for (std::size_t m = 0; m < masters.size(); ++m) {
    Box box;
    if (enlargedBox(masters[m], x, margin, box))
      entries.emplace_back(box, static_cast<int>(m));
    else
      ++result.skippedFaces;
    if (facingTest)
      masterNormalValid[m] =
          faceOutwardNormal(x.dimension, mesh::numCorners(masters[m].type), faceCorners(masters[m], x), masterNormal[m]);
  }
  // Range constructor: bulk loading by packing (better tree than insertion).
  const Tree tree(entries.begin(), entries.end());

  const auto& slaves = contact.slaveFaces();
  std::vector<Entry> hits;
  for (std::size_t k = 0; k < slaveFaces.size(); ++k) {
    const int s = slaveFaces[k];
    COULOMB_CHECK(s >= 0 && static_cast<std::size_t>(s) < slaves.size(), "slave face index " << s);
    Box box;
    if (!enlargedBox(slaves[s], x, margin, box)) {
      ++result.skippedFaces;
      continue;
    }
    hits.clear();
    tree.query(bgi::intersects(box), std::back_inserter(hits));
    std::vector<int>& found = result.candidates[k];
    found.reserve(hits.size());
    std::array<double, 3> normal{};
    const bool slaveNormalValid =
        facingTest && faceOutwardNormal(x.dimension, mesh::numCorners(slaves[s].type), faceCorners(slaves[s], x), normal);
    for (const Entry& hit : hits) {
      const int m = hit.second;
      if (slaveNormalValid && masterNormalValid[m] &&
          normal[0] * masterNormal[m][0] + normal[1] * masterNormal[m][1] + normal[2] * masterNormal[m][2] >
              maximumNormalDot)
        continue;  // the faces do not face each other
      found.push_back(m);
    }
    std::sort(found.begin(), found.end());
    // Only a face with no master face in reach: one whose candidates all
    // failed the facing test (a block's side beside a flat master) is near
    // the master, not inside it.
    if (hits.empty()) recordUnpairedDepth(contact, x, tree, slaves[s], result);
  }
  return result;
}

long long globalPairCount(const SearchResult& result, const Teuchos::Comm<int>& comm) {
  const long long local = result.numLocalPairs();
  long long total = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(total));
  return total;
}

}  // namespace coulomb::contact
