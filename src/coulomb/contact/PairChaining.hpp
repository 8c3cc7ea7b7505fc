#pragma once
/// @file PairChaining.hpp
/// @brief Nodes that are a slave node of one pair and a master node of
/// another (issue 18, item 4): the corner of a block whose side is a slave
/// surface and whose top is the master of a punch, a body pressed between
/// two others at an edge.
///
/// Why: a condensed pair (ALM, MPC) replaces the rows of its active slave
/// node j by the node's contact conditions and recovers the multiplier from
/// the node's residual (ContactPair.hpp). When j is also a master node of an
/// earlier pair A, A puts its recovered force g^A_j (and f_c^A_j for a
/// penalty A) on those rows, outside the replaced part: the conditions then
/// carry a foreign force and the multiplier misses it (Newton does not
/// converge, or converges to a wrong state). So:
///  - pairs are updated in an order where A comes before every pair B whose
///    slave nodes are A's master nodes (a cycle is refused);
///  - before B's update, the earlier pairs' entries on B's slave rows are
///    taken out and moved to the owners of those rows (take());
///  - B recovers its multipliers from r + (those forces) (residualFor());
///  - after B's update (restore()): on the rows B replaced, A's force is
///    now inside B's conditions through that residual, so A's g and G leave
///    the system and its derivative enters B's by the chain rule: every
///    coefficient d of B on the K row t (tangentTransform, (t', t, d)) also
///    takes d × A's derivative rows at t (G^A and tangentTransform^A);
///    A's f_c, K_c stay (T applies to them). Rows B left open get A's
///    entries back unchanged.
#include <cstddef>
#include <memory>
#include <vector>

#include "coulomb/contact/ContactContributions.hpp"
#include "coulomb/core/TpetraTypes.hpp"

namespace coulomb::contact {

class ContactPair;

class PairChaining {
public:
  /// Not collective (every rank holds every pair's nodes). Throws
  /// coulomb::Error naming two pairs of a cycle, or a condensed pair and a
  /// node on both its slave and its master surface.
  explicit PairChaining(const std::vector<std::unique_ptr<ContactPair>>& pairs);

  /// The order in which to update the pairs (indices into pairs).
  const std::vector<std::size_t>& order() const { return order_; }
  /// Pair p has slave rows that earlier pairs may reach.
  bool chained(std::size_t p) const { return !slaveRows_[p].empty(); }
  /// Some pair is chained.
  bool anyChained() const {
    for (const auto& rows : slaveRows_)
      if (!rows.empty()) return true;
    return false;
  }

  /// Collective, before pair p's update when chained(p): takes the entries
  /// of `sofar` on pair p's slave rows out of it, onto the owners of the rows.
  ContactContributions take(std::size_t p, ContactContributions& sofar, const Map& map) const;
  /// The residual pair p recovers its multipliers from: r + the taken forces.
  static Teuchos::RCP<Vector> residualFor(const Vector& r, const ContactContributions& taken);
  /// Collective, after pair p's update into `mine`: the taken entries
  /// folded into it (see the file comment). The folded tangentTransform
  /// entries go to the owners of their columns, as ContactModel's tangent
  /// needs (it combines rows of K where they live).
  static void restore(ContactContributions&& taken, ContactContributions& mine, const Map& map);

private:
  std::vector<std::size_t> order_;
  /// Per pair: the sorted global DoF rows of its slave nodes that are
  /// master nodes of another pair (empty unless the pair is condensed).
  std::vector<std::vector<GlobalOrdinal>> slaveRows_;
};

}  // namespace coulomb::contact
