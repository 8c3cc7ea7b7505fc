// ContactPair::updateSaddlePoint: the ALM frictionless contact with the dual
// multipliers kept as Newton unknowns (MultiplierBlock in ContactPair.hpp),
// deck `Contact/System Form` = Saddle Point. The condensed form
// (ContactPair::update) is the production path; this one exists to check it:
// the same mortar values and derivatives, the nodal law of NodalContactLaw
// (4.72b, components form, vector multiplier) instead of the condensation.
#include <cmath>

#include <Tpetra_Vector.hpp>

#include "coulomb/contact/CondensationFrame.hpp"
#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/contact/NodalContactLaw.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::contact {

namespace {

/// almResidual of either dimension, widened to 3 components.
template <int dim>
AlmNodeResidual<3> widenedResidual(const std::array<double, 3>& lambda, const std::array<double, 3>& n, double gap,
                                   double D, const AlmParameters& p, ContactState state) {
  AlmNodeInput<dim> in;
  for (int c = 0; c < dim; ++c) {
    in.lambda[c] = lambda[c];
    in.normal[c] = n[c];
  }
  in.gap = gap;
  in.D = D;
  const auto r = almResidual<dim>(in, p, state);
  AlmNodeResidual<3> out;
  for (int i = 0; i < dim; ++i) {
    out.r[i] = r.r[i];
    out.dGap[i] = r.dGap[i];
    out.dD[i] = r.dD[i];
    for (int c = 0; c < dim; ++c) {
      out.dLambda[i][c] = r.dLambda[i][c];
      out.dNormal[i][c] = r.dNormal[i][c];
    }
  }
  return out;
}

/// A slave node whose free components cannot carry its normal multiplier
/// (CondensationFrame::usable) stays inactive, as in the condensed form.
bool frameUsable(int dim, const std::array<double, 3>& n, const std::array<bool, 3>& prescribed) {
  if (dim == 2) return condensationFrame<2>(std::array<double, 2>{n[0], n[1]},
                                            std::array<bool, 2>{prescribed[0], prescribed[1]}).usable;
  return condensationFrame<3>(n, prescribed).usable;
}

}  // namespace

PairIterationSummary ContactPair::updateSaddlePoint(const Vector& u, const std::vector<std::array<double, 3>>& z,
                                                    bool updateSet, ContactContributions& out) {
  COULOMB_REQUIRE(settings_.formulation == ContactFormulation::ALM && !frictional(),
                  "internal: the saddle-point form is for ALM frictionless pairs");
  searchAndIntegrate(u);
  const auto& slaveNodes = interface_->slaveNodes();
  const auto& owned = interface_->ownedSlaveNodes();
  COULOMB_REQUIRE(z.size() == owned.size(), "internal: one multiplier per owned slave node");
  const double t = thickness_;
  // z_j = (k / eps_n,j) lambda_j; rows R_j = (eps_n,j t / k) r_lambda,j.
  PairIterationSummary summary;
  std::string failure;

  std::vector<char> usable(owned.size(), 0), differentiateNode(owned.size(), 0);
  std::vector<std::array<double, 3>> lambda(owned.size());
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const ContactState previous = state_[i];
    for (int c = 0; c < 3; ++c) lambda[i][c] = penalty_[i] / k_ * z[i][c];
    const NodalMortarEntry* entry = mortar_.find(node);
    usable[i] = entry != nullptr && entry->D > minimumD_ &&
                frameUsable(dim_, normals_[s].n, prescribed_[interface_->interfaceNodeIndex(node)]);
    double lambdaN = 0;
    ContactState state = previous;
    if (usable[i]) {
      for (int c = 0; c < dim_; ++c) lambdaN += lambda[i][c] * normals_[s].n[c];
      state = nextState(almContactState(lambdaN, entry->gap, entry->D, k_, penalty_[i], touchingGap()), previous, updateSet,
                        summary.violations);
    } else {
      state = ContactState::Inactive;
    }
    state_[i] = state;
    countState(summary.activeSet, state, previous);
    if (state == ContactState::Active) {
      std::string deep = penetrationFailure(node, entry->gap, entry->D);
      if (failure.empty()) failure = std::move(deep);
    }
    lambdaN_[i] = state == ContactState::Active ? lambdaN : 0.0;
    pressure_[i] = -k_ * lambdaN_[i];
    // Derivatives where the rows or forces depend on the geometry: active
    // nodes (gap), and inactive ones still carrying a multiplier (n, D).
    const bool carries = lambda[i][0] != 0.0 || lambda[i][1] != 0.0 || lambda[i][2] != 0.0;
    differentiateNode[i] = usable[i] && (state == ContactState::Active || carries);
  }
  widenSearchRadius();
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  differentiate(differentiateNode);

  auto row = [this](long long node, int c) { return dofRow(node, c); };
  auto emitDerivative = [&](GlobalOrdinal target, const DerivativeRow& from, double scale) {
    for (const auto& [key, value] : from)
      if (!isPrescribed(key.first, key.second) && value != 0.0)
        out.multipliers.rows.push_back({target, row(key.first, key.second), scale * value});
  };
  auto emitStiffness = [&](GlobalOrdinal target, const DerivativeRow& from, double scale) {
    for (const auto& [key, value] : from)
      if (!isPrescribed(key.first, key.second) && value != 0.0)
        out.contactStiffness.push_back({target, row(key.first, key.second), scale * value});
  };

  for (std::size_t i = 0; i < owned.size(); ++i) {
    const int s = owned[i];
    const long long node = slaveNodes[s];
    if (!usable[i]) {
      // No mortar entry (or not usable): the multiplier vanishes, R = t eps_n h^(dim-1) z.
      const double scale = t * penalty_[i] * referenceD_;
      for (int c = 0; c < dim_; ++c) {
        out.multipliers.rows.push_back({multiplierDof(s, c), multiplierDof(s, c), scale});
        out.multipliers.residual.push_back({multiplierDof(s, c), scale * z[i][c]});
      }
      continue;
    }
    const bool withDerivatives = differentiateNode[i] != 0;
    const NodalMortarEntry* entry = withDerivatives ? mortarDerivatives_.find(node) : mortar_.find(node);
    COULOMB_REQUIRE(entry != nullptr, "internal: a differentiated node has its mortar entry");
    const auto& normal = withDerivatives ? normalDerivatives_[s] : normals_[s];
    const double D = entry->D;
    const double toLambda = penalty_[i] / k_, rowScale = penalty_[i] * t / k_;
    const AlmParameters parameters{k_, penalty_[i], penalty_[i]};
    const auto law =
        dim_ == 2 ? widenedResidual<2>(lambda[i], normal.n, entry->gap, D, parameters, state_[i])
                  : widenedResidual<3>(lambda[i], normal.n, entry->gap, D, parameters, state_[i]);

    // The multiplier rows: R, dR/dz, dR/du (through g~, n, D).
    for (int a = 0; a < dim_; ++a) {
      const GlobalOrdinal target = multiplierDof(s, a);
      out.multipliers.residual.push_back({target, rowScale * law.r[a]});
      for (int c = 0; c < dim_; ++c)
        out.multipliers.rows.push_back({target, multiplierDof(s, c), rowScale * toLambda * law.dLambda[a][c]});
      if (!withDerivatives) continue;
      emitDerivative(target, entry->dGap, rowScale * law.dGap[a]);
      emitDerivative(target, entry->dD, rowScale * law.dD[a]);
      for (const auto& d : normal.derivative) {
        double value = 0;
        for (int c = 0; c < dim_; ++c) value += law.dNormal[a][c] * d.dn[c];
        if (value != 0.0 && !isPrescribed(d.node, d.component))
          out.multipliers.rows.push_back({target, row(d.node, d.component), rowScale * value});
      }
    }
    if (state_[i] == ContactState::Active)
      summary.normalResidual2 += (penalty_[i] * t * entry->gap) * (penalty_[i] * t * entry->gap);

    // Forces on the bodies (NodalContactLaw): slave k t D lambda, master
    // -k t M_jl lambda; the displacement rows carry r - f_c, the columns
    // C = -df/dz, and K_c = -df/du through D and M (lambda is an unknown).
    for (int c = 0; c < dim_; ++c) {
      const double force = k_ * t * D * lambda[i][c];
      if (state_[i] == ContactState::Active) {
        summary.slaveForce[c] += force;
        summary.normalForce[c] += force;
        summary.contactForce2 += force * force;
      }
      if (!isPrescribed(node, c)) {
        out.contactResidual.push_back({row(node, c), -force});
        out.multipliers.columns.push_back({row(node, c), multiplierDof(s, c), -k_ * t * D * toLambda});
        if (withDerivatives) emitStiffness(row(node, c), entry->dD, -k_ * t * lambda[i][c]);
      }
      for (const auto& [master, Mjl] : entry->M) {
        if (isPrescribed(master, c)) continue;
        out.contactResidual.push_back({row(master, c), k_ * t * Mjl * lambda[i][c]});
        out.multipliers.columns.push_back({row(master, c), multiplierDof(s, c), k_ * t * Mjl * toLambda});
        if (!withDerivatives) continue;
        const auto dM = entry->dM.find(master);
        if (dM != entry->dM.end()) emitStiffness(row(master, c), dM->second, k_ * t * lambda[i][c]);
      }
    }
  }
  reduceSummary(summary);
  return summary;
}

}  // namespace coulomb::contact
