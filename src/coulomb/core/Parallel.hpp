#pragma once
/// @file Parallel.hpp
/// @brief Agreement on failures that only some ranks can detect, so that
/// every rank throws the same coulomb::Error and none hangs.
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>

#include "coulomb/core/MemoryBudget.hpp"

namespace coulomb {

/// @brief Collective: if any rank passes a non-empty `localMessage`, every
/// rank throws coulomb::Error with the message of the lowest such rank.
void throwIfAnyRankFailed(const Teuchos::Comm<int>& comm, const std::string& localMessage);

/// @brief Collective: like throwIfAnyRankFailed, but throws
/// coulomb::EvaluationError (the iterate is rejected, the step cut back).
void throwEvaluationErrorIfAnyRank(const Teuchos::Comm<int>& comm, const std::string& localMessage);

/// @brief Collective logical or.
bool anyRank(const Teuchos::Comm<int>& comm, bool local);

/// @brief Collective personalised exchange: `send[r]` goes to rank r; returns
/// what every rank sent here, concatenated in rank order (one MPI_Alltoall of
/// the sizes, one MPI_Alltoallv of the doubles). `send` has one entry per rank.
std::vector<double> exchangeByRank(const Teuchos::Comm<int>& comm, std::vector<std::vector<double>> send);

/// @brief Collective: the run's memory budget, the same on every rank so
/// that all reach the same verdict on a mesh: the smallest available memory
/// of any machine, the most ranks on one machine (MPI_COMM_TYPE_SHARED).
MemoryBudget memoryBudget(const Teuchos::Comm<int>& comm);

}  // namespace coulomb
