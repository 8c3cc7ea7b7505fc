/// @file SaddlePoint.cpp
/// @brief Frictionless ALM with the dual multipliers kept as Newton unknowns
/// (MultiplierBlock in ContactContributions.hpp), deck `Contact/System Form`
/// = Saddle Point. The condensed form (AlmFrictionless.cpp) is the
/// production path; this one exists to check it: the same mortar values and
/// derivatives, the nodal law of NodalContactLaw (4.72b, components form,
/// vector multiplier) instead of the condensation. Per node the unknown is
/// z_j = (k / eps_n,j) lambda_j (a length) and the rows are
/// R_j = (eps_n,j t / k) r_lambda,j.
#include "coulomb/contact/laws/CondensationFrame.hpp"
#include "coulomb/contact/laws/NodalContactLaw.hpp"
#include "coulomb/contact/formulation/Formulations.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
class SaddlePoint final : public Formulation {
public:
  explicit SaddlePoint(const PairConstants& c) : c_(c) {}

  bool needsMultipliers() const override { return true; }

  ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                      PairIterationSummary& summary) const override {
    // A node whose free components cannot carry its normal multiplier stays
    // open (CondensationFrame::usable), as in the condensed form.
    if (!usable(n)) {
      n.state->lambdaN = n.state->pressure = n.state->augmentedPressure = 0.0;
      return ContactState::Inactive;
    }
    const auto lambda = multiplier(n);
    double lambdaN = 0;
    for (int c = 0; c < dim; ++c) lambdaN += lambda[c] * n.normal->n[c];
    const ContactState state =
        nextState(almContactState(lambdaN, n.mortar->gap, n.mortar->D, c_.k, n.epsN, c_.touchingGap()), previous,
                  updateSet, summary.violations);
    n.state->lambdaN = isActive(state) ? lambdaN : 0.0;
    n.state->pressure = -c_.k * n.state->lambdaN;
    n.state->augmentedPressure = -augmentedNormalMultiplier(lambdaN, n.mortar->gap, n.mortar->D, c_.k, n.epsN);
    return state;
  }

  /// The rows or forces depend on the geometry at active nodes (gap) and at
  /// open ones still carrying a multiplier (n, D).
  bool needsDerivatives(const SlaveNode& n) const override {
    if (!usable(n)) return false;
    return isActive(n.state->state) || carriesMultiplier(n.multiplier);
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    auto& out = sink.out.multipliers;
    const double t = c_.thickness;
    if (!usable(n)) {
      // No master in reach (or not usable): the multiplier vanishes, R = t eps_n h^(dim-1) z.
      addVanishingMultiplier(sink, n.slave, n.multiplier, dim, t * n.epsN * c_.referenceD);
      return;
    }
    const bool withDerivatives = n.mortarDerivative != nullptr;
    const NodalMortarEntry& entry = withDerivatives ? *n.mortarDerivative : *n.mortar;
    const NodalNormal& normal = withDerivatives ? *n.normalDerivative : *n.normal;
    const double D = entry.D;
    const double toLambda = n.epsN / c_.k, rowScale = n.epsN * t / c_.k;
    const auto lambda = multiplier(n);
    AlmNodeInput<dim> in;
    in.lambda = lambda;
    in.normal = first<dim>(normal.n);
    in.gap = entry.gap;
    in.D = D;
    const auto law = almResidual<dim>(in, AlmParameters{c_.k, n.epsN, n.epsN}, n.state->state);

    // The multiplier rows: R, dR/dz, dR/du (through g~, n, D).
    for (int a = 0; a < dim; ++a) {
      const GlobalOrdinal target = sink.multiplierDof(n.slave, a);
      out.residual.push_back({target, rowScale * law.r[a]});
      for (int c = 0; c < dim; ++c)
        out.rows.push_back({target, sink.multiplierDof(n.slave, c), rowScale * toLambda * law.dLambda[a][c]});
      if (!withDerivatives) continue;
      sink.add(out.rows, target, entry.dGap, rowScale * law.dGap[a]);
      sink.add(out.rows, target, entry.dD, rowScale * law.dD[a]);
      for (const auto& d : normal.derivative) {
        double value = 0;
        for (int c = 0; c < dim; ++c) value += law.dNormal[a][c] * d.dn[c];
        if (value != 0.0 && !sink.prescribed(d.node, d.component))
          out.rows.push_back({target, sink.row(d.node, d.component), rowScale * value});
      }
    }
    if (isActive(n.state->state))
      summary.normalResidual2 += (n.epsN * t * entry.gap) * (n.epsN * t * entry.gap);

    // Forces on the bodies (NodalContactLaw): slave k t D lambda, master -k t M_jl lambda.
    std::array<double, 3> lambda3{};
    for (int c = 0; c < dim; ++c) lambda3[c] = lambda[c];
    addMultiplierForces(sink, n.slave, n.node, n.prescribed, entry, lambda3, toLambda, c_.k * t, withDerivatives,
                        isActive(n.state->state), normal.n, summary);
  }

private:
  bool usable(const SlaveNode& n) const {
    return n.mortar != nullptr && condensationFrame<dim>(first<dim>(n.normal->n), first<dim>(n.prescribed)).usable;
  }
  /// lambda_j = (eps_n / k) z_j.
  std::array<double, dim> multiplier(const SlaveNode& n) const {
    std::array<double, dim> lambda{};
    for (int c = 0; c < dim; ++c) lambda[c] = n.epsN / c_.k * n.multiplier[c];
    return lambda;
  }

  PairConstants c_;
};

}  // namespace

template <int dim>
std::unique_ptr<Formulation> makeSaddlePoint(const PairConstants& constants) {
  return std::make_unique<SaddlePoint<dim>>(constants);
}
template std::unique_ptr<Formulation> makeSaddlePoint<2>(const PairConstants&);
template std::unique_ptr<Formulation> makeSaddlePoint<3>(const PairConstants&);

}  // namespace coulomb::contact
