/// @file VertexCoarsening.cpp
/// @brief The corner-node coarse level of a quadratic mesh (see the header).
#include "coulomb/fem/VertexCoarsening.hpp"

#include "coulomb/fem/RigidBodyModes.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <vector>

namespace coulomb::fem {

namespace {

bool hasQuadraticCells(const mesh::GlobalMesh& mesh) {
  for (const auto& block : mesh.blocks)
    if (mesh::isQuadratic(block.cellType)) return true;
  return false;
}

/// Per global node: a corner of some cell.
std::vector<char> cornerNodes(const mesh::GlobalMesh& mesh) {
  std::vector<char> vertex(mesh.numNodes(), 0);
  for (const auto& block : mesh.blocks) {
    const int n = mesh::numNodes(block.cellType), corners = mesh::numCorners(block.cellType);
    for (long long e = 0; e < block.numElements(); ++e)
      for (int a = 0; a < corners; ++a) vertex[block.connectivity[e * n + a]] = 1;
  }
  return vertex;
}

}  // namespace

long long cornerNodeCount(const mesh::GlobalMesh& mesh) {
  if (!hasQuadraticCells(mesh)) return 0;
  const std::vector<char> vertex = cornerNodes(mesh);
  return std::count(vertex.begin(), vertex.end(), 1);
}

VertexCoarsening vertexCoarsening(const mesh::Mesh& mesh, const DofMap& dofs) {
  VertexCoarsening out;
  const mesh::GlobalMesh& global = mesh.global();
  if (!hasQuadraticCells(global)) return out;

  // Per global node: a corner of some cell (a vertex). Per owned node that
  // is not: the corners it is the mean of, from a local cell that has it (a
  // node's owner holds a cell around it, Mesh.hpp; in a conforming mesh
  // every such cell names the same corners).
  const long long numNodes = global.numNodes();
  const std::vector<char> vertex = cornerNodes(global);
  const int owned = mesh.numOwnedNodes();
  std::vector<std::array<long long, 8>> means(owned);
  std::vector<int> meanCount(owned, 0);
  for (std::size_t b = 0; b < global.blocks.size(); ++b) {
    const auto& block = global.blocks[b];
    const int n = mesh::numNodes(block.cellType), corners = mesh::numCorners(block.cellType);
    for (long long element : mesh.localElements(b)) {
      const long long e = element - block.firstElement;
      for (int a = corners; a < n; ++a) {
        const long long node = block.connectivity[e * n + a];
        const int local = mesh.localNode(node);
        if (vertex[node] || local < 0 || local >= owned || meanCount[local] > 0) continue;
        const mesh::NodeCorners c = mesh::nodeCorners(block.cellType, a);
        for (int k = 0; k < c.count; ++k) means[local][k] = block.connectivity[e * n + c.corners[k]];
        meanCount[local] = c.count;
      }
    }
  }

  // The corner nodes numbered 0, 1, ... in global node order (the same on
  // every rank): MueLu's aggregation reads a node from a DoF as dof / dim.
  std::vector<long long> coarseIndex(numNodes, -1);
  long long count = 0;
  for (long long node = 0; node < numNodes; ++node)
    if (vertex[node]) coarseIndex[node] = count++;
  const int dim = mesh.dimension();
  std::vector<GlobalOrdinal> coarseDofs, coarseNodes;
  std::vector<long long> ownedVertices;
  for (int i = 0; i < mesh.numOwnedNodes(); ++i) {
    const long long node = mesh.localNodes()[i];
    if (!vertex[node]) continue;
    ownedVertices.push_back(node);
    coarseNodes.push_back(coarseIndex[node]);
    for (int c = 0; c < dim; ++c) coarseDofs.push_back(DofMap::globalDof(coarseIndex[node], c, dim));
  }
  const auto comm = mesh.comm();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto coarseMap = Teuchos::rcp(new Map(invalid, coarseDofs.data(), coarseDofs.size(), 0, comm));
  auto coarseNodeMap = Teuchos::rcp(new Map(invalid, coarseNodes.data(), coarseNodes.size(), 0, comm));

  out.prolongator = Teuchos::rcp(new CrsMatrix(dofs.ownedMap(), 8));
  for (int i = 0; i < mesh.numOwnedNodes(); ++i) {
    const long long node = mesh.localNodes()[i];
    for (int c = 0; c < dim; ++c) {
      const GlobalOrdinal row = DofMap::globalDof(node, c, dim);
      if (vertex[node]) {
        const GlobalOrdinal col = DofMap::globalDof(coarseIndex[node], c, dim);
        const double one = 1.0;
        out.prolongator->insertGlobalValues(row, 1, &one, &col);
        continue;
      }
      const int corners = meanCount[i];
      if (corners == 0) continue;  // a node of no cell: a zero row
      std::vector<GlobalOrdinal> cols(corners);
      std::vector<double> values(corners, 1.0 / corners);
      for (int k = 0; k < corners; ++k) cols[k] = DofMap::globalDof(coarseIndex[means[i][k]], c, dim);
      out.prolongator->insertGlobalValues(row, corners, values.data(), cols.data());
    }
  }
  out.prolongator->fillComplete(coarseMap, dofs.ownedMap());

  std::vector<double> cornerCoordinates(ownedVertices.size() * dim);
  out.coordinates = Teuchos::rcp(new MultiVector(coarseNodeMap, dim));
  auto x = out.coordinates->get2dViewNonConst();
  for (std::size_t i = 0; i < ownedVertices.size(); ++i)
    for (int d = 0; d < dim; ++d) x[d][i] = cornerCoordinates[i * dim + d] = global.coordinates[ownedVertices[i] * dim + d];
  out.nullspace = rigidBodyModes(coarseMap, cornerCoordinates, dim);
  return out;
}

}  // namespace coulomb::fem
