#include "coulomb/fem/MeshChecks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/FaceTopology.hpp"

namespace coulomb::fem {

namespace {

double tetVolume(const double* a, const double* b, const double* c, const double* d) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

/// The block holding global element `element`.
const mesh::ElementBlock& blockOf(const mesh::GlobalMesh& mesh, long long element) {
  for (const auto& block : mesh.blocks)
    if (element >= block.firstElement && element < block.firstElement + block.numElements()) return block;
  COULOMB_CHECK(false, "element " << element << " is in no block");
  return mesh.blocks.front();
}

}  // namespace

double cellMeasure(mesh::CellType type, const double* X) {
  // A quadratic cell is measured by its corners (they lead its node list):
  // the straight-sided cell they span. Its curved edges change the volume,
  // but a cell whose corners span no volume is degenerate however its
  // mid-side nodes sit, which is what the zero-volume check asks.
  if (mesh::isQuadratic(type)) return cellMeasure(mesh::linearType(type), X);
  switch (type) {
    case mesh::CellType::Tri3:
    case mesh::CellType::Quad4: {
      // The shoelace formula: exact for a polygon.
      const int n = mesh::numNodes(type);
      double twice = 0;
      for (int a = 0; a < n; ++a) {
        const int b = (a + 1) % n;
        twice += X[2 * a] * X[2 * b + 1] - X[2 * b] * X[2 * a + 1];
      }
      return 0.5 * twice;
    }
    case mesh::CellType::Tet4: return tetVolume(X, X + 3, X + 6, X + 9);
    case mesh::CellType::Hex8: {
      static const int kTets[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
      double volume = 0;
      for (const auto& t : kTets) volume += tetVolume(X, X + 3 * t[0], X + 3 * t[1], X + 18);
      return volume;
    }
    default: break;
  }
  return 0.0;
}

double cellDiameter(mesh::CellType type, const double* X) {
  const int n = mesh::numNodes(type), dim = mesh::spatialDimension(type);
  double d2 = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      double s = 0;
      for (int c = 0; c < dim; ++c) s += (X[dim * a + c] - X[dim * b + c]) * (X[dim * a + c] - X[dim * b + c]);
      d2 = std::max(d2, s);
    }
  return std::sqrt(d2);
}

bool hasZeroVolume(mesh::CellType type, const double* X) {
  const double h = cellDiameter(type, X);
  return std::abs(cellMeasure(type, X)) <= 1e-10 * std::pow(h, mesh::spatialDimension(type));
}

std::array<long long, 2> findCoincidentNodes(const mesh::GlobalMesh& mesh, const std::vector<char>& exempt) {
  const int dim = mesh.dimension;
  const long long n = mesh.numNodes();
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  for (const auto& block : mesh.blocks)
    for (long long node : block.connectivity) used[static_cast<std::size_t>(node)] = 1;
  std::array<double, 3> lo{}, hi{};
  lo.fill(INFINITY);
  hi.fill(-INFINITY);
  for (long long i = 0; i < n; ++i)
    for (int c = 0; c < dim; ++c) {
      lo[c] = std::min(lo[c], mesh.coordinates[dim * i + c]);
      hi[c] = std::max(hi[c], mesh.coordinates[dim * i + c]);
    }
  double diagonal2 = 0;
  for (int c = 0; c < dim; ++c) diagonal2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  const double tolerance = 1e-10 * std::sqrt(diagonal2);
  if (!(tolerance > 0.0)) return {-1, -1};
  // A hash grid of cells of the tolerance's size: two nodes within the
  // tolerance are in the same or neighbouring cells.
  using Key = std::array<long long, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
  };
  auto keyOf = [&](long long i) {
    Key k{0, 0, 0};
    for (int c = 0; c < dim; ++c)
      k[c] = static_cast<long long>(std::floor((mesh.coordinates[dim * i + c] - lo[c]) / tolerance));
    return k;
  };
  std::unordered_map<Key, std::vector<long long>, KeyHash> grid;
  for (long long i = 0; i < n; ++i)
    if (used[i] && !(static_cast<std::size_t>(i) < exempt.size() && exempt[i])) grid[keyOf(i)].push_back(i);
  // Two nodes of one element at one point are a collapsed cell (the volume
  // check names it), not an unmerged mesh.
  const NodeElementAdjacency adjacency = nodeElementAdjacency(mesh);
  auto shareAnElement = [&](long long i, long long j) {
    for (long long k = adjacency.offsets[i]; k < adjacency.offsets[i + 1]; ++k)
      if (std::binary_search(adjacency.elements.begin() + adjacency.offsets[j],
                             adjacency.elements.begin() + adjacency.offsets[j + 1], adjacency.elements[k]))
        return true;
    return false;
  };
  std::array<long long, 2> found{-1, -1};
  for (const auto& [key, nodes] : grid)
    for (long long i : nodes)
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = (dim == 3 ? -1 : 0); dz <= (dim == 3 ? 1 : 0); ++dz) {
            const auto it = grid.find({key[0] + dx, key[1] + dy, key[2] + dz});
            if (it == grid.end()) continue;
            for (long long j : it->second) {
              if (j <= i) continue;
              double d2 = 0;
              for (int c = 0; c < dim; ++c) {
                const double d = mesh.coordinates[dim * i + c] - mesh.coordinates[dim * j + c];
                d2 += d * d;
              }
              // The lowest pair: the same answer whatever the hash order.
              if (d2 <= tolerance * tolerance && (found[0] < 0 || i < found[0] || (i == found[0] && j < found[1])) &&
                  !shareAnElement(i, j))
                found = {i, j};
            }
          }
  return found;
}

void checkCoincidentNodes(const mesh::GlobalMesh& mesh, const std::vector<char>& exempt, const std::string& file) {
  const auto pair = findCoincidentNodes(mesh, exempt);
  if (pair[0] < 0) return;
  std::ostringstream point;
  for (int c = 0; c < mesh.dimension; ++c) point << (c ? ", " : "") << mesh.coordinates[mesh.dimension * pair[0] + c];
  throw Error("mesh '" + file + "': nodes " + std::to_string(pair[0] + 1) + " and " + std::to_string(pair[1] + 1) +
              " are at the same point (" + point.str() +
              ") but no element joins them and they are on no contact surface: the mesh is not merged "
              "(gmsh: Coherence; Cubit: merge all), or name the touching surfaces in a contact pair");
}

void checkAxisymmetricMesh(const mesh::GlobalMesh& mesh, const std::string& file) {
  const int d = mesh.dimension;
  std::vector<double> low(d, 0.0), high(d, 0.0);
  for (long long i = 0; i < mesh.numNodes(); ++i)
    for (int c = 0; c < d; ++c) {
      const double x = mesh.coordinates[d * i + c];
      low[c] = i == 0 ? x : std::min(low[c], x);
      high[c] = i == 0 ? x : std::max(high[c], x);
    }
  double diagonal2 = 0;
  for (int c = 0; c < d; ++c) diagonal2 += (high[c] - low[c]) * (high[c] - low[c]);
  const double tolerance = 1e-10 * std::sqrt(diagonal2);
  for (long long i = 0; i < mesh.numNodes(); ++i)
    COULOMB_REQUIRE(mesh.coordinates[d * i] >= -tolerance,
                    "mesh '" << file << "': node " << i + 1 << " has x = " << mesh.coordinates[d * i]
                             << " < 0, but with 'Problem/Plane Assumption' = 'Axisymmetric' x is the radius (the "
                                "axis is x = 0)");
}

NodeElementAdjacency nodeElementAdjacency(const mesh::GlobalMesh& mesh) {
  NodeElementAdjacency a;
  const auto n = static_cast<std::size_t>(mesh.numNodes());
  a.offsets.assign(n + 1, 0);
  for (const auto& block : mesh.blocks)
    for (long long node : block.connectivity) ++a.offsets[static_cast<std::size_t>(node) + 1];
  for (std::size_t i = 0; i < n; ++i) a.offsets[i + 1] += a.offsets[i];
  a.elements.resize(static_cast<std::size_t>(a.offsets[n]));
  std::vector<long long> next(a.offsets.begin(), a.offsets.end() - 1);
  for (const auto& block : mesh.blocks) {
    const int per = mesh::numNodes(block.cellType);
    for (std::size_t k = 0; k < block.connectivity.size(); ++k)
      a.elements[next[block.connectivity[k]]++] = block.firstElement + static_cast<long long>(k) / per;
  }
  return a;
}

long long elementAcrossFace(const mesh::GlobalMesh& mesh, const NodeElementAdjacency& adjacency, long long element,
                            int side) {
  const mesh::ElementBlock& block = blockOf(mesh, element);
  std::array<int, mesh::kMaxFaceNodes> local{};
  const int count = faceLocalNodes(block.cellType, side, local);
  const long long* cell = &block.connectivity[(element - block.firstElement) * mesh::numNodes(block.cellType)];
  // The elements of the face's first node that hold all its other nodes too.
  const long long first = cell[local[0]];
  for (long long k = adjacency.offsets[first]; k < adjacency.offsets[first + 1]; ++k) {
    const long long other = adjacency.elements[k];
    if (other == element) continue;
    bool all = true;
    for (int a = 1; a < count && all; ++a) {
      const long long node = cell[local[a]];
      all = std::binary_search(adjacency.elements.begin() + adjacency.offsets[node],
                               adjacency.elements.begin() + adjacency.offsets[node + 1], other);
    }
    if (all) return other;
  }
  return -1;
}

}  // namespace coulomb::fem
