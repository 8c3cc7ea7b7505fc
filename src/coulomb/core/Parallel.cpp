#include "coulomb/core/Parallel.hpp"

#include <climits>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "coulomb/core/Error.hpp"

namespace coulomb {

void throwIfAnyRankFailed(const Teuchos::Comm<int>& comm, const std::string& localMessage) {
  const int mine = localMessage.empty() ? INT_MAX : comm.getRank();
  int first = INT_MAX;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == INT_MAX) return;
  int length = comm.getRank() == first ? static_cast<int>(localMessage.size()) : 0;
  Teuchos::broadcast(comm, first, Teuchos::outArg(length));
  std::vector<char> buffer(localMessage.begin(), localMessage.end());
  buffer.resize(length);
  if (length > 0) Teuchos::broadcast(comm, first, length, buffer.data());
  throw Error(std::string(buffer.begin(), buffer.end()));
}

bool anyRank(const Teuchos::Comm<int>& comm, bool local) {
  int value = local ? 1 : 0, result = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, value, Teuchos::outArg(result));
  return result != 0;
}

}  // namespace coulomb
