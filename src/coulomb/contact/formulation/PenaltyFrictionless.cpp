/// @file PenaltyFrictionless.cpp
/// @brief Frictionless penalty (4.71a): no multipliers, the pressure
/// eps_n <-g~> / D of NodalContactLaw.hpp as forces on the slave and master
/// rows (residual -f), K_c = -df/dx through g~, n, D and M.
#include <algorithm>

#include "coulomb/contact/laws/NodalContactLaw.hpp"
#include "coulomb/contact/formulation/Formulations.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
class PenaltyFrictionless final : public Formulation {
public:
  explicit PenaltyFrictionless(const PairConstants& c) : c_(c) {}

  ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                      PairIterationSummary& summary) const override {
    const double gap = n.mortar->gap, D = n.mortar->D;
    const ContactState state = nextState(penaltyContactState(gap), previous, updateSet, summary.violations);
    n.state->pressure = isActive(state) ? n.epsN * std::max(-gap, 0.0) / D : 0.0;
    n.state->lambdaN = -n.state->pressure / c_.k;
    n.state->augmentedPressure = -n.epsN * gap / D;
    return state;
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    if (!isActive(n.state->state) || n.mortarDerivative == nullptr) return;
    const NodalMortarEntry& entry = *n.mortarDerivative;
    const NodalNormal& normal = *n.normalDerivative;
    const double t = c_.thickness, D = entry.D;
    std::array<double, dim> force{};
    for (int c = 0; c < dim; ++c) force[c] = -n.state->pressure * t * D * normal.n[c];
    summary.addSlaveForce(force, force);
    auto& out = sink.out;
    auto rows = [&](long long target, const NodalForce<dim>& f, const DerivativeRow* dM) {
      for (int c = 0; c < dim; ++c) {
        const GlobalOrdinal row = sink.row(target, c);
        if (sink.prescribed(target, c)) {
          out.prescribedForce.push_back({row, t * f.f[c]});
          continue;
        }
        out.contactResidual.push_back({row, -t * f.f[c]});
        DerivativeRow values;
        addScaled(values, entry.dGap, -t * f.dGap[c]);
        addScaled(values, entry.dD, -t * f.dD[c]);
        if (dM) addScaled(values, *dM, -t * f.dM[c]);
        std::array<double, dim> along{};
        for (int m = 0; m < dim; ++m) along[m] = -t * f.dNormal[c][m];
        addNormalDerivative(values, normal, along);
        sink.add(out.contactStiffness, row, values);
      }
    };
    const auto nv = first<dim>(normal.n);
    rows(n.node, penaltySlaveForce<dim>(nv, entry.gap, n.epsN), nullptr);
    for (const auto& [master, Mjl] : entry.M) {
      const auto dM = entry.dM.find(master);
      rows(master, penaltyMasterForce<dim>(nv, entry.gap, D, Mjl, n.epsN),
           dM != entry.dM.end() ? &dM->second : nullptr);
    }
  }

private:
  PairConstants c_;
};

}  // namespace

template <int dim>
std::unique_ptr<Formulation> makePenaltyFrictionless(const PairConstants& constants) {
  return std::make_unique<PenaltyFrictionless<dim>>(constants);
}
template std::unique_ptr<Formulation> makePenaltyFrictionless<2>(const PairConstants&);
template std::unique_ptr<Formulation> makePenaltyFrictionless<3>(const PairConstants&);

}  // namespace coulomb::contact
