#include "coulomb/core/Parallel.hpp"

#include <climits>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <mpi.h>

#include "coulomb/core/Error.hpp"

namespace coulomb {

namespace {

/// The message of the lowest rank that has one, on every rank; empty when none has.
std::string agreedMessage(const Teuchos::Comm<int>& comm, const std::string& localMessage) {
  const int mine = localMessage.empty() ? INT_MAX : comm.getRank();
  int first = INT_MAX;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == INT_MAX) return std::string();
  int length = comm.getRank() == first ? static_cast<int>(localMessage.size()) : 0;
  Teuchos::broadcast(comm, first, Teuchos::outArg(length));
  std::vector<char> buffer(localMessage.begin(), localMessage.end());
  buffer.resize(length);
  if (length > 0) Teuchos::broadcast(comm, first, length, buffer.data());
  std::string message(buffer.begin(), buffer.end());
  return message.empty() ? std::string("(no message)") : message;
}

}  // namespace

void throwIfAnyRankFailed(const Teuchos::Comm<int>& comm, const std::string& localMessage) {
  const std::string message = agreedMessage(comm, localMessage);
  if (!message.empty()) throw Error(message);
}

void throwEvaluationErrorIfAnyRank(const Teuchos::Comm<int>& comm, const std::string& localMessage) {
  const std::string message = agreedMessage(comm, localMessage);
  if (!message.empty()) throw EvaluationError(message);
}

bool anyRank(const Teuchos::Comm<int>& comm, bool local) {
  int value = local ? 1 : 0, result = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, value, Teuchos::outArg(result));
  return result != 0;
}

std::vector<double> exchangeByRank(const Teuchos::Comm<int>& comm, std::vector<std::vector<double>> send) {
  const int size = comm.getSize();
  COULOMB_CHECK(static_cast<int>(send.size()) == size, "exchangeByRank needs one buffer per rank");
  if (size == 1) return std::move(send[0]);
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  COULOMB_CHECK(mpi != nullptr, "Coulomb needs an MPI Teuchos communicator");
  const MPI_Comm raw = *mpi->getRawMpiComm();
  std::vector<int> sendCounts(size), sendOffsets(size + 1, 0), recvCounts(size), recvOffsets(size + 1, 0);
  std::vector<double> flat;
  for (int r = 0; r < size; ++r) {
    COULOMB_CHECK(send[r].size() < static_cast<std::size_t>(1) << 30, "exchange buffer too large");
    sendCounts[r] = static_cast<int>(send[r].size());
    sendOffsets[r + 1] = sendOffsets[r] + sendCounts[r];
    flat.insert(flat.end(), send[r].begin(), send[r].end());
  }
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, raw);
  for (int r = 0; r < size; ++r) recvOffsets[r + 1] = recvOffsets[r] + recvCounts[r];
  std::vector<double> received(static_cast<std::size_t>(recvOffsets[size]));
  MPI_Alltoallv(flat.data(), sendCounts.data(), sendOffsets.data(), MPI_DOUBLE, received.data(), recvCounts.data(),
                recvOffsets.data(), MPI_DOUBLE, raw);
  return received;
}

MemoryBudget memoryBudget(const Teuchos::Comm<int>& comm) {
  MemoryBudget budget;
  budget.ranks = comm.getSize();
  int onHost = 1;
  if (const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm)) {
    MPI_Comm host = MPI_COMM_NULL;
    MPI_Comm_split_type(*mpi->getRawMpiComm(), MPI_COMM_TYPE_SHARED, comm.getRank(), MPI_INFO_NULL, &host);
    MPI_Comm_size(host, &onHost);
    MPI_Comm_free(&host);
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, onHost, Teuchos::outArg(budget.ranksOnHost));
  // 0 (unknown) on any rank means no check anywhere.
  const unsigned long long mine = availableMemoryBytes();
  unsigned long long least = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(least));
  budget.availableBytes = least;
  return budget;
}

}  // namespace coulomb
