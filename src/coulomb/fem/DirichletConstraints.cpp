#include "coulomb/fem/DirichletConstraints.hpp"

#include <map>

#include <Tpetra_Vector.hpp>

namespace coulomb::fem {

DirichletConstraints::DirichletConstraints(const mesh::Mesh& mesh, const DofMap& dofs,
                                           const std::vector<DirichletCondition>& conditions)
    : conditions_(conditions) {
  const int dim = mesh.dimension();
  constrained_.assign(mesh.localNodes().size() * dim, 0);
  std::map<int, Prescribed> byDof;  // later conditions overwrite earlier ones
  for (const auto& c : conditions_) {
    const auto& set = mesh.global().nodeSets[mesh.nodeSetIndex(c.nodeSet, "Dirichlet Conditions/" + c.name + "/Node Set")];
    for (long long node : set.nodes) {
      const int local = mesh.localNode(node);
      if (local < 0) continue;
      double offset = c.value;
      for (std::size_t d = 0; d < c.linearCoefficients.size(); ++d)
        offset += c.linearCoefficients[d] * mesh.global().coordinates[node * dim + d];
      for (int component : c.components) {
        const int dof = dofs.localDof(local, component);
        constrained_[dof] = 1;
        if (local < mesh.numOwnedNodes()) byDof[dof] = Prescribed{dof, offset, &c.function};
      }
    }
  }
  for (const auto& [dof, p] : byDof) owned_.push_back(p);
}

void DirichletConstraints::setPrescribedValues(double time, Vector& ownedU) const {
  auto u = ownedU.getDataNonConst(0);
  for (const auto& p : owned_) u[p.ownedLocalDof] = prescribed(p, time);
}

void DirichletConstraints::setResidualRows(double time, const Vector& ownedU, Vector& ownedResidual) const {
  auto u = ownedU.getData(0);
  auto r = ownedResidual.getDataNonConst(0);
  for (const auto& p : owned_) r[p.ownedLocalDof] = u[p.ownedLocalDof] - prescribed(p, time);
}

std::vector<int> DirichletConstraints::ownedConstrainedDofs() const {
  std::vector<int> result;
  result.reserve(owned_.size());
  for (const auto& p : owned_) result.push_back(p.ownedLocalDof);
  return result;
}

}  // namespace coulomb::fem
