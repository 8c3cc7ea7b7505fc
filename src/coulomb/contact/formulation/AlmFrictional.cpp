/// @file AlmFrictional.cpp
/// @brief ALM and MPC, condensed, with friction or without: the active and
/// stick/slip sets (4.73-4.77) and the condensed rows of FrictionalNode.hpp,
/// chained with the derivatives of the mortar quantities and of the weighted
/// slip. Frictionless pairs run the same kernel on its slip branch with a
/// zero threshold (the seed's automatic pure slip): the tangent rows say
/// b_s.r_F = 0, the multiplier has no tangential part, no slip is needed.
/// docs/architecture.md, "Frictional contact", has the system. Contact
/// forces on prescribed DoFs (slave nodes on a Dirichlet set, with the
/// friction of their driven directions, and masters) are listed apart
/// (ContactContributions::prescribedForce): the supports carry them.
#include <cmath>

#include "coulomb/contact/formulation/FrictionParameters.hpp"
#include "coulomb/contact/laws/FrictionalNode.hpp"
#include "coulomb/contact/formulation/Formulations.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
class AlmFrictional final : public Formulation {
public:
  explicit AlmFrictional(const PairConstants& c)
      : c_(c), p_(pairFrictionalParameters(c)), frictional_(c.settings->frictional()) {
    if (!frictional_) p_.law = FrictionLaw{}, p_.pureSlip = true;
  }

  bool usesSlip() const override { return frictional_; }

  ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                      PairIterationSummary& summary) const override {
    auto decided = frictionalState<dim>(input(n, *n.mortar, *n.normal), previous, parameters(n));
    const ContactState state = nextState(decided.state, previous, updateSet, summary.violations);
    n.state->augmentedPressure = -decided.augmentedNormal;
    n.state->augmentedTraction = {0.0, 0.0, 0.0};
    for (int c = 0; c < dim; ++c) n.state->augmentedTraction[c] = decided.augmentedTangent[c];
    if (!isActive(state)) decided = FrictionalNodeState<dim>{};
    n.state->lambdaN = decided.lambdaN;
    n.state->pressure = -c_.k * decided.lambdaN;
    n.state->traction = {0.0, 0.0, 0.0};
    for (int c = 0; c < dim; ++c) n.state->traction[c] = decided.traction[c];
    return state;
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    const bool residual = sink.residualPart, tangent = sink.tangentPart;
    if (!isActive(n.state->state) || (tangent && n.mortarDerivative == nullptr)) return;
    const NodalMortarEntry& entry = n.mortarDerivative ? *n.mortarDerivative : *n.mortar;
    const NodalNormal& normal = n.mortarDerivative ? *n.normalDerivative : *n.normal;
    const auto k = frictionalRows<dim>(input(n, entry, normal), n.state->state, parameters(n));
    if (!k.usable) return;
    for (int c = 0; c < dim; ++c) n.state->slipDirection[c] = k.direction[c];
    const double t = c_.thickness, kt = c_.k * t;
    const auto& nv = normal.n;
    auto& out = sink.out;

    // Forces and residual figures: the recovered traction acts on the slave.
    double tn = 0;
    for (int c = 0; c < dim; ++c) tn += k.lambda[c] * nv[c];
    std::array<double, dim> force{}, normalPart{};
    for (int c = 0; c < dim; ++c) {
      force[c] = kt * entry.D * k.lambda[c];
      normalPart[c] = kt * entry.D * tn * nv[c];
    }
    if (residual) summary.addSlaveForce(force, normalPart);

    // The explicit part of d(row)/dx: through n, w, D and g~ (the r part is
    // tangentTransform). Kernel inputs: r [0, dim), n [dim, 2 dim), w [2 dim, 3 dim), D, g~.
    auto explicitRow = [&](const std::array<double, kFrictionalInputs<dim>>& d) {
      DerivativeRow row;
      std::array<double, dim> alongNormal{};
      for (int m = 0; m < dim; ++m) alongNormal[m] = d[dim + m];
      addNormalDerivative(row, normal, alongNormal);
      addScaled(row, entry.dD, d[3 * dim]);
      for (int m = 0; m < dim && frictional_; ++m) addScaled(row, (*n.slipDerivative)[m], d[2 * dim + m]);
      addScaled(row, entry.dGap, d[3 * dim + 1]);
      return row;
    };

    // Slave rows: the bulk row is replaced (T - I = -1), the value goes to g.
    // A prescribed component keeps its row; its force goes to the support.
    for (int c = 0; c < dim; ++c) {
      const GlobalOrdinal target = sink.row(n.node, c);
      if (n.prescribed[c]) {
        if (residual) out.prescribedForce.push_back({target, kt * entry.D * k.lambda[c]});
        continue;
      }
      if (residual) {
        out.transform.push_back({target, target, -1.0});
        out.constraintResidual.push_back({target, k.rows[c]});
      }
      if (!tangent) continue;
      for (int m = 0; m < dim; ++m)
        if (!n.prescribed[m] && k.dRows[c][m] != 0.0)
          out.tangentTransform.push_back({target, sink.row(n.node, m), k.dRows[c][m]});
      sink.add(out.constraint, target, explicitRow(k.dRows[c]));
    }
    // The (4.78) groups: the gap slot's row (the free component with the
    // largest |n_c|) is the normal one, the other free slots stick or slip.
    if (residual) {
      double gapRow2 = 0, others2 = 0, largest = -1;
      int gapSlot = -1;
      for (int c = 0; c < dim; ++c)
        if (!n.prescribed[c] && std::abs(nv[c]) > largest) {
          largest = std::abs(nv[c]);
          gapSlot = c;
        }
      for (int c = 0; c < dim; ++c) {
        if (n.prescribed[c]) continue;
        (c == gapSlot ? gapRow2 : others2) += k.rows[c] * k.rows[c];
      }
      summary.normalResidual2 += gapRow2;
      (n.state->state == ContactState::Stick ? summary.stickResidual2 : summary.slipResidual2) += others2;
    }
    // Master rows: + k t M_jl lambda_j (the recovered force, acting on the master as -f).
    // lambda depends on w and g~ only along driven directions (FrictionalNode.hpp).
    // Its explicit derivative rows are the same for every master node (scaled by M_jl).
    std::array<DerivativeRow, dim> lambdaRows;
    for (int c = 0; c < dim && tangent; ++c) lambdaRows[c] = explicitRow(k.dLambda[c]);
    for (const auto& [master, Mjl] : entry.M)
      for (int c = 0; c < dim; ++c) {
        const GlobalOrdinal target = sink.row(master, c);
        if (sink.prescribed(master, c)) {
          if (residual) out.prescribedForce.push_back({target, -kt * Mjl * k.lambda[c]});
          continue;
        }
        if (residual) out.constraintResidual.push_back({target, kt * Mjl * k.lambda[c]});
        if (!tangent) continue;
        for (int m = 0; m < dim; ++m)
          if (!n.prescribed[m] && k.dLambda[c][m] != 0.0)
            out.tangentTransform.push_back({target, sink.row(n.node, m), kt * Mjl * k.dLambda[c][m]});
        DerivativeRow row = lambdaRows[c];  // one triplet per column: M_jl lambdaRow + lambda dM
        for (auto& [key, value] : row) value *= Mjl;
        const auto dM = entry.dM.find(master);
        if (dM != entry.dM.end()) addScaled(row, dM->second, k.lambda[c]);
        sink.add(out.constraint, target, row, kt);
      }
  }

private:
  FrictionalNodeInput<dim> input(const SlaveNode& n, const NodalMortarEntry& entry, const NodalNormal& normal) const {
    FrictionalNodeInput<dim> in;
    in.residual = first<dim>(n.residual);
    in.normal = first<dim>(normal.n);
    in.slip = first<dim>(n.slip);
    in.D = entry.D;
    in.gap = entry.gap;
    in.prescribed = first<dim>(n.prescribed);
    in.driven = first<dim>(n.driven);
    in.oldTraction = first<dim>(n.stepStart->traction);
    in.lastSlip = first<dim>(n.lastStepSlip);
    in.previousDirection = first<dim>(n.state->slipDirection);
    return in;
  }
  FrictionalParameters parameters(const SlaveNode& n) const { return nodeFrictionalParameters(p_, n, c_); }

  PairConstants c_;
  FrictionalParameters p_;
  bool frictional_;
};

}  // namespace

std::unique_ptr<Formulation> makeAlmFrictional(int dim, const PairConstants& constants) {
  if (dim == 2) return std::make_unique<AlmFrictional<2>>(constants);
  return std::make_unique<AlmFrictional<3>>(constants);
}

}  // namespace coulomb::contact
