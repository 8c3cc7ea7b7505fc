#include "coulomb/contact/ActiveSetCycle.hpp"

#include <algorithm>
#include <sstream>

namespace coulomb::contact {

std::uint64_t nodeStateHash(long long node, int state) {
  std::uint64_t h = static_cast<std::uint64_t>(node) * 4 + static_cast<std::uint64_t>(state);
  h += 0x9e3779b97f4a7c15ULL;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  h ^= h >> 31;
  return h >> 24;
}

void ActiveSetCycle::record(std::uint64_t signature, std::size_t active, std::size_t changed) {
  if (changed == 0) {
    history_.clear();
    return;
  }
  history_.push_back({signature, active, changed});
  // Two longest periods are all period() ever looks at.
  const std::size_t keep = 2 * kLongestPeriod;
  if (history_.size() > keep) history_.erase(history_.begin(), history_.end() - keep);
}

int ActiveSetCycle::period() const {
  const int n = static_cast<int>(history_.size());
  for (int p = 2; p <= kLongestPeriod; ++p) {
    const int span = std::max(2 * p, kShortestSpan);
    if (span > n) break;
    bool repeats = true;
    for (int k = n - span + p; k < n && repeats; ++k) repeats = history_[k].signature == history_[k - p].signature;
    // Sets that repeat with period p but are all one set are no cycle (a
    // changed iterate cannot return to its own set unless signatures collide).
    bool constant = true;
    for (int k = n - p + 1; k < n && constant; ++k) constant = history_[k].signature == history_[n - p].signature;
    if (repeats && !constant) return p;
  }
  return 0;
}

std::string ActiveSetCycle::describe() const {
  const int p = period();
  if (p == 0) return "";
  std::size_t fewest = history_.back().active, most = fewest, least = history_.back().changed, largest = least;
  for (auto it = history_.end() - std::max(2 * p, kShortestSpan); it != history_.end(); ++it) {
    fewest = std::min(fewest, it->active), most = std::max(most, it->active);
    least = std::min(least, it->changed), largest = std::max(largest, it->changed);
  }
  std::ostringstream out;
  out << "the active set cycles with period " << p << " (" << fewest;
  if (most != fewest) out << " … " << most;
  out << " active nodes, " << least;
  if (largest != least) out << " … " << largest;
  out << " state changes per iterate)";
  return out.str();
}

}  // namespace coulomb::contact
