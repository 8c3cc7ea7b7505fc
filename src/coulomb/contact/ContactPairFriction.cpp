/// @file ContactPairFriction.cpp
/// @brief ContactPair::update for frictional pairs (ALM): the weighted slip
/// of the step (seed 4.69b, or 4.65a), the active and stick/slip sets
/// (4.73-4.77) and the condensed rows of FrictionalNode.hpp chained with the
/// derivatives of the mortar quantities. docs/architecture.md, "Frictional
/// contact", has the system. Contact forces on prescribed DoFs (slave nodes
/// on a Dirichlet set, with the friction of their driven directions, and
/// masters) are listed apart (ContactContributions::prescribedForce): the
/// supports carry them.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/contact/FrictionalNode.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::contact {

namespace {

/// What the kernel needs of a node besides r, n, w, D, g~ (3 wide).
struct NodeExtras {
  std::array<bool, 3> prescribed{}, driven{};
  std::array<double, 3> oldTraction{}, lastSlip{}, previousDirection{};
};

/// The 3-wide input of the kernel's dimension.
template <int dim>
FrictionalNodeInput<dim> narrow(const std::array<double, 3>& r, const std::array<double, 3>& n,
                                const std::array<double, 3>& w, double D, double gap, const NodeExtras& x) {
  FrictionalNodeInput<dim> in;
  for (int c = 0; c < dim; ++c) {
    in.lastSlip[c] = x.lastSlip[c];
    in.residual[c] = r[c];
    in.normal[c] = n[c];
    in.slip[c] = w[c];
    in.prescribed[c] = x.prescribed[c];
    in.driven[c] = x.driven[c];
    in.oldTraction[c] = x.oldTraction[c];
    in.previousDirection[c] = x.previousDirection[c];
  }
  in.D = D;
  in.gap = gap;
  return in;
}

/// Kernel results widened to 3 components and the 11 inputs of 3D
/// (r 0-2, n 3-5, w 6-8, D 9, g~ 10).
struct Rows {
  bool usable = false;
  std::array<double, 3> rows{}, lambda{}, direction{};
  std::array<std::array<double, 11>, 3> dRows{}, dLambda{};
};
struct State {
  ContactState state = ContactState::Inactive;
  double lambdaN = 0;
  std::array<double, 3> traction{};
};

template <int dim>
Rows widenRows(const FrictionalNodeRows<dim>& k) {
  Rows out;
  out.usable = k.usable;
  auto input = [](int i) { return i < dim ? i : i < 2 * dim ? 3 + i - dim : i < 3 * dim ? 6 + i - 2 * dim : 9 + i - 3 * dim; };
  for (int c = 0; c < dim; ++c) {
    out.rows[c] = k.rows[c];
    out.lambda[c] = k.lambda[c];
    out.direction[c] = k.direction[c];
    for (int i = 0; i < kFrictionalInputs<dim>; ++i) {
      out.dRows[c][input(i)] = k.dRows[c][i];
      out.dLambda[c][input(i)] = k.dLambda[c][i];
    }
  }
  return out;
}

State decide(int dim, const std::array<double, 3>& r, const std::array<double, 3>& n, const std::array<double, 3>& w,
             double D, double gap, const NodeExtras& x, ContactState previous, const FrictionalParameters& p) {
  State out;
  auto copy = [&out](const auto& s, int d) {
    out.state = s.state;
    out.lambdaN = s.lambdaN;
    for (int c = 0; c < d; ++c) out.traction[c] = s.traction[c];
  };
  if (dim == 2) copy(frictionalState<2>(narrow<2>(r, n, w, D, gap, x), previous, p), 2);
  else copy(frictionalState<3>(narrow<3>(r, n, w, D, gap, x), previous, p), 3);
  return out;
}

Rows rowsOf(int dim, const std::array<double, 3>& r, const std::array<double, 3>& n, const std::array<double, 3>& w,
            double D, double gap, const NodeExtras& x, ContactState state, const FrictionalParameters& p) {
  if (dim == 2) return widenRows<2>(frictionalRows<2>(narrow<2>(r, n, w, D, gap, x), state, p));
  return widenRows<3>(frictionalRows<3>(narrow<3>(r, n, w, D, gap, x), state, p));
}

void addScaled(DerivativeRow& to, const DerivativeRow& from, double scale) {
  if (scale == 0.0) return;
  for (const auto& [key, value] : from) to[key] += scale * value;
}

}  // namespace

void ContactPair::settleState(std::size_t i, ContactState state, ContactState previous,
                              PairIterationSummary& summary) {
  if (!isActive(state)) weightedSlip_[i] = slipIncrement_[i] = {0.0, 0.0, 0.0};  // an open node does not slip
  state_[i] = state;
  countState(summary.activeSet, state, previous);
}

FrictionalParameters ContactPair::frictionalParameters() const {
  FrictionalParameters p;
  p.k = k_;  // eps_n, eps_tau and mu are the node's: setNodeParameters
  p.thickness = thickness_;
  p.slipAugmentation = settings_.slipAugmentation;
  p.slipThreshold = settings_.slipThreshold;
  // 1e-10 of the slave face size: far above the round-off of the
  // coordinates, far below any slip that matters.
  p.roundOffSlip = 1e-10 * faceSize_;
  p.touchingGap = touchingGap();
  p.law = settings_.friction;
  p.multiPointConstraint = settings_.formulation == ContactFormulation::MPC;
  p.slipDirectionFromSlip = settings_.slipResetFrequency < 0;
  p.pureSlip = settings_.pureSlip;
  return p;
}

void ContactPair::setNodeParameters(FrictionalParameters& p, std::size_t i, long long node) const {
  p.law.coefficient = settings_.frictionCoefficient(node);
  p.epsN = penalty_[i];
  p.epsTau = settings_.tangentFactor * penalty_[i];
}

std::array<double, 3> ContactPair::weightedSlip(const NodalMortarEntry& entry,
                                                std::array<DerivativeRow, 3>* derivative) const {
  // Objective (4.69b): w = (D - D^t) x_j - sum_l (M_jl - M^t_jl) x_l, taken
  // in the translation-invariant form
  //   w = sum_l (M_jl - M^t_jl) (x_j - x_l),
  // which drops (ΔD - sum_l ΔM_jl) x_j. With the lumped D of the mortar
  // kernels (D_j = sum_l M_jl segment by segment) that term is zero up to
  // round-off, so the two forms are the same slip; the form leaves out the
  // round-off's dependence on the origin (eps_mach |x_j| D, a slip that
  // grows with the distance from the origin) and keeps (4.69b)'s
  // objectivity: a rigid motion changes no M_jl and rotates x_j - x_l.
  // (tests/unit/contact_friction_decks_mpi.cpp,
  // FrictionFrameIndifference.ObjectiveSlipIsTranslationInvariant.)
  // Non-objective (4.65a, seed sign): w = -[D (x_j - x^t_j) - sum_l M_jl (x_l - x^t_l)].
  // Without operators of the last converged state (a node that had no
  // master in reach) only the non-objective measure exists.
  const NodalMortarEntry* previous = stepStartMortar_.find(entry.node);
  bool objective = settings_.slipMeasure == SlipMeasure::Objective && previous != nullptr;
  if (objective && settings_.operatorThreshold > 0.0) {
    // Relative change of D_j and the M_jl over the step (the seed's OPERATOR_THRESHOLD).
    double change = std::abs(entry.D - previous->D), size = std::abs(entry.D);
    std::map<long long, double> difference;
    for (const auto& [l, m] : entry.M) difference[l] += m, size += std::abs(m);
    for (const auto& [l, m] : previous->M) difference[l] -= m;
    for (const auto& [l, d] : difference) change += std::abs(d);
    objective = change > settings_.operatorThreshold * size;
  }
  auto point = [this](const InterfaceConfiguration& x, long long node) {
    return x.point(interface_->interfaceNodeIndex(node));
  };
  std::array<double, 3> w{};
  if (derivative)
    for (auto& row : *derivative) row.clear();
  const double* xj = point(x_, entry.node);
  const double* xtj = point(stepStartX_, entry.node);
  if (objective) {
    // Union of the master nodes of now and then.
    std::map<long long, std::pair<double, double>> masters;
    for (const auto& [l, m] : entry.M) masters[l].first = m;
    for (const auto& [l, m] : previous->M) masters[l].second = m;
    for (const auto& [l, m] : masters) {
      const double* xl = point(x_, l);
      for (int c = 0; c < dim_; ++c) w[c] += (m.first - m.second) * (xj[c] - xl[c]);
    }
    if (derivative)
      for (int c = 0; c < dim_; ++c) {
        auto& row = (*derivative)[c];
        for (const auto& [l, m] : masters) {
          const double* xl = point(x_, l);
          const auto dM = entry.dM.find(l);
          if (dM != entry.dM.end()) addScaled(row, dM->second, xj[c] - xl[c]);
          row[{entry.node, c}] += m.first - m.second;
          row[{l, c}] -= m.first - m.second;
        }
      }
  } else {
    for (int c = 0; c < dim_; ++c) w[c] = -entry.D * (xj[c] - xtj[c]);
    for (const auto& [l, m] : entry.M) {
      const double* xl = point(x_, l);
      const double* xtl = point(stepStartX_, l);
      for (int c = 0; c < dim_; ++c) w[c] += m * (xl[c] - xtl[c]);
    }
    if (derivative)
      for (int c = 0; c < dim_; ++c) {
        auto& row = (*derivative)[c];
        addScaled(row, entry.dD, -(xj[c] - xtj[c]));
        row[{entry.node, c}] -= entry.D;
        for (const auto& [l, m] : entry.M) {
          const auto dM = entry.dM.find(l);
          if (dM != entry.dM.end()) addScaled(row, dM->second, point(x_, l)[c] - point(stepStartX_, l)[c]);
          row[{l, c}] += m;
        }
      }
  }
  return w;
}

PairIterationSummary ContactPair::updateFrictional(const Vector& bulkResidual, bool updateSet,
                                                   ContactContributions& out) {
  if (settings_.formulation == ContactFormulation::Penalty) return updatePenaltyFrictional(updateSet, out);
  const auto r = bulkResidual.getData(0);
  const auto& map = *dofMap_;
  const auto& slaveNodes = interface_->slaveNodes();
  const auto& owned = interface_->ownedSlaveNodes();
  const double t = thickness_;
  FrictionalParameters p = frictionalParameters();

  auto residualAt = [&](long long node) {
    std::array<double, 3> values{};
    for (int c = 0; c < dim_; ++c)
      if (!isPrescribed(node, c)) values[c] = r[map.getLocalElement(dofRow(node, c))];
    return values;
  };
  auto prescribedOf = [&](long long node) { return prescribed_[interface_->interfaceNodeIndex(node)]; };
  // The kernel's extras of owned node i with mortar entry `entry`. A
  // prescribed component is driven (it moves the slave relative to the
  // master, FrictionalNodeInput::driven) unless a master node coupled to the
  // slave node has it prescribed too: then it is a plane both bodies share (a
  // symmetry plane), across which nothing slides; the mortar slip there is
  // one-sided (the node's support ends at the plane) and must not be read as
  // a slip.
  auto extrasOf = [&](std::size_t i, const NodalMortarEntry& entry) {
    NodeExtras x;
    x.prescribed = prescribedOf(entry.node);
    for (int c = 0; c < dim_; ++c) {
      if (!x.prescribed[c]) continue;
      bool shared = false;
      for (const auto& [master, Mjl] : entry.M) shared = shared || isPrescribed(master, c);
      x.driven[c] = !shared;
    }
    x.oldTraction = stepStartTraction_[i];
    x.lastSlip = lastStepSlip_[i];
    x.previousDirection = slipDirection_[i];
    return x;
  };

  // Stage 1: values, the new sets.
  PairIterationSummary summary;
  std::string failure;
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const ContactState previous = state_[i];
    const NodalMortarEntry* entry = mortar_.find(node);
    ContactState state = ContactState::Inactive;
    State decided;
    if (entry != nullptr && entry->D > minimumD_) {
      const auto w = weightedSlip(*entry, nullptr);
      setNodeParameters(p, i, node);
      decided =
          decide(dim_, residualAt(node), normals_[s].n, w, entry->D, entry->gap, extrasOf(i, *entry), previous, p);
      weightedSlip_[i] = w;
      for (int c = 0; c < 3; ++c) slipIncrement_[i][c] = -w[c] / entry->D;  // the slave relative to the master
      state = nextState(decided.state, previous, updateSet, summary.violations);
      if (state == ContactState::Inactive) decided = State{};
      if (isActive(state)) {
        std::string deep = penetrationFailure(node, entry->gap, entry->D);
        if (failure.empty()) failure = std::move(deep);
      }
    }
    settleState(i, state, previous, summary);
    if (state != kSlip) slipDirection_[i] = {0.0, 0.0, 0.0};  // stage 2 sets it for the slipping ones
    lambdaN_[i] = decided.lambdaN;
    pressure_[i] = -k_ * decided.lambdaN;
    traction_[i] = decided.traction;
  }
  widenSearchRadius();
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  differentiateActive();

  // Stage 2: the rows of the active nodes and their derivatives.
  for (std::size_t i = 0; i < owned.size(); ++i) {
    if (!isActive(state_[i])) continue;
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const NodalMortarEntry* entry = mortarDerivatives_.find(node);
    if (entry == nullptr) continue;  // cannot happen: the node's faces were differentiated
    const auto& n = normalDerivatives_[s].n;
    const auto& dn = normalDerivatives_[s].derivative;
    std::array<DerivativeRow, 3> dw;
    const auto w = weightedSlip(*entry, &dw);
    const auto rf = residualAt(node);
    setNodeParameters(p, i, node);
    const NodeExtras extras = extrasOf(i, *entry);
    const Rows k = rowsOf(dim_, rf, n, w, entry->D, entry->gap, extras, state_[i], p);
    if (!k.usable) continue;
    slipDirection_[i] = k.direction;

    // Forces and residual figures: the recovered traction acts on the slave.
    double tn = 0;
    for (int c = 0; c < dim_; ++c) tn += k.lambda[c] * n[c];
    for (int c = 0; c < dim_; ++c) {
      const double force = k_ * t * entry->D * k.lambda[c];
      const double normal = k_ * t * entry->D * tn * n[c];
      summary.slaveForce[c] += force;
      summary.normalForce[c] += normal;
      summary.tangentialForce[c] += force - normal;
      summary.contactForce2 += force * force;
      summary.tangentialForce2 += (force - normal) * (force - normal);
    }

    // The explicit part of d(row)/dx: through n, w, D and g~ (the r part is tangentTransform).
    auto explicitRow = [&](const std::array<double, 11>& d, bool withSlipAndGap) {
      DerivativeRow row;
      for (const auto& nd : dn)
        for (int m = 0; m < dim_; ++m)
          if (d[3 + m] != 0.0) row[{nd.node, nd.component}] += d[3 + m] * nd.dn[m];
      addScaled(row, entry->dD, d[9]);
      if (withSlipAndGap) {
        for (int m = 0; m < dim_; ++m) addScaled(row, dw[m], d[6 + m]);
        addScaled(row, entry->dGap, d[10]);
      }
      return row;
    };
    auto emit = [&](GlobalOrdinal target, const DerivativeRow& row, double scale) {
      for (const auto& [key, value] : row)
        if (value != 0.0 && !isPrescribed(key.first, key.second))
          out.constraint.push_back({target, dofRow(key.first, key.second), scale * value});
    };

    // Slave rows: the bulk row is replaced (T - I = -1), the value goes to g.
    // A prescribed component keeps its row; its force goes to the support.
    for (int c = 0; c < dim_; ++c) {
      if (isPrescribed(node, c)) {
        out.prescribedForce.push_back({dofRow(node, c), k_ * t * entry->D * k.lambda[c]});
        continue;
      }
      const GlobalOrdinal target = dofRow(node, c);
      out.transform.push_back({target, target, -1.0});
      out.constraintResidual.push_back({target, k.rows[c]});
      for (int m = 0; m < dim_; ++m)
        if (!isPrescribed(node, m) && k.dRows[c][m] != 0.0)
          out.tangentTransform.push_back({target, dofRow(node, m), k.dRows[c][m]});
      emit(target, explicitRow(k.dRows[c], true), 1.0);
    }
    // Tangential rows for the (4.78) groups: every free slot but the gap row's.
    {
      double gapRow2 = 0, all2 = 0;
      double largest = -1;
      int gapSlot = -1;
      for (int c = 0; c < dim_; ++c)
        if (!isPrescribed(node, c) && std::abs(n[c]) > largest) {
          largest = std::abs(n[c]);
          gapSlot = c;
        }
      for (int c = 0; c < dim_; ++c) {
        if (isPrescribed(node, c)) continue;
        if (c == gapSlot) gapRow2 += k.rows[c] * k.rows[c];
        else all2 += k.rows[c] * k.rows[c];
      }
      summary.normalResidual2 += gapRow2;
      (state_[i] == ContactState::Stick ? summary.stickResidual2 : summary.slipResidual2) += all2;
    }
    // Master rows: + k t M_jl lambda_j (the recovered force, acting on the master as -f).
    // lambda depends on w and g~ only along driven directions (FrictionalNode.hpp).
    for (const auto& [master, Mjl] : entry->M)
      for (int c = 0; c < dim_; ++c) {
        const GlobalOrdinal target = dofRow(master, c);
        const double kt = k_ * t;
        if (isPrescribed(master, c)) {
          out.prescribedForce.push_back({target, -kt * Mjl * k.lambda[c]});
          continue;
        }
        out.constraintResidual.push_back({target, kt * Mjl * k.lambda[c]});
        for (int m = 0; m < dim_; ++m)
          if (!isPrescribed(node, m) && k.dLambda[c][m] != 0.0)
            out.tangentTransform.push_back({target, dofRow(node, m), kt * Mjl * k.dLambda[c][m]});
        DerivativeRow row = explicitRow(k.dLambda[c], true);
        for (auto& [key, value] : row) value *= Mjl;
        const auto dM = entry->dM.find(master);
        if (dM != entry->dM.end()) addScaled(row, dM->second, k.lambda[c]);
        emit(target, row, kt);
      }
  }
  reduceSummary(summary);
  return summary;
}

namespace {

/// Penalty kernel of either dimension, widened to 3 components and the 8
/// inputs of 3D (n 0-2, w 3-5, D 6, g~ 7).
struct PenaltyForce {
  std::array<double, 3> force{}, traction{};
  double pressure = 0;
  std::array<std::array<double, 8>, 3> dForce{};
};

template <int dim>
PenaltyFrictionalInput<dim> penaltyInput(const std::array<double, 3>& n, const std::array<double, 3>& w,
                                         const std::array<double, 3>& oldTraction, double D, double gap) {
  PenaltyFrictionalInput<dim> in;
  for (int c = 0; c < dim; ++c) {
    in.normal[c] = n[c];
    in.slip[c] = w[c];
    in.oldTraction[c] = oldTraction[c];
  }
  in.D = D;
  in.gap = gap;
  return in;
}

template <int dim>
PenaltyForce widenPenalty(const PenaltyFrictionalForce<dim>& k) {
  PenaltyForce out;
  out.pressure = k.pressure;
  auto input = [](int i) { return i < dim ? i : i < 2 * dim ? 3 + i - dim : 6 + i - 2 * dim; };
  for (int c = 0; c < dim; ++c) {
    out.force[c] = k.force[c];
    out.traction[c] = k.traction[c];
    for (int i = 0; i < kPenaltyFrictionalInputs<dim>; ++i) out.dForce[c][input(i)] = k.dForce[c][i];
  }
  return out;
}

}  // namespace

PairIterationSummary ContactPair::updatePenaltyFrictional(bool updateSet, ContactContributions& out) {
  const auto& slaveNodes = interface_->slaveNodes();
  const auto& owned = interface_->ownedSlaveNodes();
  FrictionalParameters p = frictionalParameters();
  auto decide = [&](const std::array<double, 3>& n, const std::array<double, 3>& w, std::size_t i, double D,
                    double gap, ContactState previous) {
    return dim_ == 2 ? penaltyFrictionalState<2>(penaltyInput<2>(n, w, stepStartTraction_[i], D, gap), previous, p)
                     : penaltyFrictionalState<3>(penaltyInput<3>(n, w, stepStartTraction_[i], D, gap), previous, p);
  };
  auto force = [&](const std::array<double, 3>& n, const std::array<double, 3>& w, std::size_t i, double D,
                   double gap, ContactState state) {
    return dim_ == 2
               ? widenPenalty<2>(penaltyFrictionalForce<2>(penaltyInput<2>(n, w, stepStartTraction_[i], D, gap), state, p))
               : widenPenalty<3>(penaltyFrictionalForce<3>(penaltyInput<3>(n, w, stepStartTraction_[i], D, gap), state, p));
  };

  // Stage 1: the sets (values).
  PairIterationSummary summary;
  std::string failure;
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const ContactState previous = state_[i];
    const NodalMortarEntry* entry = mortar_.find(node);
    ContactState state = ContactState::Inactive;
    if (entry != nullptr && entry->D > minimumD_) {
      const auto w = weightedSlip(*entry, nullptr);
      weightedSlip_[i] = w;
      for (int c = 0; c < 3; ++c) slipIncrement_[i][c] = -w[c] / entry->D;
      setNodeParameters(p, i, node);
      state = nextState(decide(normals_[s].n, w, i, entry->D, entry->gap, previous), previous, updateSet,
                        summary.violations);
      if (isActive(state)) {
        std::string deep = penetrationFailure(node, entry->gap, entry->D);
        if (failure.empty()) failure = std::move(deep);
      }
    }
    settleState(i, state, previous, summary);
    if (!isActive(state)) traction_[i] = {0.0, 0.0, 0.0}, lambdaN_[i] = pressure_[i] = 0.0;
  }
  widenSearchRadius();
  throwEvaluationErrorIfAnyRank(*interface_->comm(), failure);
  differentiateActive();

  // Stage 2: forces f on the slave (residual -f, K_c = -df/dx) and -(M/D) f on the masters.
  for (std::size_t i = 0; i < owned.size(); ++i) {
    if (!isActive(state_[i])) continue;
    const int s = owned[i];
    const long long node = slaveNodes[s];
    const NodalMortarEntry* entry = mortarDerivatives_.find(node);
    if (entry == nullptr) continue;
    const auto& n = normalDerivatives_[s].n;
    const auto& dn = normalDerivatives_[s].derivative;
    std::array<DerivativeRow, 3> dw;
    const auto w = weightedSlip(*entry, &dw);
    const double D = entry->D;
    setNodeParameters(p, i, node);
    const PenaltyForce f = force(n, w, i, D, entry->gap, state_[i]);
    pressure_[i] = f.pressure;
    lambdaN_[i] = -f.pressure / k_;
    for (int c = 0; c < 3; ++c) traction_[i][c] = f.traction[c] - f.pressure * n[c];
    double fn = 0;
    for (int c = 0; c < dim_; ++c) fn += f.force[c] * n[c];
    for (int c = 0; c < dim_; ++c) {
      summary.slaveForce[c] += f.force[c];
      summary.normalForce[c] += fn * n[c];
      summary.tangentialForce[c] += f.force[c] - fn * n[c];
      summary.contactForce2 += f.force[c] * f.force[c];
      summary.tangentialForce2 += (f.force[c] - fn * n[c]) * (f.force[c] - fn * n[c]);
    }
    auto derivative = [&](int c) {
      DerivativeRow row;
      for (const auto& nd : dn)
        for (int m = 0; m < dim_; ++m)
          if (f.dForce[c][m] != 0.0) row[{nd.node, nd.component}] += f.dForce[c][m] * nd.dn[m];
      for (int m = 0; m < dim_; ++m) addScaled(row, dw[m], f.dForce[c][3 + m]);
      addScaled(row, entry->dD, f.dForce[c][6]);
      addScaled(row, entry->dGap, f.dForce[c][7]);
      return row;
    };
    auto emit = [&](GlobalOrdinal target, const DerivativeRow& row, double scale) {
      for (const auto& [key, value] : row)
        if (value != 0.0 && !isPrescribed(key.first, key.second))
          out.contactStiffness.push_back({target, dofRow(key.first, key.second), scale * value});
    };
    for (int c = 0; c < dim_; ++c) {
      const DerivativeRow df = derivative(c);
      if (!isPrescribed(node, c)) {
        out.contactResidual.push_back({dofRow(node, c), -f.force[c]});
        emit(dofRow(node, c), df, -1.0);
      } else {
        out.prescribedForce.push_back({dofRow(node, c), f.force[c]});
      }
      for (const auto& [master, Mjl] : entry->M) {
        if (isPrescribed(master, c)) {
          out.prescribedForce.push_back({dofRow(master, c), -Mjl / D * f.force[c]});
          continue;
        }
        const GlobalOrdinal target = dofRow(master, c);
        out.contactResidual.push_back({target, Mjl / D * f.force[c]});
        DerivativeRow row = df;
        for (auto& [key, value] : row) value *= Mjl / D;
        const auto dM = entry->dM.find(master);
        if (dM != entry->dM.end()) addScaled(row, dM->second, f.force[c] / D);
        addScaled(row, entry->dD, -Mjl * f.force[c] / (D * D));
        emit(target, row, 1.0);
      }
    }
  }
  reduceSummary(summary);
  return summary;
}

}  // namespace coulomb::contact
