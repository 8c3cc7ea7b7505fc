#pragma once
/// @file InterfaceBalance.hpp
/// @brief Which rank integrates which slave face: the faces redistributed
/// over all ranks by the work their candidates make.
///
/// Why: the bulk partition (mesh/Partition.hpp) balances elements, and a
/// contact interface is a small part of the volume, so its faces sit on a
/// few ranks — often one or two of many — while the others wait for them in
/// every mortar pass (search, D, M, g~ and their Sacado derivatives, the most
/// expensive part of a contact iterate).
///
/// How: every rank holds all faces and all current interface coordinates
/// (InterfaceGather), so any rank can integrate any slave face; sumToOwners
/// already sends each contribution to the owner of its slave node. The
/// faces a rank integrates are therefore a free choice. Here they are a
/// Zoltan2 multi-jagged partition of the faces' reference centroids (compact
/// groups: a node's faces tend to share a rank, fewer partial sums to send),
/// weighted by the face's cost in the last search: one for its search plus
/// one per candidate master face (a segment each). What stays with the bulk
/// partition is the slave node's own work (active set, condensation), which
/// needs its rows of K.
#include <vector>

#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"

namespace coulomb::contact {

/// @brief Collective: the slave faces this rank integrates after balancing
/// (indices into contact.slaveFaces(), increasing). `faces`: those it
/// integrated so far; `searched`: its search result of them (the weights;
/// a face missing from it counts as one). Every slave face listed on some
/// rank lands on exactly one rank.
std::vector<int> balancedSlaveFaces(const ContactInterface& contact, const std::vector<int>& faces,
                                    const SearchResult& searched);

/// @brief The slave nodes of the given slave faces (indices into slaveNodes(), increasing).
std::vector<int> slaveNodesOfFaces(const ContactInterface& contact, const std::vector<int>& faces);

}  // namespace coulomb::contact
