/// @file SelfContactRoles.cpp
/// @brief Slave / master roles on a self-contact surface (see the header).
#include "coulomb/contact/interface/SelfContactRoles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace coulomb::contact {
namespace {

/// Centre, unit outward normal and diameter of a face from its corners.
struct FacePlane {
  std::array<double, 3> centre{}, normal{};
  double diameter = 0;
};

FacePlane facePlane(int dim, const ContactFace& face, const InterfaceConfiguration& x) {
  const int corners = mesh::numCorners(face.type);
  std::array<std::array<double, 3>, 4> p{};
  FacePlane f;
  for (int a = 0; a < corners; ++a)
    for (int c = 0; c < dim; ++c) {
      p[a][c] = x.point(face.interfaceIndex[a])[c];
      f.centre[c] += p[a][c] / corners;
    }
  for (int a = 0; a < corners; ++a)
    for (int b = a + 1; b < corners; ++b) {
      double d2 = 0;
      for (int c = 0; c < dim; ++c) d2 += (p[a][c] - p[b][c]) * (p[a][c] - p[b][c]);
      f.diameter = std::max(f.diameter, std::sqrt(d2));
    }
  if (dim == 2) {
    // (dy, -dx) points out of the element (ContactInterface.hpp).
    f.normal = {p[1][1] - p[0][1], p[0][0] - p[1][0], 0.0};
  } else {
    // Right-hand rule over the corners: (x2 - x0) x (x3 - x1) for a
    // quadrilateral, (x1 - x0) x (x2 - x0) for a triangle.
    const auto& a0 = p[0];
    const auto& a1 = corners == 4 ? p[2] : p[1];
    const auto& b0 = corners == 4 ? p[1] : p[0];
    const auto& b1 = corners == 4 ? p[3] : p[2];
    const std::array<double, 3> u{a1[0] - a0[0], a1[1] - a0[1], a1[2] - a0[2]};
    const std::array<double, 3> v{b1[0] - b0[0], b1[1] - b0[1], b1[2] - b0[2]};
    f.normal = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  }
  const double length = std::sqrt(f.normal[0] * f.normal[0] + f.normal[1] * f.normal[1] + f.normal[2] * f.normal[2]);
  if (length > 0)
    for (double& c : f.normal) c /= length;
  return f;
}

bool sharesNodeWith(const ContactFace& a, const ContactFace& b) {
  for (int i = 0; i < a.numNodes; ++i)
    for (int j = 0; j < b.numNodes; ++j)
      if (a.nodes[i] == b.nodes[j]) return true;
  return false;
}

/// Union-find root with path halving.
int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

bool selfContactFacesFaceEachOther(int dim, const ContactFace& a, const ContactFace& b,
                                   const InterfaceConfiguration& x) {
  if (sharesNodeWith(a, b)) return false;
  const FacePlane pa = facePlane(dim, a, x), pb = facePlane(dim, b, x);
  double opposing = 0, aheadOfA = 0, aheadOfB = 0;
  for (int c = 0; c < dim; ++c) {
    opposing += pa.normal[c] * pb.normal[c];
    aheadOfA += (pb.centre[c] - pa.centre[c]) * pa.normal[c];
    aheadOfB += (pa.centre[c] - pb.centre[c]) * pb.normal[c];
  }
  return opposing < -kSelfContactOpposing && aheadOfA >= -kSelfContactBehind * pa.diameter &&
         aheadOfB >= -kSelfContactBehind * pb.diameter;
}

SelfContactRoles decideSelfContactRoles(const std::vector<ContactFace>& faces,
                                        std::vector<std::pair<int, int>> links) {
  const int n = static_cast<int>(faces.size());
  SelfContactRoles out;
  out.role.assign(faces.size(), SelfContactRole::None);
  for (auto& link : links)
    if (link.first > link.second) std::swap(link.first, link.second);
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  // Zones: linked faces joined through shared nodes.
  std::vector<char> linked(faces.size(), 0);
  for (const auto& [a, b] : links) linked[a] = linked[b] = 1;
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<long long, int> firstFaceOfNode;
  for (int f = 0; f < n; ++f) {
    if (!linked[f]) continue;
    for (int a = 0; a < faces[f].numNodes; ++a) {
      const auto [it, inserted] = firstFaceOfNode.emplace(faces[f].nodes[a], f);
      if (!inserted) {
        // The lower face index becomes the root: a zone is named by its lowest face.
        const int r1 = root(parent, f), r2 = root(parent, it->second);
        parent[std::max(r1, r2)] = std::min(r1, r2);
      }
    }
  }
  // Zone graph, coloured breadth-first from the lowest-named zone of each group.
  std::map<int, std::vector<int>> neighbours;
  for (const auto& [a, b] : links) {
    const int za = root(parent, a), zb = root(parent, b);
    if (za == zb) continue;
    neighbours[za].push_back(zb);
    neighbours[zb].push_back(za);
  }
  std::map<int, int> colour;
  for (const auto& [zone, unused] : neighbours) {
    if (colour.count(zone)) continue;
    colour[zone] = 0;
    std::vector<int> queue{zone};
    for (std::size_t head = 0; head < queue.size(); ++head)
      for (int next : neighbours[queue[head]])
        if (!colour.count(next)) {
          colour[next] = 1 - colour[queue[head]];
          queue.push_back(next);
        }
  }
  for (const auto& [a, b] : links) {
    const int za = root(parent, a), zb = root(parent, b);
    if (za == zb || colour[za] == colour[zb]) {
      ++out.droppedLinks;
      continue;
    }
    for (int f : {a, b}) out.role[f] = colour[root(parent, f)] == 0 ? SelfContactRole::Slave : SelfContactRole::Master;
  }
  // A zone's faces whose links were all dropped take its role too: a slave
  // region is the whole zone, so the D of its nodes is complete. (Faces of
  // two zones never share a node, or they would be one zone: no node is on
  // a slave and a master face.)
  for (int f = 0; f < n; ++f)
    if (linked[f] && out.role[f] == SelfContactRole::None) {
      const auto it = colour.find(root(parent, f));
      if (it != colour.end()) out.role[f] = it->second == 0 ? SelfContactRole::Slave : SelfContactRole::Master;
    }
  return out;
}

SelfContactRoles restrictToSelfContactRoles(const ContactInterface& contact, const InterfaceConfiguration& startX,
                                            const InterfaceConfiguration& x, SearchResult& search) {
  const int dim = contact.dimension();
  const auto& faces = contact.slaveFaces();
  std::vector<int> all(faces.size());
  std::iota(all.begin(), all.end(), 0);
  // The links of both configurations (see the header).
  std::vector<std::pair<int, int>> links;
  for (const InterfaceConfiguration* config : {&startX, &x}) {
    const SearchResult everything = searchContactPairs(contact, *config, search.radius, all);
    for (std::size_t k = 0; k < everything.slaveFaces.size(); ++k) {
      const int a = everything.slaveFaces[k];
      for (int b : everything.candidates[k])
        if (a < b && selfContactFacesFaceEachOther(dim, faces[a], faces[b], *config)) links.emplace_back(a, b);
    }
  }
  SelfContactRoles roles = decideSelfContactRoles(faces, links);
  SearchResult kept;
  kept.radius = search.radius;
  kept.skippedFaces = search.skippedFaces;
  for (std::size_t k = 0; k < search.slaveFaces.size(); ++k) {
    const int a = search.slaveFaces[k];
    if (roles.role[a] != SelfContactRole::Slave) continue;
    std::vector<int> candidates;
    for (int b : search.candidates[k])
      if (roles.role[b] == SelfContactRole::Master && !sharesNodeWith(faces[a], faces[b])) candidates.push_back(b);
    if (candidates.empty()) continue;
    kept.slaveFaces.push_back(a);
    kept.candidates.push_back(std::move(candidates));
  }
  // Every node lies on its own surface: "behind the nearest master face"
  // (SearchResult::unpairedDepth) says nothing here.
  search = std::move(kept);
  return roles;
}

}  // namespace coulomb::contact
