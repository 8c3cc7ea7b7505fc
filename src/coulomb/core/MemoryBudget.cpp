#include "coulomb/core/MemoryBudget.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace coulomb {
namespace {

/// The first number of a one-value file (cgroup files), or -1 ("max", missing).
long double readNumber(const char* path) {
  std::ifstream in(path);
  long double value = -1;
  if (!(in >> value)) return -1;
  return value;
}

/// MemAvailable of /proc/meminfo in bytes, or 0.
std::uint64_t memAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  std::uint64_t kilobytes = 0;
  while (in >> key >> kilobytes) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return kilobytes * 1024;
  }
  return 0;
}

}  // namespace

std::uint64_t availableMemoryBytes() {
  std::uint64_t available = memAvailable();
  // A container or batch job sees the machine's memory in /proc/meminfo but
  // may use only its cgroup's limit.
  const long double limits[][2] = {
      {readNumber("/sys/fs/cgroup/memory.max"), readNumber("/sys/fs/cgroup/memory.current")},
      {readNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes"),
       readNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes")}};
  for (const auto& limit : limits) {
    // v1 reports "no limit" as a huge number (about 2^63).
    if (limit[0] <= 0 || limit[0] >= 1e18L) continue;
    const long double left = std::max<long double>(limit[0] - std::max<long double>(limit[1], 0), 0);
    const auto bytes = static_cast<std::uint64_t>(left);
    available = available == 0 ? bytes : std::min(available, bytes);
  }
  return available;
}

std::uint64_t meshMemoryLowerBound(long long nodes, long long elements, int dimension, const MemoryBudget& budget) {
  const long double n = static_cast<long double>(std::max(nodes, 0LL));
  const long double e = static_cast<long double>(std::max(elements, 0LL));
  const int d = dimension == 2 ? 2 : 3;
  // Every rank: coordinates (8 bytes each, read once more as per-axis
  // arrays) and the smallest cell's connectivity (8-byte node numbers).
  const long double perRank = n * d * 8 * 2 + e * (d + 1) * 8;
  // The machine's share of the matrix: per DoF row, the node neighbours of a
  // linear mesh times d columns, each an 8-byte value and a 4-byte index.
  const long double neighbours = d == 2 ? 9 : 27;
  const long double matrix = n * d * neighbours * d * 12;
  const long double share = static_cast<long double>(budget.ranksOnHost) / std::max(budget.ranks, 1);
  return static_cast<std::uint64_t>(std::min<long double>(perRank * budget.ranksOnHost + matrix * share, 1.8e19L));
}

std::string meshMemoryProblem(long long nodes, long long elements, int dimension, const MemoryBudget& budget) {
  if (budget.availableBytes == 0) return "";
  const std::uint64_t needed = meshMemoryLowerBound(nodes, elements, dimension, budget);
  if (needed <= budget.availableBytes) return "";
  std::ostringstream out;
  out << nodes << " nodes and " << elements << " elements need at least " << formatBytes(static_cast<double>(needed))
      << " on this machine (";
  if (budget.ranksOnHost > 1) out << "each of its " << budget.ranksOnHost << " ranks holds the whole mesh; ";
  out << "the stiffness matrix alone needs its share), but " << formatBytes(static_cast<double>(budget.availableBytes))
      << " are available: the mesh is too large for this machine"
      << (budget.ranksOnHost > 1 ? " or this many ranks on it" : "") << ", or its header is damaged";
  return out.str();
}

std::string formatBytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while (bytes >= 1000 && unit < 6) {
    bytes /= 1000;
    ++unit;
  }
  std::ostringstream out;
  out << std::setprecision(unit == 0 ? 0 : 3) << (unit == 0 ? std::fixed : std::defaultfloat) << bytes << " "
      << units[unit];
  return out.str();
}

}  // namespace coulomb
