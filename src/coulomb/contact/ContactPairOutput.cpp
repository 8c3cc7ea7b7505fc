/// @file ContactPairOutput.cpp
/// @brief What a pair reports after an update: its iteration summary summed
/// over ranks (with the set's signature, ActiveSetCycle) and the per-node
/// output fields.
#include <cstdint>

#include <Teuchos_CommHelpers.hpp>

#include "coulomb/contact/ActiveSetCycle.hpp"
#include "coulomb/contact/ContactPair.hpp"

namespace coulomb::contact {

void ContactPair::reduceSummary(PairIterationSummary& summary) const {
  const auto& comm = *interface_->comm();
  const auto sums = PairIterationSummary::sums(summary);
  std::array<double, sums.size()> values{}, totals{};
  for (std::size_t i = 0; i < sums.size(); ++i) values[i] = *sums[i];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(values.size()), values.data(), totals.data());
  for (std::size_t i = 0; i < sums.size(); ++i) *sums[i] = totals[i];
  // The set's signature (ActiveSetCycle): the sum of its nodes' hashes.
  long long signature = 0;
  const auto& owned = interface_->ownedSlaveNodes();
  for (std::size_t i = 0; i < owned.size(); ++i)
    signature += static_cast<long long>(nodeStateHash(interface_->slaveNodes()[owned[i]], static_cast<int>(nodes_[i].state)));
  long long counts[8] = {summary.violations,
                         static_cast<long long>(summary.activeSet.nodes),
                         static_cast<long long>(summary.activeSet.active),
                         static_cast<long long>(summary.activeSet.inactive),
                         static_cast<long long>(summary.activeSet.changed),
                         static_cast<long long>(summary.activeSet.stick),
                         static_cast<long long>(summary.activeSet.stickSlipChanged),
                         signature};
  long long countTotals[8];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 8, counts, countTotals);
  summary.violations = countTotals[0];
  summary.activeSet.nodes = countTotals[1];
  summary.activeSet.active = countTotals[2];
  summary.activeSet.inactive = countTotals[3];
  summary.activeSet.changed = countTotals[4];
  summary.activeSet.stick = countTotals[5];
  summary.activeSet.stickSlipChanged = countTotals[6];
  summary.setSignature = static_cast<std::uint64_t>(countTotals[7]);
}

void ContactPair::addForceIncrements(const std::vector<SlaveNodeState>& before, PairIterationSummary& summary) const {
  const auto& owned = interface_->ownedSlaveNodes();
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const SlaveNodeState &now = nodes_[i], &was = before[i];
    const NodalMortarEntry* entry = mortar_.find(interface_->slaveNodes()[owned[i]]);
    if (!isActive(now.state) || entry == nullptr) continue;
    const double scale = constants_.thickness * entry->D;
    const double dp = scale * (now.pressure - was.pressure);
    summary.normalIncrement2 += dp * dp;
    const auto& n = normals_[owned[i]].n;
    std::array<double, 3> dt{};
    double dn = 0;
    for (int c = 0; c < 3; ++c) dt[c] = scale * (now.traction[c] - was.traction[c]), dn += dt[c] * n[c];
    double tangential2 = 0;
    for (int c = 0; c < 3; ++c) tangential2 += (dt[c] - dn * n[c]) * (dt[c] - dn * n[c]);
    (now.state == ContactState::Stick ? summary.stickIncrement2 : summary.slipIncrement2) += tangential2;
  }
}

std::vector<ContactPair::NodeOutput> ContactPair::nodeOutput() const {
  std::vector<NodeOutput> out;
  const auto& owned = interface_->ownedSlaveNodes();
  for (std::size_t i = 0; i < owned.size(); ++i) {
    NodeOutput o;
    o.node = interface_->slaveNodes()[owned[i]];
    const SlaveNodeState& node = nodes_[i];
    o.state = node.state;
    o.pressure = node.pressure;
    o.penalty = penalty_[i];
    o.augmentedPressure = node.augmentedPressure;
    if (const NodalMortarEntry* entry = mortar_.find(o.node)) {
      o.weightedGap = entry->gap;
      o.area = entry->D;
      // No gap where the node is no contact node (contactWeight: g~ / D of a
      // sliver of overlap is no gap).
      o.gap = contactWeight(*entry) ? entry->gap / entry->D : 0.0;
    }
    if (static_cast<std::size_t>(owned[i]) < normals_.size()) o.normal = normals_[owned[i]].n;
    for (int c = 0; c < 3; ++c) o.multiplier[c] = node.lambdaN * o.normal[c];
    if (frictional()) {
      double tn = 0;
      for (int c = 0; c < 3; ++c) tn += node.traction[c] * o.normal[c];
      for (int c = 0; c < 3; ++c) {
        o.multiplier[c] = node.traction[c] / constants_.k;
        o.tangentialTraction[c] = node.traction[c] - tn * o.normal[c];
        o.augmentedTraction[c] = node.augmentedTraction[c];
        o.weightedSlip[c] = node.weightedSlip[c];
        o.slip[c] = accumulatedSlip_[i][c] + node.slipIncrement[c];
      }
    }
    out.push_back(o);
  }
  return out;
}

}  // namespace coulomb::contact
