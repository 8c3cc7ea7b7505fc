#include "coulomb/fem/DirichletConstraints.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Tpetra_Vector.hpp>

namespace coulomb::fem {

DirichletConstraints::DirichletConstraints(const mesh::Mesh& mesh, const DofMap& dofs,
                                           const std::vector<DirichletCondition>& conditions)
    : conditions_(conditions) {
  const int dim = mesh.dimension();
  dim_ = dim;
  constrained_.assign(mesh.localNodes().size() * dim, 0);
  std::map<int, Prescribed> byDof;  // later conditions overwrite earlier ones
  for (const auto& c : conditions_) {
    const auto& set = mesh.global().nodeSets[mesh.nodeSetIndex(c.nodeSet, "Dirichlet Conditions/" + c.name + "/Node Set")];
    for (long long node : set.nodes) {
      const int local = mesh.localNode(node);
      if (local < 0) continue;
      if (c.rotation) {
        // Rotate what the earlier conditions prescribe on this node (all components).
        NodeRotation r;
        r.rotation = &c;
        for (int d = 0; d < dim; ++d) {
          r.X[d] = mesh.global().coordinates[node * dim + d];
          const auto it = byDof.find(dofs.localDof(local, d));
          if (it != byDof.end() && it->second.rotation < 0) {
            r.offset[d] = it->second.offset;
            r.base[d] = it->second.function;
          }
        }
        const int index = static_cast<int>(rotations_.size());
        rotations_.push_back(r);
        for (int component : c.components) {
          const int dof = dofs.localDof(local, component);
          constrained_[dof] = 1;
          if (local < mesh.numOwnedNodes()) byDof[dof] = Prescribed{dof, 0.0, &c.function, component, index};
        }
        continue;
      }
      double offset = c.value;
      for (std::size_t d = 0; d < c.linearCoefficients.size(); ++d)
        offset += c.linearCoefficients[d] * mesh.global().coordinates[node * dim + d];
      for (int component : c.components) {
        const int dof = dofs.localDof(local, component);
        constrained_[dof] = 1;
        if (local < mesh.numOwnedNodes()) byDof[dof] = Prescribed{dof, offset, &c.function, component, -1};
      }
    }
  }
  for (const auto& [dof, p] : byDof) owned_.push_back(p);
}

double DirichletConstraints::prescribed(const Prescribed& p, double time) const {
  if (p.rotation < 0) return p.offset * (*p.function)(time);
  // u = R (X + v - C) + C - X, R the rotation by angle f(t) about the axis
  // through C (Rodrigues; 2D: about z).
  const NodeRotation& r = rotations_[static_cast<std::size_t>(p.rotation)];
  const DirichletCondition& c = *r.rotation;
  const double angle = c.rotationAngle * (*p.function)(time);
  std::array<double, 3> q{};  // X + v - C
  for (int d = 0; d < dim_; ++d) q[d] = r.X[d] + (r.base[d] ? r.offset[d] * (*r.base[d])(time) : 0.0) - c.rotationCenter[d];
  const auto& k = c.rotationAxis;
  const double cosA = std::cos(angle), sinA = std::sin(angle);
  const double kq = k[0] * q[0] + k[1] * q[1] + k[2] * q[2];
  const std::array<double, 3> cross = {k[1] * q[2] - k[2] * q[1], k[2] * q[0] - k[0] * q[2], k[0] * q[1] - k[1] * q[0]};
  const int i = p.component;
  const double rotated = q[i] * cosA + cross[i] * sinA + k[i] * kq * (1 - cosA);
  return rotated + c.rotationCenter[i] - r.X[i];
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

bool DirichletConstraints::pendingIncrements(double time, const Vector& ownedU, Vector& ownedPending) const {
  ownedPending.putScalar(0.0);
  auto u = ownedU.getData(0);
  auto pending = ownedPending.getDataNonConst(0);
  // One entry per DoF (the constructor keeps the later of two conditions on it).
  for (const auto& p : owned_) {
    const double target = prescribed(p, time), now = u[p.ownedLocalDof];
    // An iterate that carries ū up to rounding (u + (ū − u) need not be ū
    // to the last bit) has nothing pending.
    const bool carried = std::abs(target - now) <= 1e-12 * std::max(std::abs(target), std::abs(now));
    pending[p.ownedLocalDof] = carried ? 0.0 : target - now;
  }
  return std::any_of(owned_.begin(), owned_.end(), [&](const Prescribed& p) { return pending[p.ownedLocalDof] != 0.0; });
}

std::vector<int> DirichletConstraints::ownedConstrainedDofs() const {
  std::vector<int> result;
  result.reserve(owned_.size());
  for (const auto& p : owned_) result.push_back(p.ownedLocalDof);
  return result;
}

}  // namespace coulomb::fem
