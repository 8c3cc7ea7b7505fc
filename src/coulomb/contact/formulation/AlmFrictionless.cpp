/// @file AlmFrictionless.cpp
/// @brief Frictionless ALM and MPC, condensed (ContactPair.hpp has the
/// system): the slave node's a-row recovers lambda_n and is replaced by the
/// gap row sign eps_n t g~ (CondensationFrame.hpp), the master rows take
/// M_jl n / (D |n_F|) × the a-row, K_c = -d f_c / dx with lambda_n frozen.
/// ALM and MPC share the rows (the MPC's ties) and differ in the state rule
/// (FrictionlessNode.hpp).
#include "coulomb/contact/laws/FrictionlessNode.hpp"
#include "coulomb/contact/formulation/Formulations.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
class AlmFrictionless final : public Formulation {
public:
  explicit AlmFrictionless(const PairConstants& c) : c_(c) {}

  bool usesResidual() const override { return true; }

  ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                      PairIterationSummary& summary) const override {
    const auto node = frictionlessState<dim>(input(n, *n.mortar, *n.normal), previous, parameters(n));
    ContactState state = nextState(node.state, previous, updateSet, summary.violations);
    if (!node.frame.usable) state = ContactState::Inactive;
    n.state->lambdaN = isActive(state) ? node.lambdaN : 0.0;
    n.state->pressure = -c_.k * n.state->lambdaN;
    n.state->augmentedPressure = node.frame.usable ? -node.augmentedNormal : 0.0;
    return state;
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    if (!isActive(n.state->state) || n.mortarDerivative == nullptr) return;
    const NodalMortarEntry& entry = *n.mortarDerivative;
    const auto& normal = *n.normalDerivative;
    const auto frame = condensationFrame<dim>(first<dim>(normal.n), first<dim>(n.prescribed));
    const double D = entry.D, gap = entry.gap, lambdaN = n.state->lambdaN, epsN = n.epsN, t = c_.thickness;
    const auto& nv = normal.n;
    auto& out = sink.out;
    auto row = [&sink](long long node, int c) { return sink.row(node, c); };

    // Slave force f_j = k t lambda_n D n acting on the slave body.
    std::array<double, dim> force{};
    for (int c = 0; c < dim; ++c) force[c] = c_.k * t * D * lambdaN * nv[c];
    summary.addSlaveForce(force, force);
    // Forces on prescribed DoFs (slave f_j, master -k t lambda_n M_jl n): the supports'.
    for (int c = 0; c < dim; ++c) {
      if (n.prescribed[c]) out.prescribedForce.push_back({row(n.node, c), c_.k * t * D * lambdaN * nv[c]});
      for (const auto& [master, Mjl] : entry.M)
        if (sink.prescribed(master, c))
          out.prescribedForce.push_back({row(master, c), -c_.k * t * lambdaN * Mjl * nv[c]});
    }
    // T - I on the slave rows: the gap slot is emptied, the b rows replace the others.
    out.transform.push_back({row(n.node, frame.gapSlot), row(n.node, frame.gapSlot), -1.0});
    for (int f = 0; f < frame.numFree; ++f) {
      const int slot = frame.free[f];
      if (slot == frame.gapSlot) continue;
      out.transform.push_back({row(n.node, slot), row(n.node, slot), -1.0});
      for (int g = 0; g < frame.numFree; ++g)
        out.transform.push_back({row(n.node, slot), row(n.node, frame.free[g]), frame.b[slot][frame.free[g]]});
    }
    // T - I on the master rows: + M_jl n_c / (D |n_F|) × the a-row of j.
    for (const auto& [master, Mjl] : entry.M)
      for (int c = 0; c < dim; ++c) {
        if (sink.prescribed(master, c)) continue;
        const double scale = Mjl * nv[c] / (D * frame.normFree);
        for (int g = 0; g < frame.numFree; ++g)
          out.transform.push_back({row(master, c), row(n.node, frame.free[g]), scale * frame.a[frame.free[g]]});
      }
    // The gap row: sign eps_n t g~_j and its derivative.
    const double scale = frame.gapRowSign * epsN * t;
    out.constraintResidual.push_back({row(n.node, frame.gapSlot), scale * gap});
    sink.add(out.constraint, row(n.node, frame.gapSlot), entry.dGap, scale);
    summary.normalResidual2 += (epsN * t * gap) * (epsN * t * gap);
    // K_c = -d f_c / dx with lambda_n frozen: slave f_j = k t lambda_n D n, master f_l = -k t lambda_n M_jl n.
    if (lambdaN == 0.0) return;
    const double kl = c_.k * t * lambdaN;
    for (int c = 0; c < dim; ++c) {
      if (n.prescribed[c]) continue;
      DerivativeRow values;
      addScaled(values, entry.dD, -kl * nv[c]);
      std::array<double, dim> along{};
      along[c] = -kl * D;
      addNormalDerivative(values, normal, along);
      sink.add(out.contactStiffness, row(n.node, c), values);
    }
    for (const auto& [master, Mjl] : entry.M)
      for (int c = 0; c < dim; ++c) {
        if (sink.prescribed(master, c)) continue;
        DerivativeRow values;
        const auto dM = entry.dM.find(master);
        if (dM != entry.dM.end()) addScaled(values, dM->second, kl * nv[c]);
        std::array<double, dim> along{};
        along[c] = kl * Mjl;
        addNormalDerivative(values, normal, along);
        sink.add(out.contactStiffness, row(master, c), values);
      }
  }

private:
  FrictionlessNodeInput<dim> input(const SlaveNode& n, const NodalMortarEntry& entry, const NodalNormal& normal) const {
    FrictionlessNodeInput<dim> in;
    in.residual = first<dim>(n.residual);
    in.normal = first<dim>(normal.n);
    in.prescribed = first<dim>(n.prescribed);
    in.D = entry.D;
    in.gap = entry.gap;
    return in;
  }
  FrictionlessParameters parameters(const SlaveNode& n) const {
    FrictionlessParameters p;
    p.k = c_.k;
    p.epsN = n.epsN;
    p.thickness = c_.thickness;
    p.touchingGap = c_.touchingGap();
    p.multiPointConstraint = c_.settings->formulation == ContactFormulation::MPC;
    return p;
  }

  PairConstants c_;
};

}  // namespace

template <int dim>
std::unique_ptr<Formulation> makeAlmFrictionless(const PairConstants& constants) {
  return std::make_unique<AlmFrictionless<dim>>(constants);
}
template std::unique_ptr<Formulation> makeAlmFrictionless<2>(const PairConstants&);
template std::unique_ptr<Formulation> makeAlmFrictionless<3>(const PairConstants&);

}  // namespace coulomb::contact
