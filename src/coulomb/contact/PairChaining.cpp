/// @file PairChaining.cpp
/// @brief PairChaining (see the header for the why and the algebra).
#include "coulomb/contact/PairChaining.hpp"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include <Tpetra_Vector.hpp>

#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"

namespace coulomb::contact {
namespace {

bool replacesRows(const ContactPairSettings& s) {
  return s.formulation == ContactFormulation::ALM || s.formulation == ContactFormulation::MPC;
}

std::vector<long long> masterNodes(const ContactInterface& contact) {
  std::vector<long long> nodes;
  for (const ContactFace& f : contact.masterFaces()) nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.begin() + f.numNodes);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

/// Moves the entries of `from` whose row is in `rows` (sorted) to the end of `to`.
template <class Entry>
void moveRows(std::vector<Entry>& from, const std::vector<GlobalOrdinal>& rows, std::vector<Entry>& to) {
  auto keep = std::stable_partition(from.begin(), from.end(), [&](const Entry& e) {
    return !std::binary_search(rows.begin(), rows.end(), e.row);
  });
  to.insert(to.end(), keep, from.end());
  from.erase(keep, from.end());
}

}  // namespace

PairChaining::PairChaining(const std::vector<std::unique_ptr<ContactPair>>& pairs) {
  const std::size_t n = pairs.size();
  slaveRows_.resize(n);
  if (n == 0) return;
  const int dim = pairs[0]->interface().dimension();
  std::vector<std::vector<long long>> masters(n);
  for (std::size_t q = 0; q < n; ++q) masters[q] = masterNodes(pairs[q]->interface());
  // before[p]: the pairs whose master nodes are slave nodes of pair p.
  std::vector<std::set<std::size_t>> before(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (!replacesRows(pairs[p]->settings())) continue;
    std::set<long long> shared;
    for (long long node : pairs[p]->interface().slaveNodes())
      for (std::size_t q = 0; q < n; ++q)
        if (std::binary_search(masters[q].begin(), masters[q].end(), node)) {
          // Within one pair there is no order to fold in: refused, but for
          // a self-contact surface, whose roles keep slave and master
          // nodes apart (SelfContactRoles.hpp).
          if (q == p && pairs[p]->interface().selfContact()) continue;
          COULOMB_REQUIRE(q != p, "Contact/Pairs/" << pairs[p]->settings().name << ": node " << node + 1
                                                   << " is on both the slave and the master surface of the pair; "
                                                      "its condensed rows cannot take both (leave it out of one side "
                                                      "set, or use Formulation = Penalty)");
          before[p].insert(q);
          shared.insert(node);
        }
    for (long long node : shared)
      for (int c = 0; c < dim; ++c) slaveRows_[p].push_back(static_cast<GlobalOrdinal>(dim * node + c));
  }
  // Kahn's order, the deck order among the pairs that are free.
  std::vector<char> done(n, 0);
  while (order_.size() < n) {
    std::size_t next = n;
    for (std::size_t p = 0; p < n && next == n; ++p)
      if (!done[p] && std::all_of(before[p].begin(), before[p].end(), [&](std::size_t q) { return done[q] != 0; }))
        next = p;
    if (next == n) {
      // Every undone pair waits on another undone one: walk back until a
      // pair repeats, then p and q are on the loop.
      std::size_t p = 0;
      while (done[p]) ++p;
      std::vector<char> seen(n, 0);
      auto waitsOn = [&](std::size_t r) {
        for (std::size_t w : before[r])
          if (!done[w]) return w;
        return r;
      };
      while (!seen[p]) {
        seen[p] = 1;
        p = waitsOn(p);
      }
      const std::size_t q = waitsOn(p);
      throw Error("Contact/Pairs/" + pairs[p]->settings().name + " and Contact/Pairs/" + pairs[q]->settings().name +
                  ": each has slave nodes that are master nodes of the other (through a chain of pairs); the condensed "
                  "rows need an order (use Formulation = Penalty for one of them)");
    }
    done[next] = 1;
    order_.push_back(next);
  }
}

ContactContributions PairChaining::take(std::size_t p, ContactContributions& sofar, const Map& map) const {
  const auto& rows = slaveRows_[p];
  ContactContributions taken;
  moveRows(sofar.constraintResidual, rows, taken.constraintResidual);
  moveRows(sofar.contactResidual, rows, taken.contactResidual);
  moveRows(sofar.constraint, rows, taken.constraint);
  moveRows(sofar.tangentTransform, rows, taken.tangentTransform);
  moveRows(sofar.contactStiffness, rows, taken.contactStiffness);
  taken.constraintResidual = linalg::onRowOwners(taken.constraintResidual, map);
  taken.contactResidual = linalg::onRowOwners(taken.contactResidual, map);
  taken.constraint = linalg::onRowOwners(taken.constraint, map);
  taken.tangentTransform = linalg::onRowOwners(taken.tangentTransform, map);
  taken.contactStiffness = linalg::onRowOwners(taken.contactStiffness, map);
  return taken;
}

Teuchos::RCP<Vector> PairChaining::residualFor(const Vector& r, const ContactContributions& taken) {
  auto out = Teuchos::rcp(new Vector(r, Teuchos::Copy));
  for (const auto* part : {&taken.contactResidual, &taken.constraintResidual})
    for (const auto& e : *part) out->sumIntoGlobalValue(e.row, e.value);
  return out;
}

void PairChaining::restore(ContactContributions&& taken, ContactContributions& mine, const Map& map) {
  // f_c, K_c: inside T (r - f_c), (T + ...)(K + K_c), whatever the row.
  mine.contactResidual.insert(mine.contactResidual.end(), taken.contactResidual.begin(), taken.contactResidual.end());
  mine.contactStiffness.insert(mine.contactStiffness.end(), taken.contactStiffness.begin(), taken.contactStiffness.end());
  std::unordered_set<GlobalOrdinal> replaced;
  for (const auto& t : mine.transform)
    if (t.row == t.column) replaced.insert(t.row);
  // B's coefficients on each replaced K row t: (t', d).
  std::unordered_map<GlobalOrdinal, std::vector<std::pair<GlobalOrdinal, double>>> onRow;
  for (const auto& t : mine.tangentTransform)
    if (replaced.count(t.column)) onRow[t.column].push_back({t.row, t.value});
  for (const auto& e : taken.constraintResidual)
    if (!replaced.count(e.row)) mine.constraintResidual.push_back(e);  // else inside B's conditions
  for (const auto& t : taken.constraint) {
    if (!replaced.count(t.row)) {
      mine.constraint.push_back(t);
      continue;
    }
    for (const auto& [target, d] : onRow[t.row]) mine.constraint.push_back({target, t.column, d * t.value});
  }
  std::vector<linalg::MatrixTriplet> folded;  // rows of K to combine: on the owners of those rows
  for (const auto& t : taken.tangentTransform) {
    if (!replaced.count(t.row)) {
      folded.push_back(t);
      continue;
    }
    for (const auto& [target, d] : onRow[t.row]) folded.push_back({target, t.column, d * t.value});
  }
  // Route by column: swap, route to row owners, swap back.
  for (auto& t : folded) std::swap(t.row, t.column);
  folded = linalg::onRowOwners(folded, map);
  for (auto& t : folded) std::swap(t.row, t.column);
  mine.tangentTransform.insert(mine.tangentTransform.end(), folded.begin(), folded.end());
}

}  // namespace coulomb::contact
