#include "coulomb/fem/DofMap.hpp"

#include <vector>

#include <Tpetra_Map.hpp>

namespace coulomb::fem {

DofMap::DofMap(const mesh::Mesh& mesh) : dofsPerNode_(mesh.dimension()) {
  const auto& nodes = mesh.localNodes();
  std::vector<GlobalOrdinal> overlap;
  overlap.reserve(nodes.size() * dofsPerNode_);
  for (long long node : nodes)
    for (int c = 0; c < dofsPerNode_; ++c) overlap.push_back(globalDof(node, c, dofsPerNode_));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const std::size_t numOwnedDofs = static_cast<std::size_t>(mesh.numOwnedNodes()) * dofsPerNode_;
  ownedMap_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(overlap.data(), numOwnedDofs), 0,
                                   mesh.comm()));
  overlapMap_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(overlap), 0, mesh.comm()));
  std::vector<GlobalOrdinal> ownedNodes(nodes.begin(), nodes.begin() + mesh.numOwnedNodes());
  ownedNodeMap_ = Teuchos::rcp(new Map(invalid, Teuchos::ArrayView<const GlobalOrdinal>(ownedNodes), 0, mesh.comm()));
}

}  // namespace coulomb::fem
