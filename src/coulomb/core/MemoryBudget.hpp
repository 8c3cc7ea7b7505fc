#pragma once
/// @file MemoryBudget.hpp
/// @brief How much memory this machine can give a run, and a lower bound of
/// what a mesh will take, so that a mesh too large for the machine (or one
/// whose header declares absurd counts) is refused with a message before
/// anything is allocated, instead of ending in an out-of-memory kill.
#include <cstdint>
#include <string>

namespace coulomb {

/// The memory this process may still use: MemAvailable of /proc/meminfo,
/// lowered by a cgroup limit (v2 memory.max − memory.current, or v1
/// memory.limit_in_bytes − usage) where one is set. 0 when nothing can be
/// read (then no check is made).
std::uint64_t availableMemoryBytes();

/// What the ranks of one machine share, and how many they are.
struct MemoryBudget {
  std::uint64_t availableBytes = 0;  ///< on this machine, for all its ranks; 0 = unknown (no check)
  int ranksOnHost = 1;               ///< ranks of the run on this machine
  int ranks = 1;                     ///< ranks of the run
};

/// A lower bound of the bytes the ranks on one machine need for a mesh of
/// `nodes` nodes and `elements` elements in `dimension` D: every rank holds
/// the whole mesh as read (coordinates, connectivity of the smallest cell),
/// and the machine's share of the global stiffness matrix (at least the
/// nonzeros of a vertex-connected linear mesh, 9 (2D) or 27 (3D) node
/// neighbours times dimension² values with their column indices).
std::uint64_t meshMemoryLowerBound(long long nodes, long long elements, int dimension, const MemoryBudget& budget);

/// "" when the lower bound fits the budget (or the budget is unknown),
/// else the reason, for a one-line error after "mesh 'FILE': ".
std::string meshMemoryProblem(long long nodes, long long elements, int dimension, const MemoryBudget& budget);

/// Bytes as a person reads them: "512 MB", "23.4 GB".
std::string formatBytes(double bytes);

}  // namespace coulomb
