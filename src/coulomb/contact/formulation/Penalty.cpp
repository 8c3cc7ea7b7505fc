/// @file Penalty.cpp
/// @brief Penalty, with friction (4.71a with a return map, FrictionalNode.hpp)
/// or without (the same kernel on its slip branch with a zero threshold: no
/// tangential traction, no slip needed): the force f of the node's traction
/// on the slave (residual -f, K_c = -df/dx through n, w, D, g~) and
/// -(M_jl / D) f on the masters.
#include "coulomb/contact/formulation/FrictionParameters.hpp"
#include "coulomb/contact/laws/FrictionalNode.hpp"
#include "coulomb/contact/formulation/Formulations.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
class Penalty final : public Formulation {
public:
  explicit Penalty(const PairConstants& c)
      : c_(c), p_(pairFrictionalParameters(c)), frictional_(c.settings->frictional()) {
    // Frictionless: every active node on the slip branch, whose threshold is 0.
    if (!frictional_) p_.law = FrictionLaw{}, p_.pureSlip = true;
  }

  bool usesSlip() const override { return frictional_; }

  ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                      PairIterationSummary& summary) const override {
    const ContactState state = nextState(
        penaltyFrictionalState<dim>(input(n, *n.mortar, *n.normal), previous, parameters(n)), previous, updateSet,
        summary.violations);
    // An active node's traction is set by emit() (a stale one until then).
    if (!isActive(state)) n.state->traction = {0.0, 0.0, 0.0}, n.state->lambdaN = n.state->pressure = 0.0;
    n.state->augmentedPressure = -n.epsN * n.mortar->gap / n.mortar->D;
    n.state->augmentedTraction = {0.0, 0.0, 0.0};
    return state;
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    const bool residual = sink.residualPart, tangent = sink.tangentPart;
    if (!isActive(n.state->state) || (tangent && n.mortarDerivative == nullptr)) return;
    const NodalMortarEntry& entry = n.mortarDerivative ? *n.mortarDerivative : *n.mortar;
    const NodalNormal& normal = n.mortarDerivative ? *n.normalDerivative : *n.normal;
    const auto& nv = normal.n;
    const double D = entry.D;
    const auto f = penaltyFrictionalForce<dim>(input(n, entry, normal), n.state->state, parameters(n));
    n.state->pressure = f.pressure;
    n.state->lambdaN = -f.pressure / c_.k;
    n.state->traction = {0.0, 0.0, 0.0};
    for (int c = 0; c < dim; ++c) n.state->traction[c] = f.traction[c] - f.pressure * nv[c];
    for (int c = 0; c < dim; ++c) n.state->augmentedTraction[c] = f.trial[c];
    double fn = 0;
    for (int c = 0; c < dim; ++c) fn += f.force[c] * nv[c];
    std::array<double, dim> normalPart{};
    for (int c = 0; c < dim; ++c) normalPart[c] = fn * nv[c];
    if (residual) summary.addSlaveForce(f.force, normalPart);
    // Kernel inputs: n [0, dim), w [dim, 2 dim), D, g~.
    auto derivative = [&](int c) {
      DerivativeRow row;
      std::array<double, dim> alongNormal{};
      for (int m = 0; m < dim; ++m) alongNormal[m] = f.dForce[c][m];
      addNormalDerivative(row, normal, alongNormal);
      if (n.slipDerivative)
        for (int m = 0; m < dim; ++m) addScaled(row, (*n.slipDerivative)[m], f.dForce[c][dim + m]);
      addScaled(row, entry.dD, f.dForce[c][2 * dim]);
      addScaled(row, entry.dGap, f.dForce[c][2 * dim + 1]);
      return row;
    };
    auto& out = sink.out;
    for (int c = 0; c < dim; ++c) {
      const DerivativeRow df = tangent ? derivative(c) : DerivativeRow{};
      if (!n.prescribed[c]) {
        if (residual) out.contactResidual.push_back({sink.row(n.node, c), -f.force[c]});
        if (tangent) sink.add(out.contactStiffness, sink.row(n.node, c), df, -1.0);
      } else if (residual) {
        out.prescribedForce.push_back({sink.row(n.node, c), f.force[c]});
      }
      for (const auto& [master, Mjl] : entry.M) {
        const GlobalOrdinal target = sink.row(master, c);
        if (sink.prescribed(master, c)) {
          if (residual) out.prescribedForce.push_back({target, -Mjl / D * f.force[c]});
          continue;
        }
        if (residual) out.contactResidual.push_back({target, Mjl / D * f.force[c]});
        if (!tangent) continue;
        DerivativeRow row = df;
        for (auto& [key, value] : row) value *= Mjl / D;
        const auto dM = entry.dM.find(master);
        if (dM != entry.dM.end()) addScaled(row, dM->second, f.force[c] / D);
        addScaled(row, entry.dD, -Mjl * f.force[c] / (D * D));
        sink.add(out.contactStiffness, target, row);
      }
    }
  }

private:
  PenaltyFrictionalInput<dim> input(const SlaveNode& n, const NodalMortarEntry& entry,
                                    const NodalNormal& normal) const {
    PenaltyFrictionalInput<dim> in;
    in.normal = first<dim>(normal.n);
    in.slip = first<dim>(n.slip);
    in.oldTraction = first<dim>(n.stepStart->traction);
    in.D = entry.D;
    in.gap = entry.gap;
    return in;
  }
  FrictionalParameters parameters(const SlaveNode& n) const { return nodeFrictionalParameters(p_, n, c_); }

  PairConstants c_;
  FrictionalParameters p_;
  bool frictional_;
};

}  // namespace

std::unique_ptr<Formulation> makePenalty(int dim, const PairConstants& constants) {
  if (dim == 2) return std::make_unique<Penalty<2>>(constants);
  return std::make_unique<Penalty<3>>(constants);
}

}  // namespace coulomb::contact
