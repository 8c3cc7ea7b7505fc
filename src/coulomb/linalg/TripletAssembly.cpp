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
  std::vector<GlobalOrdinal> rows(n);
  for (std::size_t i = 0; i < n; ++i) rows[i] = static_cast<GlobalOrdinal>(records[i * width]);
  std::vector<int> owners(n, -1);
  std::vector<LocalOrdinal> locals(n);
  const auto lookup = map.getRemoteIndexList(Teuchos::ArrayView<const GlobalOrdinal>(rows.data(), n),
                                             Teuchos::ArrayView<int>(owners.data(), n),
                                             Teuchos::ArrayView<LocalOrdinal>(locals.data(), n));
  std::string failure;
  if (lookup != Tpetra::AllIDsPresent) {
    for (std::size_t i = 0; i < n; ++i)
      if (owners[i] < 0) {
        failure = "internal: contribution to row " + std::to_string(rows[i]) + " outside the DoF map";
        break;
      }
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
