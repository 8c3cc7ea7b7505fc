#pragma once
/// @file Partition.hpp
/// @brief Element partition of a GlobalMesh over MPI ranks with Zoltan2.
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::mesh {

/// @brief Owner rank of every global element, the same on every rank.
/// Zoltan2's multi-jagged geometric partition of element centroids (a
/// recursive coordinate bisection generalisation): contiguous, compact
/// parts, which is what the contact interfaces want too.
std::vector<int> partitionElements(const GlobalMesh& mesh, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

}  // namespace coulomb::mesh
