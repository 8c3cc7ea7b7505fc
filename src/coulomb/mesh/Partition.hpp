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

/// @brief Collective: a weighted geometric partition of points into one part
/// per rank (Zoltan2 multi-jagged). Each rank hands in its own points
/// (`points`: x, y, z per point, z ignored when `dimension` is 2; `weights`: one positive weight per point,
/// the work the point stands for) and gets the part of each of them back.
/// The parts have about equal total weight and are compact, so objects near
/// each other land on the same rank. Deterministic for given input and
/// rank count.
std::vector<int> partitionWeightedPoints(int dimension, const std::vector<double>& points,
                                         const std::vector<double>& weights,
                                         const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

}  // namespace coulomb::mesh
