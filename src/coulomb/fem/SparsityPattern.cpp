#include "coulomb/fem/SparsityPattern.hpp"

#include <algorithm>
#include <vector>

#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_Map.hpp>

namespace coulomb::fem {

namespace {

/// Neighbour node lists (global numbers, sorted, unique) of the nodes for which
/// `wanted(node)` >= 0, over the elements accepted by `useElement`.
template <typename RowIndex, typename UseElement>
std::vector<std::vector<long long>> nodeNeighbours(const mesh::Mesh& mesh, std::size_t numRows, RowIndex rowOf,
                                                   UseElement useElement) {
  std::vector<std::vector<long long>> neighbours(numRows);
  for (const auto& block : mesh.global().blocks) {
    const int n = mesh::numNodes(block.cellType);
    for (long long i = 0; i < block.numElements(); ++i) {
      if (!useElement(block.firstElement + i)) continue;
      const long long* cell = &block.connectivity[i * n];
      for (int a = 0; a < n; ++a) {
        const int row = rowOf(cell[a]);
        if (row < 0) continue;
        neighbours[row].insert(neighbours[row].end(), cell, cell + n);
      }
    }
  }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

/// Tpetra's CSR constructor takes the rows as sorted by local column index
/// (it binary-searches them when summing): local order differs from global
/// order as soon as a rank has ghost nodes.
void sortRows(const Teuchos::ArrayRCP<size_t>& rowPointers, Teuchos::ArrayRCP<LocalOrdinal>& columns) {
  for (std::size_t row = 0; row + 1 < static_cast<std::size_t>(rowPointers.size()); ++row)
    std::sort(columns.begin() + rowPointers[row], columns.begin() + rowPointers[row + 1]);
}

}  // namespace

Teuchos::RCP<const CrsGraph> buildGhostRowsGraph(const mesh::Mesh& mesh, const DofMap& dofs) {
  const int rank = mesh.comm()->getRank();
  const int dim = dofs.dofsPerNode();
  const int numOwned = mesh.numOwnedNodes();
  const std::size_t numGhost = mesh.localNodes().size() - static_cast<std::size_t>(numOwned);
  const auto neighbours = nodeNeighbours(
      mesh, numGhost,
      [&](long long node) {
        const int local = mesh.localNode(node);
        return local >= numOwned ? local - numOwned : -1;
      },
      [&](long long element) { return mesh.elementOwner(element) == rank; });
  std::vector<GlobalOrdinal> rowGids;
  rowGids.reserve(numGhost * dim);
  for (std::size_t i = 0; i < numGhost; ++i)
    for (int c = 0; c < dim; ++c) rowGids.push_back(DofMap::globalDof(mesh.localNodes()[numOwned + i], c, dim));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto rowMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(rowGids), 0, mesh.comm()));
  Teuchos::ArrayRCP<size_t> rowPointers(numGhost * dim + 1);
  rowPointers[0] = 0;
  for (std::size_t node = 0; node < numGhost; ++node)
    for (int c = 0; c < dim; ++c) {
      const std::size_t row = node * dim + c;
      rowPointers[row + 1] = rowPointers[row] + neighbours[node].size() * dim;
    }
  Teuchos::ArrayRCP<LocalOrdinal> columns(rowPointers[rowPointers.size() - 1]);
  std::size_t k = 0;
  for (std::size_t node = 0; node < numGhost; ++node)
    for (int c = 0; c < dim; ++c)
      for (long long other : neighbours[node])
        for (int d = 0; d < dim; ++d) columns[k++] = dofs.localDof(mesh.localNode(other), d);
  sortRows(rowPointers, columns);
  auto graph = Teuchos::rcp(new CrsGraph(rowMap, dofs.overlapMap(), rowPointers, columns));
  graph->fillComplete(dofs.ownedMap(), dofs.ownedMap());
  return graph;
}

Teuchos::RCP<const CrsGraph> buildOwnedGraph(const mesh::Mesh& mesh, const DofMap& dofs) {
  const int dim = dofs.dofsPerNode();
  const int numOwned = mesh.numOwnedNodes();
  const auto neighbours = nodeNeighbours(
      mesh, numOwned,
      [&](long long node) {
        const int local = mesh.localNode(node);
        return local < numOwned ? local : -1;
      },
      [](long long) { return true; });
  // Column map: owned DoFs first (Tpetra's convention, cheap Import), then the others sorted.
  std::vector<long long> remoteNodes;
  for (const auto& list : neighbours)
    for (long long node : list)
      if (mesh.nodeOwner(node) != mesh.comm()->getRank()) remoteNodes.push_back(node);
  std::sort(remoteNodes.begin(), remoteNodes.end());
  remoteNodes.erase(std::unique(remoteNodes.begin(), remoteNodes.end()), remoteNodes.end());
  std::vector<GlobalOrdinal> columnGids;
  columnGids.reserve((numOwned + remoteNodes.size()) * dim);
  for (int i = 0; i < numOwned; ++i)
    for (int c = 0; c < dim; ++c) columnGids.push_back(DofMap::globalDof(mesh.localNodes()[i], c, dim));
  for (long long node : remoteNodes)
    for (int c = 0; c < dim; ++c) columnGids.push_back(DofMap::globalDof(node, c, dim));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto columnMap = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(columnGids), 0, mesh.comm()));

  auto columnOf = [&](long long node, int c) {
    const int local = mesh.localNode(node);
    if (local >= 0 && local < numOwned) return local * dim + c;
    const auto it = std::lower_bound(remoteNodes.begin(), remoteNodes.end(), node);
    return static_cast<int>((numOwned + (it - remoteNodes.begin())) * dim + c);
  };
  Teuchos::ArrayRCP<size_t> rowPointers(static_cast<std::size_t>(numOwned) * dim + 1);
  rowPointers[0] = 0;
  for (int node = 0; node < numOwned; ++node)
    for (int c = 0; c < dim; ++c) {
      const std::size_t row = static_cast<std::size_t>(node) * dim + c;
      rowPointers[row + 1] = rowPointers[row] + neighbours[node].size() * dim;
    }
  Teuchos::ArrayRCP<LocalOrdinal> columns(rowPointers[rowPointers.size() - 1]);
  std::size_t k = 0;
  for (int node = 0; node < numOwned; ++node)
    for (int c = 0; c < dim; ++c)
      for (long long other : neighbours[node])
        for (int d = 0; d < dim; ++d) columns[k++] = columnOf(other, d);
  sortRows(rowPointers, columns);
  auto graph = Teuchos::rcp(new CrsGraph(dofs.ownedMap(), columnMap, rowPointers, columns));
  graph->fillComplete(dofs.ownedMap(), dofs.ownedMap());
  return graph;
}

}  // namespace coulomb::fem
