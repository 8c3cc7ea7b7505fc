#pragma once
/// @file PairMerging.hpp
/// @brief Contact pairs whose slave surfaces share nodes, joined into one
/// pair (issue 18, item 4).
///
/// Why: a node on the slave surfaces of two pairs (the edge between two
/// slave surfaces, a punch resting on two blocks written as one pair per
/// block) would otherwise get two sets of contact conditions for one set of
/// displacement rows: two multipliers per direction, one of them a
/// duplicated null mode. Joined, the node has one multiplier per direction,
/// its D and M summed over all its slave faces and masters, and one nodal
/// normal averaged over all its slave faces (the mortar operators of the
/// union of the surfaces).
#include <vector>

#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::contact {

/// @brief The pairs of `pairs`, those sharing slave nodes (directly or
/// through a chain) joined into one: name "a+b", slave and master side set
/// lists joined (ContactInterface reads comma-separated lists), the options
/// of the first. Pairs sharing nothing are returned unchanged, in deck order
/// (a joined pair takes the place of its first member). Not collective.
/// @throws coulomb::Error (every rank) naming both pairs, a shared node and
/// the deck parameter when the joined pairs differ in an option (formulation,
/// friction, penalty, ...): one node can follow one contact law only.
std::vector<ContactPairSettings> mergePairsSharingSlaveNodes(const mesh::Mesh& mesh,
                                                             const std::vector<ContactPairSettings>& pairs);

/// @brief The deck name of the first option in which `a` and `b` differ
/// (e.g. "Friction Coefficient"), or empty when every option other than the
/// name and the side sets agrees.
std::string firstDifferentOption(const ContactPairSettings& a, const ContactPairSettings& b);

}  // namespace coulomb::contact
