#pragma once
/// @file SelfContactRoles.hpp
/// @brief Self-contact (issue 18, item 5): one surface that may touch itself
/// (a C-shaped ring closing, a crushed tube). The pair lists the surface as
/// both its slave and its master; before each search's mortar pass, every
/// face gets a role for the load step: slave, master or none, so that each
/// contacting region is covered once and no node carries a multiplier while
/// it also receives master forces (the condensed rows could not take both).
///
/// The rule, from the configurations at the start of the load step and now:
///  1. Links: two faces of the surface that share no node, whose enlarged
///     boxes meet (the search radius, ContactSearch.hpp), whose normals
///     oppose (n_a . n_b < -kSelfContactOpposing: more than 120 degrees
///     apart, so a wall and the faces of a corner next to it are not a
///     contact region) and that lie in front of each other (the
///     other's centre at most kSelfContactBehind face diameters behind a
///     face's plane: a penetration of an iterate passes, the far side of a
///     thin wall does not).
///  2. Zones: the linked faces joined through shared nodes (a contact
///     region of the surface); a zone is named by its lowest face index.
///  3. Roles: the zones linked to one another are coloured alternately,
///     starting from the lowest-named zone of each group (slave first), so
///     the two sides of every region get opposite roles. A link inside one
///     zone, or between zones of one colour (an odd loop), cannot be split
///     and is dropped (counted). Two zones never share a node (they would
///     be one), so no node is on both a slave and a master face.
/// Deterministic and the same on every rank and for every partition: the
/// links come from a search of all faces (every rank holds all faces and
/// coordinates; the surface is small next to the volume, once per search).
#include <vector>

#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"

namespace coulomb::contact {

/// Linked faces' normals are further apart than arccos(-this): 120 degrees.
inline constexpr double kSelfContactOpposing = 0.5;
/// How far (in face diameters of the face whose plane it is) the centre of
/// a linked face may lie behind that plane.
inline constexpr double kSelfContactBehind = 0.25;

enum class SelfContactRole : signed char { None = 0, Slave = 1, Master = 2 };

/// @brief Roles of the faces of one surface from its links (pairs of face
/// indices, any order, duplicates allowed). `faces`: the surface's faces
/// (their nodes say which faces are neighbours). Pure, no MPI.
struct SelfContactRoles {
  std::vector<SelfContactRole> role;  ///< per face
  long long droppedLinks = 0;         ///< links that could not be split (see the file comment)
};
SelfContactRoles decideSelfContactRoles(const std::vector<ContactFace>& faces,
                                        std::vector<std::pair<int, int>> links);

/// @brief Whether faces a and b of a self-contact surface are linked in the
/// configuration x (rule 1 without the box test). Pure.
bool selfContactFacesFaceEachOther(int dim, const ContactFace& a, const ContactFace& b,
                                   const InterfaceConfiguration& x);

/// @brief Restricts `search` (this rank's result of searchContactPairs on a
/// self-contact interface in configuration x, radius search.radius) to the
/// slave faces and their master candidates of the roles decided from the
/// links in `startX` and in x together. Not collective; returns the roles
/// (for notes and tests).
///
/// Why both: the links of x alone fail when a load step's predictor pushes
/// one side through the other by more than a linked face may lie behind
/// (kSelfContactBehind), which unlinked the very faces that must touch (a
/// C closing passed its arms through each other); a converged start has no
/// such penetration. The links of `startX` (the last converged
/// configuration) alone miss the faces that come within the search radius
/// only during the step: they are left without mortar values at its end,
/// and the objective slip of the next step lacks their D^t, M^t (a
/// frictional tube then settled into another stick zone than the ordinary
/// pair of its walls).
SelfContactRoles restrictToSelfContactRoles(const ContactInterface& contact, const InterfaceConfiguration& startX,
                                            const InterfaceConfiguration& x, SearchResult& search);

}  // namespace coulomb::contact
