#pragma once
/// @file ActiveSetCycle.hpp
/// @brief Detects an active set that cycles within a Newton step (issue 15,
/// item 4; issue 17, item 5).
///
/// The semi-smooth Newton method (seed 4.73–4.77) moves the contact and
/// stick/slip sets at every iterate. Near the Coulomb cone or the contact
/// boundary it can revisit the same sets in a fixed order: the sequence of
/// sets is periodic, no set of the cycle holds a solution of the step, and
/// Newton runs into its iteration limit (tests/performance/README.md,
/// neo_hookean_shear_3d: period 5 for 25 iterations; every variant of
/// freezing the cycling nodes converged to a state off the cone, i.e. to no
/// solution). The remedy is the smaller step: a step whose set sequence has
/// repeated for two full periods is failed at once, with a message saying
/// so, and the step controller cuts it back — instead of spending the rest
/// of the iteration limit on the cycle.
///
/// A set is known by a signature (a hash of every slave node's state,
/// ContactPair::update), so that the check costs nothing per node. Only
/// iterates that changed the set are cycle members: an iterate that keeps
/// the set ends any cycle (Newton then converges or not on that set).
#include <cstdint>
#include <string>
#include <vector>

namespace coulomb::contact {

/// One slave node's share of a set signature: a 40-bit hash of (node,
/// state), splitmix64's finaliser, so that neighbouring nodes and states
/// spread over all bits. A set's signature is the sum over its nodes (the
/// same for any partition; 2^23 nodes cannot overflow 63 bits).
std::uint64_t nodeStateHash(long long node, int state);

class ActiveSetCycle {
public:
  /// Periods 2 … kLongestPeriod are detected (a period-1 "cycle" is a set
  /// that does not change).
  static constexpr int kLongestPeriod = 8;
  /// A cycle must span this many changed iterates at least: two periods, and
  /// three for period 2 (a node or two flipping back and forth twice while
  /// the rest of the solution still moves can settle at the next iterate).
  static constexpr int kShortestSpan = 6;

  /// A new step (or a retried one): the history is cleared.
  void clear() { history_.clear(); }
  /// The set after an iterate: its signature, its active node count and how
  /// many nodes changed state (contact or stick/slip) at this iterate.
  void record(std::uint64_t signature, std::size_t active, std::size_t changed);
  /// The period p (≥ 2) when the last max(2p, kShortestSpan) recorded sets
  /// repeat with it, every one of them changed; 0 otherwise. The shortest
  /// such period.
  int period() const;
  /// "the active set cycles with period 5 (68 … 72 active nodes, 2 … 4 state
  /// changes per iterate)"; empty when period() is 0.
  std::string describe() const;

private:
  struct Entry {
    std::uint64_t signature;
    std::size_t active, changed;
  };
  std::vector<Entry> history_;  ///< iterates since the last one that kept the set
};

}  // namespace coulomb::contact
