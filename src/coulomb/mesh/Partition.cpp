#include "coulomb/mesh/Partition.hpp"

#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

#include "coulomb/core/Error.hpp"

namespace coulomb::mesh {

namespace {

MPI_Comm rawComm(const Teuchos::Comm<int>& comm) {
  const auto* mpiComm = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  COULOMB_CHECK(mpiComm != nullptr, "Coulomb needs an MPI Teuchos communicator");
  return *mpiComm->getRawMpiComm();
}

}  // namespace

std::vector<int> partitionElements(const GlobalMesh& mesh, const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  const int size = comm->getSize();
  const long long numElements = mesh.numElements();
  std::vector<int> owner(static_cast<std::size_t>(numElements), 0);
  if (size == 1) return owner;

  // Every rank holds the whole mesh; each hands Zoltan2 a contiguous chunk of
  // element centroids, and the chunks' part numbers are gathered afterwards.
  const int rank = comm->getRank();
  const long long begin = numElements * rank / size;
  const long long end = numElements * (rank + 1) / size;
  const int count = static_cast<int>(end - begin);
  const int dim = mesh.dimension;
  std::vector<double> centroid(3 * static_cast<std::size_t>(count), 0.0);
  for (const auto& block : mesh.blocks) {
    const int nodesPerCell = numNodes(block.cellType);
    for (long long e = std::max(begin, block.firstElement); e < std::min(end, block.firstElement + block.numElements()); ++e) {
      const long long i = e - begin;
      for (int a = 0; a < nodesPerCell; ++a) {
        const long long node = block.connectivity[(e - block.firstElement) * nodesPerCell + a];
        for (int d = 0; d < dim; ++d) centroid[3 * i + d] += mesh.coordinates[node * dim + d] / nodesPerCell;
      }
    }
  }

  // Every element weighs the same.
  const std::vector<int> localOwner =
      partitionWeightedPoints(dim, centroid, std::vector<double>(static_cast<std::size_t>(count), 1.0), comm);

  std::vector<int> counts(size), displacements(size);
  for (int r = 0; r < size; ++r) {
    counts[r] = static_cast<int>(numElements * (r + 1) / size - numElements * r / size);
    displacements[r] = static_cast<int>(numElements * r / size);
  }
  MPI_Allgatherv(localOwner.data(), count, MPI_INT, owner.data(), counts.data(), displacements.data(), MPI_INT,
                 rawComm(*comm));
  return owner;
}

std::vector<int> partitionWeightedPoints(int dimension, const std::vector<double>& points,
                                         const std::vector<double>& weights,
                                         const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  const int count = static_cast<int>(weights.size());
  COULOMB_CHECK(points.size() == 3 * weights.size(), "three coordinates per weighted point");
  if (comm->getSize() == 1) return std::vector<int>(weights.size(), 0);
  // Global ids only have to be unique: the rank's offset plus the position.
  int offset = 0;
  MPI_Exscan(&count, &offset, 1, MPI_INT, MPI_SUM, rawComm(*comm));
  if (comm->getRank() == 0) offset = 0;
  std::vector<long long> ids(weights.size());
  for (int i = 0; i < count; ++i) ids[i] = static_cast<long long>(offset) + i;

  using Types = Zoltan2::BasicUserTypes<double, int, long long>;
  using Adapter = Zoltan2::BasicVectorAdapter<Types>;
  // A rank without points still hands Zoltan2 valid pointers (a null y or z
  // would mean another dimension than the other ranks').
  static const double none[3] = {0.0, 0.0, 0.0};
  const double* p = count > 0 ? points.data() : none;
  const double* w = count > 0 ? weights.data() : none;
  Adapter adapter(count, ids.data(), p, p + 1, dimension == 3 ? p + 2 : nullptr, 3, 3, 3, true, w, 1);
  Teuchos::ParameterList params;
  params.set("algorithm", "multijagged");
  params.set("num_global_parts", comm->getSize());
  params.set("imbalance_tolerance", 1.05);
  Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &params, comm);
  problem.solve();
  const auto* parts = problem.getSolution().getPartListView();
  return std::vector<int>(parts, parts + count);
}

}  // namespace coulomb::mesh
