#pragma once
/// @file SparsityPattern.hpp
/// @brief Matrix graphs of the displacement tangent, built from the mesh
/// without communication (every rank holds the whole connectivity).
#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::fem {

/// @brief Graph of the ghost rows: rows = this rank's overlap DoFs owned by
/// other ranks, columns = overlap DoFs (column map == overlap map, so element
/// scatter uses overlap-local indices directly), holding the couplings of this
/// rank's elements. Empty on one rank. Fill-complete with the owned map as
/// domain and range; exported with ADD into the owned tangent.
Teuchos::RCP<const CrsGraph> buildGhostRowsGraph(const mesh::Mesh& mesh, const DofMap& dofs);

/// @brief Graph of rows = owned DoFs with the couplings of every element
/// touching an owned node, whichever rank owns that element.
Teuchos::RCP<const CrsGraph> buildOwnedGraph(const mesh::Mesh& mesh, const DofMap& dofs);

}  // namespace coulomb::fem
