#include "coulomb/mesh/Mesh.hpp"

#include <algorithm>
#include <climits>

#include "coulomb/core/Error.hpp"
#include "coulomb/mesh/Partition.hpp"

namespace coulomb::mesh {

namespace {

/// `kind` is the prefix of unnamed sets' aliases (nodeset_3), `noun` what a user calls it.
template <typename Set>
std::size_t findByName(const std::vector<Set>& sets, const std::string& name, const char* kind, const char* noun,
                       const std::string& what) {
  std::string available;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const std::string shown = displayName(sets[i].name, kind, sets[i].id);
    if (shown == name || std::string(kind) + "_" + std::to_string(sets[i].id) == name) return i;
    available += (available.empty() ? "'" : ", '") + shown + "'";
  }
  throw Error("deck: '" + what + "' names " + noun + " '" + name + "', which the mesh does not have (" +
              (available.empty() ? std::string("it has none") : "it has " + available) + ")");
}

}  // namespace

Mesh::Mesh(std::shared_ptr<const GlobalMesh> global, const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
    : global_(std::move(global)), comm_(comm) {
  const int rank = comm_->getRank();
  elementOwner_ = partitionElements(*global_, comm_);
  nodeOwner_.assign(global_->numNodes(), INT_MAX);
  localElements_.resize(global_->blocks.size());
  std::vector<char> touched(global_->numNodes(), 0);
  for (std::size_t b = 0; b < global_->blocks.size(); ++b) {
    const auto& block = global_->blocks[b];
    const int n = numNodes(block.cellType);
    for (long long i = 0; i < block.numElements(); ++i) {
      const long long element = block.firstElement + i;
      const int owner = elementOwner_[element];
      for (int a = 0; a < n; ++a) {
        const long long node = block.connectivity[i * n + a];
        nodeOwner_[node] = std::min(nodeOwner_[node], owner);
        if (owner == rank) touched[node] = 1;
      }
      if (owner == rank) localElements_[b].push_back(element);
    }
  }
  // Nodes outside every element (a mesh may carry stray points) go to rank 0.
  for (auto& owner : nodeOwner_)
    if (owner == INT_MAX) owner = 0;
  if (rank == 0)
    for (long long node = 0; node < global_->numNodes(); ++node)
      if (nodeOwner_[node] == 0) touched[node] = 1;

  for (long long node = 0; node < global_->numNodes(); ++node)
    if (touched[node] && nodeOwner_[node] == rank) localNodes_.push_back(node);
  numOwnedNodes_ = static_cast<int>(localNodes_.size());
  for (long long node = 0; node < global_->numNodes(); ++node)
    if (touched[node] && nodeOwner_[node] != rank) localNodes_.push_back(node);
  globalToLocal_.assign(global_->numNodes(), -1);
  for (std::size_t i = 0; i < localNodes_.size(); ++i) globalToLocal_[localNodes_[i]] = static_cast<int>(i);
}

std::size_t Mesh::blockIndex(const std::string& name, const std::string& what) const {
  return findByName(global_->blocks, name, "block", "element block", what);
}
std::size_t Mesh::nodeSetIndex(const std::string& name, const std::string& what) const {
  return findByName(global_->nodeSets, name, "nodeset", "node set", what);
}
std::size_t Mesh::sideSetIndex(const std::string& name, const std::string& what) const {
  return findByName(global_->sideSets, name, "sideset", "side set", what);
}

std::size_t Mesh::blockOfElement(long long globalElement) const {
  for (std::size_t b = 0; b < global_->blocks.size(); ++b) {
    const auto& block = global_->blocks[b];
    if (globalElement >= block.firstElement && globalElement < block.firstElement + block.numElements()) return b;
  }
  throw InternalError("element " + std::to_string(globalElement) + " is in no block");
}

}  // namespace coulomb::mesh
