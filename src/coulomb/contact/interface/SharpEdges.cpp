/// @file SharpEdges.cpp
/// @brief Feature groups at sharp slave nodes and the group facing the master (see the header).
#include "coulomb/contact/interface/SharpEdges.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "coulomb/contact/interface/FaceBoxTree.hpp"
#include "coulomb/contact/interface/FaceProximity.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

using namespace facebox;
using Vec = std::array<double, 3>;

/// Groups within this much of the best score are taken together (a node
/// between two equally facing groups keeps both rather than a round-off pick).
constexpr double kScoreTie = 1e-3;
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool normalize(Vec& v) {
  const double length = std::sqrt(dot(v, v));
  if (!(length > 0.0) || !std::isfinite(length)) return false;
  for (double& c : v) c /= length;
  return true;
}

}  // namespace

std::vector<int> featureGroups(const std::vector<Vec>& normals, double featureAngle) {
  const std::size_t n = normals.size();
  const double cosLimit = std::cos(featureAngle);
  // Union-find over the pairs within the angle; then numbered by first member.
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&](std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      if (dot(normals[a], normals[b]) >= cosLimit) parent[root(b)] = root(a);
  std::vector<int> group(n, -1), label(n, -1);
  int next = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t r = root(a);
    if (label[r] < 0) label[r] = next++;
    group[a] = label[r];
  }
  return group;
}

double facingNormalDot(double featureAngleDegrees) {
  return featureAngleDegrees < 180.0 ? -std::cos(featureAngleDegrees * kRadiansPerDegree) : 1.0;
}

std::vector<int> facingGroups(const std::vector<Vec>& groupNormals, const std::vector<Vec>& masterNormals,
                              double minimumScore) {
  std::vector<double> score(groupNormals.size(), -2.0);
  double best = -2.0;
  for (std::size_t g = 0; g < groupNormals.size(); ++g) {
    for (const Vec& m : masterNormals) score[g] = std::max(score[g], -dot(groupNormals[g], m));
    best = std::max(best, score[g]);
  }
  std::vector<int> facing;
  if (!(best >= minimumScore)) return facing;
  for (std::size_t g = 0; g < groupNormals.size(); ++g)
    if (score[g] >= best - kScoreTie) facing.push_back(static_cast<int>(g));
  return facing;
}

SlaveNormalFaces chooseSlaveNormalFaces(const ContactInterface& contact, const InterfaceConfiguration& x,
                                        double featureAngleDegrees, double radius,
                                        const std::vector<int>* slaveNodeIndices) {
  SlaveNormalFaces result;
  if (!(featureAngleDegrees < 180.0)) return result;
  const int dim = contact.dimension();
  const auto& offset = contact.slaveNodeFaceOffsets();
  const auto& slaveNodes = contact.slaveNodes();
  const double featureAngle = featureAngleDegrees * kRadiansPerDegree;

  // 1. Feature groups of the examined nodes; the sharp ones are kept.
  struct Sharp {
    int node;                  // slave node index
    std::vector<int> group;    // group of each face around it
    std::vector<Vec> normals;  // averaged normal of each group
  };
  std::vector<Sharp> sharp;
  std::vector<Vec> corner;
  auto examine = [&](int i) {
    corner.clear();
    for (int k = offset[i]; k < offset[i + 1]; ++k) {
      try {
        corner.push_back(averagedNormal(dim, {faceAtNode(contact, x, k)}, false).n);
      } catch (const Error&) {
        return;  // a degenerate face: the plain average, which reports it (computeNodalNormals)
      }
    }
    std::vector<int> group = featureGroups(corner, featureAngle);
    const int groups = group.empty() ? 0 : *std::max_element(group.begin(), group.end()) + 1;
    if (groups < 2) return;
    Sharp s{i, std::move(group), std::vector<Vec>(groups, Vec{0.0, 0.0, 0.0})};
    for (std::size_t k = 0; k < corner.size(); ++k)
      for (int c = 0; c < 3; ++c) s.normals[s.group[k]][c] += corner[k][c];
    for (Vec& n : s.normals)
      if (!normalize(n)) return;  // the group's normals cancel: left to NodalNormals
    sharp.push_back(std::move(s));
  };
  if (slaveNodeIndices) {
    for (int i : *slaveNodeIndices) examine(i);
  } else {
    for (std::size_t i = 0; i < slaveNodes.size(); ++i) examine(static_cast<int>(i));
  }
  if (sharp.empty()) return result;

  // 2. The master faces near each sharp node, through an R-tree of their boxes.
  const auto& masters = contact.masterFaces();
  std::vector<Entry> entries;
  std::vector<Vec> masterNormal(masters.size());
  std::vector<std::array<Vec, 4>> masterCorners(masters.size());
  std::vector<int> masterCount(masters.size(), 0);
  for (std::size_t m = 0; m < masters.size(); ++m) {
    masterCorners[m] = faceCorners(masters[m], x);
    masterCount[m] = mesh::numCorners(masters[m].type);
    const bool finite = std::all_of(masterCorners[m].begin(), masterCorners[m].end(), [](const Vec& p) {
      return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    });
    if (!finite) continue;
    if (!faceOutwardNormal(dim, masterCount[m], masterCorners[m], masterNormal[m])) continue;
    Vec lo = masterCorners[m][0], hi = masterCorners[m][0];
    for (int a = 1; a < masterCount[m]; ++a)
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], masterCorners[m][a][c]);
        hi[c] = std::max(hi[c], masterCorners[m][a][c]);
      }
    entries.emplace_back(Box(Point(lo[0], lo[1], lo[2]), Point(hi[0], hi[1], hi[2])), static_cast<int>(m));
  }
  const Tree tree(entries.begin(), entries.end());

  result.faces.assign(slaveNodes.size(), {});
  std::vector<Entry> near;
  std::vector<Vec> nearNormals;
  for (const Sharp& s : sharp) {
    const long long node = slaveNodes[s.node];
    result.sharpNodes.push_back(node);
    const double* p = x.point(contact.interfaceNodeIndex(node));
    const Vec at{p[0], p[1], dim == 3 ? p[2] : 0.0};
    near.clear();
    tree.query(bgi::intersects(Box(Point(at[0] - radius, at[1] - radius, at[2] - radius),
                                   Point(at[0] + radius, at[1] + radius, at[2] + radius))),
               std::back_inserter(near));
    nearNormals.clear();
    for (const Entry& e : near) {
      const ContactFace& m = masters[e.second];
      if (contact.selfContact() && std::find(m.nodes.begin(), m.nodes.begin() + m.numNodes, node) !=
                                       m.nodes.begin() + m.numNodes)
        continue;
      if (faceProximity(dim, masterCount[e.second], masterCorners[e.second], at).distance > radius) continue;
      nearNormals.push_back(masterNormal[e.second]);
    }
    const std::vector<int> facing = facingGroups(s.normals, nearNormals, std::cos(featureAngle));
    if (facing.empty()) continue;
    std::vector<int>& chosen = result.faces[s.node];
    for (std::size_t k = 0; k < s.group.size(); ++k)
      if (std::find(facing.begin(), facing.end(), s.group[k]) != facing.end()) chosen.push_back(static_cast<int>(k));
    if (chosen.size() == s.group.size()) chosen.clear();  // every group faces: the plain average
    else result.facingNodes.push_back(node);
  }
  std::sort(result.sharpNodes.begin(), result.sharpNodes.end());
  std::sort(result.facingNodes.begin(), result.facingNodes.end());
  return result;
}

}  // namespace coulomb::contact
