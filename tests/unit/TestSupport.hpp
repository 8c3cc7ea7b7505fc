#pragma once
// Helpers for the MPI tests: scratch folders, decks written on rank 0,
// distorted copies of shipped meshes, owned nodal displacements.
#include <functional>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/mesh/GlobalMesh.hpp"
#include "coulomb/solver/Simulation.hpp"

namespace coulomb::test {

Teuchos::RCP<const Teuchos::Comm<int>> worldComm();
/// A scratch folder under the build tree, unique per test and rank count.
std::string scratchDirectory(const std::string& name);
/// Rank 0 writes `text` to `path`; every rank waits for it.
void writeOnRoot(const std::string& path, const std::string& text);
/// Path of a mesh made by the `meshes` target.
std::string shippedMesh(const std::string& file);
/// Rank 0 writes a copy of `source` whose nodes outside every node set are
/// moved by up to `amplitude` × the local mesh size (deterministic pseudo-random).
/// Mid-side nodes of quadratic cells move too (their edges curve), unless
/// `straightEdges`: then every higher-order node is put back at the mean of its
/// corners (mesh::nodeCorners), and the cells stay straight-sided.
void writeDistortedCopy(const std::string& source, const std::string& target, double amplitude,
                        bool straightEdges = false);

/// A deck: materials/blocks for one block "body", then `body` (more sublists).
std::string deckXml(const std::string& meshFile, const std::string& material, const std::string& body);
/// The material parameters of a compressible Neo-Hookean solid (deckXml's `material`).
std::string neoHookeanXml(double youngsModulus, double poissonsRatio);
std::string dirichletXml(const std::string& name, const std::string& nodeSet, const std::string& component,
                         double value, const std::vector<double>& coefficients = {}, const std::string& function = "ramp");

/// Calls f(globalNode, X, u) for every owned node of a finished simulation.
void forOwnedNodes(const solver::Simulation& simulation,
                   const std::function<void(long long, const double*, const double*)>& f);
/// The largest nodal error of a finished simulation against the linear
/// field u_i = b_i + A_ij X_j, and the largest |u_i| of that field, over all
/// ranks: the patch tests' measure.
struct LinearFieldError {
  double error = 0, value = 0;
};
LinearFieldError linearFieldError(const solver::Simulation& simulation, const double (&A)[3][3], const double (&b)[3]);
/// Max over ranks.
double globalMax(double local);
double globalSum(double local);

}  // namespace coulomb::test
