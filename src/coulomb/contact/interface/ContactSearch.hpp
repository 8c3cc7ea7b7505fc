#pragma once
/// @file ContactSearch.hpp
/// @brief Candidate (slave face, master face) pairs of a contact interface in
/// the current configuration: a bounding-box search with a Boost.Geometry R-tree.
///
/// Criterion: each face's axis-aligned bounding box (current coordinates) is
/// enlarged by r/2 on every side, r the search radius; a master face is a
/// candidate of a slave face when their enlarged boxes intersect (closed boxes:
/// touching counts), i.e. when on every axis the gap between the two plain
/// boxes is at most r. So r is the largest distance (per axis) at which a pair
/// is still found: it must cover the open gaps that may close within a load
/// step. The mortar kernels then decide which candidates really overlap.
///
/// Algorithm: an R-tree (boost::geometry::index::rtree, R*-tree node split,
/// bulk-loaded by packing) over the enlarged boxes of all master faces, built
/// anew for every search (the configuration changes between searches; building
/// is O(M log M) for M master faces), and one intersection query per slave face.
///
/// Parallel: each rank searches only its own slave faces
/// (ContactInterface::ownedSlaveFaces(), a face belongs to the owner of its
/// element) against ALL master faces. Every rank holds the whole mesh and, after
/// InterfaceGather, the current coordinates of every interface node, so a slave
/// face and a master face that live on different ranks are paired with no extra
/// communication; the union over ranks of the per-rank pairs is the same set at
/// any rank count (each slave face is searched by exactly one rank). Only the
/// pair count for logs (globalPairCount) is a collective.
///
/// Overlap beyond the radius: a slave face with no candidate is checked for
/// nodes inside the master body (behind their nearest master face, see
/// FaceProximity.hpp), so that a caller can widen the radius instead of
/// running with no contact where the surfaces overlap.
///
/// Faces with a non-finite coordinate (a diverged Newton iterate) are left out
/// of the search and counted in SearchResult::skippedFaces, so that the caller
/// can reject the iterate instead of failing inside the tree.
#include <vector>

#include <Teuchos_Comm.hpp>

#include "coulomb/contact/interface/ContactInterface.hpp"

namespace coulomb::contact {

/// Factor of the default search radius (see defaultSearchRadius).
inline constexpr double kDefaultSearchRadiusFactor = 1.0;

/// @brief Default search radius: `factor` × the largest diameter (largest
/// distance between two of its nodes) of any slave face in configuration x.
/// Uses all slave faces (replicated), so every rank gets the same value without
/// communication. Throws coulomb::Error if factor is negative or not finite.
double defaultSearchRadius(const ContactInterface& contact, const InterfaceConfiguration& x,
                           double factor = kDefaultSearchRadiusFactor);

/// @brief Candidate master faces per searched slave face.
struct SearchResult {
  double radius = 0.0;          ///< the search radius used
  std::vector<int> slaveFaces;  ///< searched slave faces (indices into ContactInterface::slaveFaces())
  /// candidates[k]: indices into ContactInterface::masterFaces() of the candidates
  /// of slaveFaces[k], increasing.
  std::vector<std::vector<int>> candidates;
  long long skippedFaces = 0;   ///< slave + master faces left out for non-finite coordinates (this rank)
  /// Of the nodes of the searched slave faces with no candidate: the largest
  /// depth at which one lies behind its nearest master face, its projection
  /// on that face (inside the master body, beyond the radius: bodies that
  /// overlap), and that node's global number; 0 and -1 when there is none.
  double unpairedDepth = 0.0;
  long long unpairedNode = -1;

  /// Number of (slave, master) candidate pairs on this rank.
  long long numLocalPairs() const;
};

/// @brief Candidates of the slave faces this rank owns (contact.ownedSlaveFaces()).
/// Not collective. Throws coulomb::Error if radius is negative or not finite.
SearchResult searchContactPairs(const ContactInterface& contact, const InterfaceConfiguration& x, double radius);

/// @brief Candidates of the given slave faces (indices into slaveFaces()).
/// Facing test: a pair whose faces' outward normals (of their corners'
/// planes, FaceProximity.hpp) have n_s . n_m > maximumNormalDot is no
/// candidate (1: no test). Faces turned away from each other, or at right
/// angles — the side of a block beside a flat master — have no contact
/// along the slave normal; on a tilted side face the auxiliary plane still
/// finds an overlap, with gaps measured sideways (SharpEdges.hpp).
SearchResult searchContactPairs(const ContactInterface& contact, const InterfaceConfiguration& x, double radius,
                                const std::vector<int>& slaveFaces, double maximumNormalDot = 1.0);

/// @brief Collective: the total number of candidate pairs over all ranks (for logs).
long long globalPairCount(const SearchResult& result, const Teuchos::Comm<int>& comm);

}  // namespace coulomb::contact
