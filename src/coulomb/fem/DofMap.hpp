#pragma once
/// @file DofMap.hpp
/// @brief Displacement degrees of freedom as Tpetra maps.
///
/// Global DoF number = dimension * global node + component, so results map
/// back to Exodus node numbers without a table. The owned map holds the DoFs
/// of owned nodes; the overlap map those of every local node (owned first,
/// then ghosts), so owned and overlap local indices coincide on owned DoFs.
#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::fem {

class DofMap {
public:
  explicit DofMap(const mesh::Mesh& mesh);

  int dofsPerNode() const { return dofsPerNode_; }
  const Teuchos::RCP<const Map>& ownedMap() const { return ownedMap_; }
  const Teuchos::RCP<const Map>& overlapMap() const { return overlapMap_; }
  /// Owned global node numbers as a map (for nodal output fields).
  const Teuchos::RCP<const Map>& ownedNodeMap() const { return ownedNodeMap_; }
  /// Overlap-local DoF index of component c of local node n.
  int localDof(int localNode, int component) const { return localNode * dofsPerNode_ + component; }
  static GlobalOrdinal globalDof(long long globalNode, int component, int dofsPerNode) {
    return static_cast<GlobalOrdinal>(globalNode) * dofsPerNode + component;
  }

private:
  int dofsPerNode_;
  Teuchos::RCP<const Map> ownedMap_;
  Teuchos::RCP<const Map> overlapMap_;
  Teuchos::RCP<const Map> ownedNodeMap_;
};

}  // namespace coulomb::fem
