#include "coulomb/fem/RigidBodyModes.hpp"

#include <Tpetra_MultiVector.hpp>

namespace coulomb::fem {

Teuchos::RCP<MultiVector> rigidBodyModes(const Teuchos::RCP<const Map>& map, const std::vector<double>& coordinates,
                                         int dim) {
  auto modes = Teuchos::rcp(new MultiVector(map, dim == 2 ? 3 : 6));
  auto m = modes->get2dViewNonConst();
  const std::size_t nodes = coordinates.size() / dim;
  for (std::size_t i = 0; i < nodes; ++i) {
    const double* X = &coordinates[i * dim];
    for (int d = 0; d < dim; ++d) m[d][i * dim + d] = 1.0;
    if (dim == 2) {
      m[2][i * 2 + 0] = -X[1];
      m[2][i * 2 + 1] = X[0];
    } else {
      m[3][i * 3 + 1] = -X[2], m[3][i * 3 + 2] = X[1];
      m[4][i * 3 + 0] = X[2], m[4][i * 3 + 2] = -X[0];
      m[5][i * 3 + 0] = -X[1], m[5][i * 3 + 1] = X[0];
    }
  }
  return modes;
}

Teuchos::RCP<MultiVector> rigidBodyModes(const mesh::Mesh& mesh, const DofMap& dofs) {
  const int dim = mesh.dimension();
  std::vector<double> coordinates(static_cast<std::size_t>(mesh.numOwnedNodes()) * dim);
  for (int i = 0; i < mesh.numOwnedNodes(); ++i)
    for (int d = 0; d < dim; ++d) coordinates[i * dim + d] = mesh.global().coordinates[mesh.localNodes()[i] * dim + d];
  return rigidBodyModes(dofs.ownedMap(), coordinates, dim);
}

Teuchos::RCP<MultiVector> nodalCoordinates(const mesh::Mesh& mesh, const DofMap& dofs) {
  const int dim = mesh.dimension();
  auto coordinates = Teuchos::rcp(new MultiVector(dofs.ownedNodeMap(), dim));
  auto x = coordinates->get2dViewNonConst();
  for (int i = 0; i < mesh.numOwnedNodes(); ++i)
    for (int d = 0; d < dim; ++d) x[d][i] = mesh.global().coordinates[mesh.localNodes()[i] * dim + d];
  return coordinates;
}

}  // namespace coulomb::fem
