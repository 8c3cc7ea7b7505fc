#pragma once
/// @file Mesh.hpp
/// @brief One rank's view of the partitioned mesh: its elements, its owned
/// nodes and the ghost nodes its elements touch.
///
/// Ownership: each element belongs to exactly one rank (Partition.hpp); a
/// node belongs to the lowest rank among the owners of the elements around
/// it. Local node numbering puts owned nodes first, then ghosts, each group
/// in increasing global number.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::mesh {

class Mesh {
public:
  Mesh(std::shared_ptr<const GlobalMesh> global, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

  const GlobalMesh& global() const { return *global_; }
  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  int dimension() const { return global_->dimension; }

  /// Global element numbers of this rank's elements in block `b`.
  const std::vector<long long>& localElements(std::size_t b) const { return localElements_[b]; }
  int elementOwner(long long globalElement) const { return elementOwner_[globalElement]; }
  int nodeOwner(long long globalNode) const { return nodeOwner_[globalNode]; }

  /// Global numbers of local nodes: owned first (numOwnedNodes()), then ghosts.
  const std::vector<long long>& localNodes() const { return localNodes_; }
  int numOwnedNodes() const { return numOwnedNodes_; }
  /// Local number of a global node, or -1 if no local element touches it.
  int localNode(long long globalNode) const { return globalToLocal_[globalNode]; }

  /// Index of the block/node set/side set addressed by `name` (Exodus name,
  /// or block_<id>/nodeset_<id>/sideset_<id>); throws coulomb::Error naming
  /// `what` (the deck entry asking) and listing the available names.
  std::size_t blockIndex(const std::string& name, const std::string& what) const;
  std::size_t nodeSetIndex(const std::string& name, const std::string& what) const;
  std::size_t sideSetIndex(const std::string& name, const std::string& what) const;
  /// Block holding a global element.
  std::size_t blockOfElement(long long globalElement) const;

private:
  std::shared_ptr<const GlobalMesh> global_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<int> elementOwner_;
  std::vector<int> nodeOwner_;
  std::vector<std::vector<long long>> localElements_;
  std::vector<long long> localNodes_;
  int numOwnedNodes_ = 0;
  std::vector<int> globalToLocal_;
};

}  // namespace coulomb::mesh
