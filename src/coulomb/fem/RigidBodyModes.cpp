#include "coulomb/fem/RigidBodyModes.hpp"

#include <Tpetra_MultiVector.hpp>

namespace coulomb::fem {

Teuchos::RCP<MultiVector> rigidBodyModes(const mesh::Mesh& mesh, const DofMap& dofs) {
  const int dim = mesh.dimension();
  auto modes = Teuchos::rcp(new MultiVector(dofs.ownedMap(), dim == 2 ? 3 : 6));
  auto m = modes->get2dViewNonConst();
  for (int i = 0; i < mesh.numOwnedNodes(); ++i) {
    const double* X = &mesh.global().coordinates[mesh.localNodes()[i] * dim];
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

Teuchos::RCP<MultiVector> nodalCoordinates(const mesh::Mesh& mesh, const DofMap& dofs) {
  const int dim = mesh.dimension();
  auto coordinates = Teuchos::rcp(new MultiVector(dofs.ownedNodeMap(), dim));
  auto x = coordinates->get2dViewNonConst();
  for (int i = 0; i < mesh.numOwnedNodes(); ++i)
    for (int d = 0; d < dim; ++d) x[d][i] = mesh.global().coordinates[mesh.localNodes()[i] * dim + d];
  return coordinates;
}

}  // namespace coulomb::fem
