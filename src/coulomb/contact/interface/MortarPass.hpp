#pragma once
/// @file MortarPass.hpp
/// @brief The mortar pass: nodal D_j, M_jl and weighted gaps g~_j of the slave
/// nodes, with their derivatives with respect to the interface coordinates,
/// integrated over this rank's (slave face, candidate master face) pairs and
/// then summed to the owners of the slave nodes.
///
/// Quantities (seed eq. 4.63; MortarSegment2D.hpp / MortarSegment3D.hpp):
///   D_j  = sum over pairs of int_seg Phi_j dA        (dual basis: D is diagonal),
///   M_jl = sum over pairs of int_seg Phi_j N^2_l dA,
///   g~_j = sum over pairs of int_seg Phi_j g_n dA     (g_n > 0 open).
///
/// Derivatives: with respect to the current coordinates x_{k,c} of the interface
/// nodes (global node k, component c), i.e. with respect to the displacement DoF
/// (k, c) since x = X + u. Each segment kernel gives the derivatives with respect
/// to the slave coordinates, the slave nodal normals and the master coordinates
/// (linearizeSegment2D / linearizeSegment3D); the normal part is carried to the
/// coordinates by the chain rule d q / d x = d q / d n_a . d n_a / d x with the
/// sparse dn/dx of NodalNormals (so the pattern of a slave node's row reaches the
/// nodes of the slave faces around the slave nodes of its faces, and the master
/// nodes of the paired master faces). The derivatives are those of the current
/// overlap topology (the kernels' convention).
///
/// Parallel: integrateMortarPass is local (the pairs of the slave faces this rank
/// owns; every rank holds all coordinates after InterfaceGather). A slave node on
/// a boundary between partitions gets contributions from faces of several ranks;
/// sumToOwners (collective) adds them up on the owning rank of the node
/// (Mesh::nodeOwner, ContactInterface::ownedSlaveNodes()). See MortarPass.cpp for
/// the communication (one MPI_Alltoall of counts + one MPI_Alltoallv of packed
/// doubles).
#include <map>
#include <utility>
#include <vector>

#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"
#include "coulomb/contact/interface/NodalNormals.hpp"

namespace coulomb::contact {

/// (global node, coordinate component): one column of a derivative.
using DofKey = std::pair<long long, int>;
/// A sparse derivative row: d q / d x_{node, component}, sorted by (node, component).
using DerivativeRow = std::map<DofKey, double>;

/// @brief The mortar quantities of one slave node j.
struct NodalMortarEntry {
  long long node = -1;                        ///< global node number of the slave node j
  double D = 0.0;                             ///< D_j
  double gap = 0.0;                           ///< weighted gap g~_j
  std::map<long long, double> M;              ///< M_jl by global master node l
  DerivativeRow dD;                           ///< d D_j / d x
  DerivativeRow dGap;                         ///< d g~_j / d x
  std::map<long long, DerivativeRow> dM;      ///< d M_jl / d x by master node l
  /// Adds another contribution to the same node (values and derivatives).
  void add(const NodalMortarEntry& other);
};

/// @brief Nodal mortar quantities: one entry per slave node (sorted by node).
struct NodalMortarQuantities {
  int dimension = 3;
  bool withDerivatives = false;
  std::vector<NodalMortarEntry> entries;  ///< increasing node numbers, no duplicates
  /// The entry of a global node, or nullptr.
  const NodalMortarEntry* find(long long node) const;
};

/// @brief Integrates every (slave face, candidate) pair of `pairs` and accumulates
/// the nodal quantities of the slave nodes of these faces. Not collective.
///
/// `normals`: one entry per ContactInterface::slaveNodes() entry (as returned by
/// computeNodalNormals); those of the nodes of the searched slave faces must be
/// computed, with derivatives when `withDerivatives`. Result: one entry per node
/// of a slave face that has at least one contributing pair (partial sums: the
/// contributions of this rank's faces only).
/// `relativeTolerance`: passed to the segment kernels (merge, on-edge band
/// and area tolerances, relative to the face); 1e-12 because the objective
/// slip sees a jump of M_jl at the tolerance (docs/architecture.md, "Coverage").
NodalMortarQuantities integrateMortarPass(const ContactInterface& contact, const InterfaceConfiguration& x,
                                          const std::vector<NodalNormal>& normals, const SearchResult& pairs,
                                          bool withDerivatives, double relativeTolerance = 1e-12);

/// @brief Collective: sums the partial quantities of all ranks on the owner of
/// each slave node. Returns the entries of the owned slave nodes that received a
/// contribution on some rank (increasing nodes). The summation order is by
/// rank, so results are deterministic for a given rank count.
NodalMortarQuantities sumToOwners(const ContactInterface& contact, const NodalMortarQuantities& local);

}  // namespace coulomb::contact
