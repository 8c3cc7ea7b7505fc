/// @file LagrangeNcp.cpp
/// @brief The Lagrange multiplier method with nonlinear complementarity
/// functions (seed 4.79, the formulation of Popp and Gitterle that the seed
/// compares the ALM with), deck `Formulation` = LMM: the vector multipliers
/// are Newton unknowns (System Form = Saddle Point), the nodal rows are the
/// NCP functions of laws/NcpNode.hpp, frictionless or with friction. The
/// penalty-like parameters c_n = eps_n, c_tau = kappa eps_n only shape the
/// semi-smooth Newton path: the converged answer has no penalty in it.
/// Per node the unknown is z_j = (k / c_n) lambda_j (a length) and the rows
/// are R_j = t D_j C_j (a force). A frictionless ALM pair in the saddle-point
/// form is this formulation with c_n = eps_n (FormulationFactory.cpp): the
/// check that the condensation is exact (tests/unit/contact_saddle_point_mpi.cpp).
#include "coulomb/contact/formulation/Formulations.hpp"
#include "coulomb/contact/laws/CondensationFrame.hpp"
#include "coulomb/contact/laws/NcpNode.hpp"

namespace coulomb::contact {

namespace {

template <int dim>
class LagrangeNcp final : public Formulation {
public:
  explicit LagrangeNcp(const PairConstants& c) : c_(c), frictional_(c.settings->frictional()) {}

  bool needsMultipliers() const override { return true; }
  bool usesSlip() const override { return frictional_; }

  ContactState decide(const SlaveNode& n, ContactState previous, bool updateSet,
                      PairIterationSummary& summary) const override {
    // As in the condensed forms: a node whose free components cannot carry
    // its normal multiplier stays open (CondensationFrame::usable).
    if (!usable(n)) {
      n.state->lambdaN = n.state->pressure = n.state->augmentedPressure = 0.0;
      n.state->traction = n.state->augmentedTraction = {0.0, 0.0, 0.0};
      return ContactState::Inactive;
    }
    const auto in = input(n, *n.mortar, *n.normal);
    const ContactState state =
        nextState(ncpState<dim>(in, previous, parameters(n)), previous, updateSet, summary.violations);
    const auto rows = ncpRows<dim>(in, state, parameters(n));
    double lambdaN = 0;
    for (int c = 0; c < dim; ++c) lambdaN += in.lambda[c] * in.normal[c];
    n.state->lambdaN = isActive(state) ? lambdaN : 0.0;
    n.state->pressure = -c_.k * n.state->lambdaN;
    n.state->augmentedPressure = -rows.augmentedNormal;
    n.state->traction = n.state->augmentedTraction = {0.0, 0.0, 0.0};
    for (int c = 0; c < dim && frictional_; ++c) {
      n.state->traction[c] = isActive(state) ? c_.k * in.lambda[c] : 0.0;
      n.state->augmentedTraction[c] = rows.augmentedTangent[c];
    }
    return state;
  }

  /// The rows depend on the geometry at active nodes, and the forces at
  /// every node still carrying a multiplier.
  bool needsDerivatives(const SlaveNode& n) const override {
    if (!usable(n)) return false;
    return isActive(n.state->state) || carriesMultiplier(n.multiplier);
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    auto& out = sink.out.multipliers;
    const double t = c_.thickness;
    if (!usable(n)) {
      // No master in reach (or not usable): the multiplier vanishes, R = t c_n h^(dim-1) z.
      addVanishingMultiplier(sink, n.slave, n.multiplier, dim, t * n.epsN * c_.referenceD);
      return;
    }
    const bool withDerivatives = n.mortarDerivative != nullptr;
    const NodalMortarEntry& entry = withDerivatives ? *n.mortarDerivative : *n.mortar;
    const NodalNormal& normal = withDerivatives ? *n.normalDerivative : *n.normal;
    const auto in = input(n, entry, normal);
    const ContactState state = n.state->state;
    const auto ncp = ncpRows<dim>(in, state, parameters(n));
    const double D = entry.D, toLambda = n.epsN / c_.k;

    // R = t D C and its derivatives: dR/dz through lambda, dR/du through
    // n, w, D (with the product rule) and g~. Kernel inputs: lambda, n, w, D, g~.
    double normalRow = 0, tangentRow2 = 0;
    for (int c = 0; c < dim; ++c) normalRow += ncp.r[c] * in.normal[c];
    for (int a = 0; a < dim; ++a) {
      const double tangent = ncp.r[a] - normalRow * in.normal[a];
      tangentRow2 += tangent * tangent;
      const GlobalOrdinal target = sink.multiplierDof(n.slave, a);
      out.residual.push_back({target, t * D * ncp.r[a]});
      for (int c = 0; c < dim; ++c)
        out.rows.push_back({target, sink.multiplierDof(n.slave, c), t * D * toLambda * ncp.dr[a][c]});
      if (!withDerivatives) continue;
      DerivativeRow row;
      std::array<double, dim> alongNormal{};
      for (int m = 0; m < dim; ++m) alongNormal[m] = ncp.dr[a][dim + m];
      addNormalDerivative(row, normal, alongNormal);
      for (int m = 0; m < dim && frictional_; ++m) addScaled(row, (*n.slipDerivative)[m], ncp.dr[a][2 * dim + m]);
      addScaled(row, entry.dD, ncp.dr[a][3 * dim] + ncp.r[a] / D);
      addScaled(row, entry.dGap, ncp.dr[a][3 * dim + 1]);
      sink.add(out.rows, target, row, t * D);
    }
    if (isActive(state)) {
      summary.normalResidual2 += (t * D * normalRow) * (t * D * normalRow);
      (state == ContactState::Stick ? summary.stickResidual2 : summary.slipResidual2) += t * D * t * D * tangentRow2;
    }
    std::array<double, 3> lambda{};
    for (int c = 0; c < dim; ++c) lambda[c] = in.lambda[c];
    addMultiplierForces(sink, n.slave, n.node, n.prescribed, entry, lambda, toLambda, c_.k * t, withDerivatives,
                        isActive(state), normal.n, summary);
  }

private:
  bool usable(const SlaveNode& n) const {
    return n.mortar != nullptr && condensationFrame<dim>(first<dim>(n.normal->n), first<dim>(n.prescribed)).usable;
  }
  NcpNodeInput<dim> input(const SlaveNode& n, const NodalMortarEntry& entry, const NodalNormal& normal) const {
    NcpNodeInput<dim> in;
    for (int c = 0; c < dim; ++c) in.lambda[c] = n.epsN / c_.k * n.multiplier[c];  // lambda = (c_n / k) z
    in.normal = first<dim>(normal.n);
    if (frictional_) in.slip = first<dim>(n.slip);
    in.D = entry.D;
    in.gap = entry.gap;
    return in;
  }
  NcpParameters parameters(const SlaveNode& n) const {
    NcpParameters p;
    p.k = c_.k;
    p.cN = n.epsN;
    p.cTau = c_.settings->tangentFactor * n.epsN;
    p.touchingGap = c_.touchingGap();
    p.slipThreshold = c_.settings->slipThreshold;
    p.law = c_.settings->friction;
    p.law.coefficient = n.frictionCoefficient;
    if (!frictional_) p.law = FrictionLaw{};
    return p;
  }

  PairConstants c_;
  bool frictional_;
};

}  // namespace

template <int dim>
std::unique_ptr<Formulation> makeLagrangeNcp(const PairConstants& constants) {
  return std::make_unique<LagrangeNcp<dim>>(constants);
}
template std::unique_ptr<Formulation> makeLagrangeNcp<2>(const PairConstants&);
template std::unique_ptr<Formulation> makeLagrangeNcp<3>(const PairConstants&);

}  // namespace coulomb::contact
