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
#include "coulomb/core/Error.hpp"

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
    // A nonzero multiplier still pushes on the bodies (its forces need D, M derivatives).
    return isActive(n.state->state) || n.multiplier != std::array<double, 3>{};
  }

  void emit(const SlaveNode& n, RowSink& sink, PairIterationSummary& summary) const override {
    COULOMB_CHECK(sink.residualPart && sink.tangentPart, "the saddle-point form emits its rows in one pass");
    auto& out = sink.out.multipliers;
    const double t = c_.thickness;
    if (!usable(n)) {
      // No master in reach (or not usable): the multiplier vanishes, R = t c_n h^(dim-1) z.
      const double scale = t * n.epsN * c_.referenceD;
      for (int c = 0; c < dim; ++c) {
        out.rows.push_back({sink.multiplierDof(n.slave, c), sink.multiplierDof(n.slave, c), scale});
        out.residual.push_back({sink.multiplierDof(n.slave, c), scale * n.multiplier[c]});
      }
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
    addForces(n, sink, entry, in, withDerivatives, summary);
  }

private:
  /// The forces of the node's multiplier on the bodies, slave k t D lambda,
  /// master -k t M_jl lambda: the displacement rows carry -f_c, the columns
  /// C = -df/dz, and K_c = -df/du through D and M (`withDerivatives`); the
  /// force counts in the summary when the node is active.
  void addForces(const SlaveNode& n, RowSink& sink, const NodalMortarEntry& entry, const NcpNodeInput<dim>& in,
                 bool withDerivatives, PairIterationSummary& summary) const {
    const double kt = c_.k * c_.thickness, toLambda = n.epsN / c_.k, D = entry.D;
    auto& out = sink.out;
    std::array<double, dim> force{}, normalPart{};
    double fn = 0;
    for (int c = 0; c < dim; ++c) fn += kt * D * in.lambda[c] * in.normal[c];
    for (int c = 0; c < dim; ++c) {
      force[c] = kt * D * in.lambda[c];
      normalPart[c] = fn * in.normal[c];
      const GlobalOrdinal z = sink.multiplierDof(n.slave, c);
      if (!n.prescribed[c]) {
        const GlobalOrdinal row = sink.row(n.node, c);
        out.contactResidual.push_back({row, -force[c]});
        out.multipliers.columns.push_back({row, z, -kt * D * toLambda});
        if (withDerivatives) sink.add(out.contactStiffness, row, entry.dD, -kt * in.lambda[c]);
      }
      for (const auto& [master, Mjl] : entry.M) {
        if (sink.prescribed(master, c)) continue;
        const GlobalOrdinal row = sink.row(master, c);
        out.contactResidual.push_back({row, kt * Mjl * in.lambda[c]});
        out.multipliers.columns.push_back({row, z, kt * Mjl * toLambda});
        const auto dM = entry.dM.find(master);
        if (withDerivatives && dM != entry.dM.end()) sink.add(out.contactStiffness, row, dM->second, kt * in.lambda[c]);
      }
    }
    if (isActive(n.state->state)) summary.addSlaveForce(force, normalPart);
  }
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

std::unique_ptr<Formulation> makeLagrangeNcp(int dim, const PairConstants& constants) {
  if (dim == 2) return std::make_unique<LagrangeNcp<2>>(constants);
  return std::make_unique<LagrangeNcp<3>>(constants);
}

}  // namespace coulomb::contact
