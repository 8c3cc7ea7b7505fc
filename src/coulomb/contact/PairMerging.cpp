/// @file PairMerging.cpp
/// @brief mergePairsSharingSlaveNodes (see the header).
#include "coulomb/contact/PairMerging.hpp"

#include <functional>
#include <map>
#include <numeric>
#include <utility>

#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

std::string firstDifferentOption(const ContactPairSettings& a, const ContactPairSettings& b) {
  // Every option of ContactPairSettings except name, slave and master, by
  // its deck name (a new option belongs here too).
  using Same = std::function<bool(const ContactPairSettings&, const ContactPairSettings&)>;
  static const std::vector<std::pair<const char*, Same>> options = {
      {"Formulation", [](const auto& x, const auto& y) { return x.formulation == y.formulation; }},
      {"Penalty", [](const auto& x, const auto& y) { return x.penalty == y.penalty; }},
      {"Penalty Factor", [](const auto& x, const auto& y) { return x.penaltyFactor == y.penaltyFactor; }},
      {"Scale Factor", [](const auto& x, const auto& y) { return x.scaleFactor == y.scaleFactor; }},
      {"Semi-Smooth Newton", [](const auto& x, const auto& y) { return x.semiSmooth == y.semiSmooth; }},
      {"Search Every Iteration",
       [](const auto& x, const auto& y) { return x.searchEveryIteration == y.searchEveryIteration; }},
      {"Search Radius Factor", [](const auto& x, const auto& y) { return x.searchRadiusFactor == y.searchRadiusFactor; }},
      {"Feature Angle", [](const auto& x, const auto& y) { return x.featureAngle == y.featureAngle; }},
      {"Friction Law", [](const auto& x, const auto& y) { return x.friction.type == y.friction.type; }},
      {"Friction Coefficient", [](const auto& x, const auto& y) { return x.friction.coefficient == y.friction.coefficient; }},
      {"Tresca Threshold", [](const auto& x, const auto& y) { return x.friction.threshold == y.friction.threshold; }},
      {"Tangent Factor", [](const auto& x, const auto& y) { return x.tangentFactor == y.tangentFactor; }},
      {"Slip Threshold", [](const auto& x, const auto& y) { return x.slipThreshold == y.slipThreshold; }},
      {"Slip Augmentation Coefficient",
       [](const auto& x, const auto& y) { return x.slipAugmentation == y.slipAugmentation; }},
      {"Slip Reset Frequency", [](const auto& x, const auto& y) { return x.slipResetFrequency == y.slipResetFrequency; }},
      {"Slip Measure", [](const auto& x, const auto& y) { return x.slipMeasure == y.slipMeasure; }},
      {"Operator Threshold", [](const auto& x, const auto& y) { return x.operatorThreshold == y.operatorThreshold; }},
      {"Pure Slip", [](const auto& x, const auto& y) { return x.pureSlip == y.pureSlip; }},
      {"Ensure Contact", [](const auto& x, const auto& y) { return x.ensureContact == y.ensureContact; }},
      {"Friction Coefficient Field",
       [](const auto& x, const auto& y) { return x.frictionCoefficientField == y.frictionCoefficientField; }},
  };
  for (const auto& [name, same] : options)
    if (!same(a, b)) return name;
  return {};
}

std::vector<ContactPairSettings> mergePairsSharingSlaveNodes(const mesh::Mesh& mesh,
                                                             const std::vector<ContactPairSettings>& pairs) {
  if (pairs.size() < 2) return pairs;
  // Union-find over the pairs, joined through their common slave nodes;
  // every rank holds the whole mesh, so every rank finds the same groups.
  std::vector<std::size_t> root(pairs.size());
  std::iota(root.begin(), root.end(), 0);
  std::function<std::size_t(std::size_t)> find = [&](std::size_t p) { return root[p] == p ? p : root[p] = find(root[p]); };
  std::map<long long, std::size_t> slaveOf;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const ContactInterface surfaces(mesh, pairs[p].slave, pairs[p].master, "Contact/Pairs/" + pairs[p].name);
    for (long long node : surfaces.slaveNodes()) {
      const auto [it, first] = slaveOf.emplace(node, p);
      if (first || find(it->second) == find(p)) continue;
      const ContactPairSettings& other = pairs[it->second];
      const std::string option = firstDifferentOption(other, pairs[p]);
      COULOMB_REQUIRE(option.empty(),
                      "deck: 'Contact/Pairs/" << other.name << "' and 'Contact/Pairs/" << pairs[p].name
                                              << "' share slave node " << node + 1
                                              << ", so they are solved as one pair, but their '" << option
                                              << "' differ: give both pairs the same options");
      root[find(p)] = find(it->second);
    }
  }
  std::vector<ContactPairSettings> merged;
  std::map<std::size_t, std::size_t> position;  // group root -> index in merged
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto [it, first] = position.emplace(find(p), merged.size());
    if (first) {
      merged.push_back(pairs[p]);
      continue;
    }
    ContactPairSettings& joined = merged[it->second];
    if (joined.mergedFrom.empty()) joined.mergedFrom.push_back(joined.name);
    joined.mergedFrom.push_back(pairs[p].name);
    joined.name += "+" + pairs[p].name;
    joined.slave += ", " + pairs[p].slave;
    joined.master += ", " + pairs[p].master;
  }
  return merged;
}

}  // namespace coulomb::contact
