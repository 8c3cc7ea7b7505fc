#pragma once
/// @file RigidBodyModes.hpp
/// @brief Near-null space of elasticity and nodal coordinates, as MueLu wants them.
#include <Teuchos_RCP.hpp>

#include <vector>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::fem {

/// @brief Rigid-body modes on the owned DoFs: 2 translations + 1 rotation in
/// 2D, 3 + 3 in 3D (rotations about the origin).
Teuchos::RCP<MultiVector> rigidBodyModes(const mesh::Mesh& mesh, const DofMap& dofs);

/// @brief The same on `map`, whose local DoF i * dim + c is component c of
/// the node with coordinates coordinates[i * dim .. i * dim + dim).
Teuchos::RCP<MultiVector> rigidBodyModes(const Teuchos::RCP<const Map>& map, const std::vector<double>& coordinates,
                                         int dim);

/// @brief Reference coordinates of the owned nodes (one column per dimension).
Teuchos::RCP<MultiVector> nodalCoordinates(const mesh::Mesh& mesh, const DofMap& dofs);

}  // namespace coulomb::fem
