#include "coulomb/linalg/TripletAssembly.hpp"

#include <algorithm>
#include <map>
#include <string>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>
#include <mpi.h>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::linalg {

namespace {

MPI_Comm rawComm(const Teuchos::Comm<int>& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  return mpi ? static_cast<MPI_Comm>(*mpi->getRawMpiComm()) : MPI_COMM_SELF;
}

/// Sends record r (`width` doubles each, row GID first) to the owner of its
/// row; returns the records this rank owns (its own included).
std::vector<double> toOwners(const std::vector<double>& records, int width, const Map& map) {
  const auto& comm = *map.getComm();
  const int size = comm.getSize();
  const std::size_t n = records.size() / width;
  // The owner of each distinct row, looked up once (Tpetra's directory is
  // given a sorted list without duplicates). One extra, valid index on every
  // rank: Map::getRemoteIndexList returns at once for an empty list, skipping
  // the collective set-up of its directory that the ranks with entries do —
  // a rank without contributions would then desynchronise the others.
  std::vector<GlobalOrdinal> distinct;
  distinct.reserve(n + 1);
  for (std::size_t i = 0; i < n; ++i) distinct.push_back(static_cast<GlobalOrdinal>(records[i * width]));
  distinct.push_back(map.getMinAllGlobalIndex());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<int> distinctOwners(distinct.size(), -1);
  std::vector<LocalOrdinal> locals(distinct.size());
  map.getRemoteIndexList(Teuchos::ArrayView<const GlobalOrdinal>(distinct.data(), distinct.size()),
                         Teuchos::ArrayView<int>(distinctOwners.data(), distinct.size()),
                         Teuchos::ArrayView<LocalOrdinal>(locals.data(), distinct.size()));
  std::vector<int> owners(n);
  std::string failure;
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<GlobalOrdinal>(records[i * width]);
    owners[i] = distinctOwners[std::lower_bound(distinct.begin(), distinct.end(), row) - distinct.begin()];
    if ((owners[i] < 0 || owners[i] >= size) && failure.empty())
      failure = "internal: contribution to row " + std::to_string(row) + " outside the DoF map";
  }
  throwIfAnyRankFailed(comm, failure);
  if (size == 1) return records;

  std::vector<int> sendCounts(size, 0), sendOffsets(size + 1, 0);
  for (std::size_t i = 0; i < n; ++i) sendCounts[owners[i]] += width;
  for (int p = 0; p < size; ++p) sendOffsets[p + 1] = sendOffsets[p] + sendCounts[p];
  std::vector<double> packed(records.size());
  std::vector<int> cursor(sendOffsets.begin(), sendOffsets.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    std::copy(records.begin() + i * width, records.begin() + (i + 1) * width, packed.begin() + cursor[owners[i]]);
    cursor[owners[i]] += width;
  }
  std::vector<int> recvCounts(size, 0), recvOffsets(size + 1, 0);
  const MPI_Comm raw = rawComm(comm);
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, raw);
  for (int p = 0; p < size; ++p) recvOffsets[p + 1] = recvOffsets[p] + recvCounts[p];
  std::vector<double> received(recvOffsets[size]);
  MPI_Alltoallv(packed.data(), sendCounts.data(), sendOffsets.data(), MPI_DOUBLE, received.data(),
                recvCounts.data(), recvOffsets.data(), MPI_DOUBLE, raw);
  return received;
}

}  // namespace

Teuchos::RCP<CrsMatrix> matrixFromTriplets(const std::vector<MatrixTriplet>& triplets,
                                           const Teuchos::RCP<const Map>& map) {
  // Global indices travel as doubles: exact below 2^53, far beyond any mesh.
  std::vector<double> records;
  records.reserve(triplets.size() * 3);
  for (const auto& t : triplets) {
    records.push_back(static_cast<double>(t.row));
    records.push_back(static_cast<double>(t.column));
    records.push_back(t.value);
  }
  const auto mine = toOwners(records, 3, *map);
  std::map<GlobalOrdinal, std::map<GlobalOrdinal, double>> rows;
  for (std::size_t i = 0; i < mine.size(); i += 3)
    rows[static_cast<GlobalOrdinal>(mine[i])][static_cast<GlobalOrdinal>(mine[i + 1])] += mine[i + 2];

  const std::size_t numLocal = map->getNodeNumElements();
  Teuchos::Array<std::size_t> counts(numLocal, 0);
  for (const auto& [row, columns] : rows) counts[map->getLocalElement(row)] = columns.size();
  auto matrix = Teuchos::rcp(new CrsMatrix(map, counts()));
  std::vector<GlobalOrdinal> cols;
  std::vector<double> values;
  for (const auto& [row, columns] : rows) {
    cols.clear();
    values.clear();
    for (const auto& [column, value] : columns) {
      cols.push_back(column);
      values.push_back(value);
    }
    matrix->insertGlobalValues(row, Teuchos::ArrayView<const GlobalOrdinal>(cols.data(), cols.size()),
                               Teuchos::ArrayView<const double>(values.data(), values.size()));
  }
  matrix->fillComplete(map, map);
  return matrix;
}

void addEntries(const std::vector<VectorEntry>& entries, Vector& owned) {
  std::vector<double> records;
  records.reserve(entries.size() * 2);
  for (const auto& e : entries) {
    records.push_back(static_cast<double>(e.row));
    records.push_back(e.value);
  }
  const auto mine = toOwners(records, 2, *owned.getMap());
  const auto& map = *owned.getMap();
  auto data = owned.getDataNonConst(0);
  for (std::size_t i = 0; i < mine.size(); i += 2)
    data[map.getLocalElement(static_cast<GlobalOrdinal>(mine[i]))] += mine[i + 1];
}

}  // namespace coulomb::linalg
