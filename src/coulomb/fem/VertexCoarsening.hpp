#pragma once
/// @file VertexCoarsening.hpp
/// @brief The first coarse level of the multigrid preconditioner on a mesh
/// of quadratic cells: the same mesh with linear cells (its corner nodes).
///
/// Why: aggregation-based AMG coarsens a quadratic element matrix less well
/// than a linear one (more GMRES iterations per solve on HEX20 / TET10 than
/// on HEX8 at the same DoF count, tests/performance/README.md). A geometric
/// p-coarsening first — the quadratic displacement field restricted to the
/// linear one on the corners, P the linear interpolation of every other
/// node from the corners it is the mean of (mesh::nodeCorners: an edge
/// node from its edge's two ends, a face centre from four, a cell centre
/// from eight) — hands MueLu's aggregation a linear-element operator P^T A P.
/// P reproduces every linear field, so the rigid-body modes at the corners
/// are the coarse near-null space.
#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::fem {

struct VertexCoarsening {
  /// Rows: the owned DoFs (DofMap::ownedMap); columns: the DoFs of the
  /// corner nodes (their global DoF numbers), each owned by its node's owner.
  /// Null when no block has quadratic cells.
  Teuchos::RCP<CrsMatrix> prolongator;
  Teuchos::RCP<MultiVector> nullspace;    ///< rigid-body modes on the corner DoFs (P's domain map)
  Teuchos::RCP<MultiVector> coordinates;  ///< the owned corner nodes' coordinates
};

/// @brief The corner-node level of `mesh` (collective).
VertexCoarsening vertexCoarsening(const mesh::Mesh& mesh, const DofMap& dofs);

/// @brief How many nodes of `mesh` are corners of some cell; 0 when no
/// block has quadratic cells (no corner level).
long long cornerNodeCount(const mesh::GlobalMesh& mesh);

}  // namespace coulomb::fem
