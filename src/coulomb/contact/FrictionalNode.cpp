/// @file FrictionalNode.cpp
/// @brief The frictional node kernel (FrictionalNode.hpp): one generic
/// function of the scalar type, evaluated with doubles for the decision and
/// with Sacado forward AD for the rows and their derivatives.
#include "coulomb/contact/FrictionalNode.hpp"

#include <cmath>

#include <Sacado.hpp>

#include "coulomb/contact/CondensationFrame.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

namespace {

double valueOf(double x) { return x; }
template <class T>
double valueOf(const T& x) {
  return x.val();
}

/// Everything the rows and the decision need, for one scalar type.
template <int dim, class S>
struct NodeTerms {
  CondensationFrame<dim, S> frame;
  S lambdaN = 0.0;
  std::array<S, dim> beta{};      ///< by tangent slot (b_s.r_F / (k t D))
  std::array<S, dim> slip{};      ///< by tangent slot (b_s.w)
  std::array<S, dim> lambda{};    ///< lambda_n n + sum beta_s b_s
  S augmentedNormal = 0.0;
};

template <int dim, class S>
NodeTerms<dim, S> nodeTerms(const std::array<S, dim>& r, const std::array<S, dim>& n, const std::array<S, dim>& w,
                            const S& D, const S& gap, const std::array<bool, dim>& prescribed, bool recover,
                            const FrictionalParameters& p) {
  NodeTerms<dim, S> terms;
  terms.frame = condensationFrame<dim, S>(n, prescribed);
  const auto& f = terms.frame;
  if (!f.usable) return terms;
  const double kt = p.k * p.thickness;
  if (recover) {
    S aR = 0.0;
    for (int i = 0; i < f.numFree; ++i) aR += f.a[f.free[i]] * r[f.free[i]];
    terms.lambdaN = aR / (kt * D * f.normFree);
  }
  for (int c = 0; c < dim; ++c) terms.lambda[c] = terms.lambdaN * n[c];
  for (int i = 0; i < f.numFree; ++i) {
    const int s = f.free[i];
    if (s == f.gapSlot) continue;
    S q = 0.0, ws = 0.0;
    for (int c = 0; c < dim; ++c) {
      q += f.b[s][c] * r[c];
      ws += f.b[s][c] * w[c];
    }
    terms.beta[s] = recover ? S(q / (kt * D)) : S(0.0);
    terms.slip[s] = ws;
    for (int c = 0; c < dim; ++c) terms.lambda[c] += terms.beta[s] * f.b[s][c];
  }
  // MPC: the reaction of a tied node, the gap of an untied one (no augmentation).
  terms.augmentedNormal = !p.multiPointConstraint ? S(p.k * terms.lambdaN + p.epsN * gap / D)
                          : recover               ? S(p.k * terms.lambdaN)
                                                  : S(p.epsN * gap / D);
  return terms;
}

/// The vector with `component(s)` in the frame's tangent slots (free, not the gap's), zero elsewhere.
template <int dim, class S, class Component>
std::array<S, dim> tangential(const NodeTerms<dim, S>& t, Component component) {
  std::array<S, dim> v{};
  for (int i = 0; i < t.frame.numFree; ++i)
    if (t.frame.free[i] != t.frame.gapSlot) v[t.frame.free[i]] = component(t.frame.free[i]);
  return v;
}

/// |v|, and v / |v| into `unit` unless |v| is zero (then `unit` is left as it is).
template <int dim, class S>
S normalize(const std::array<S, dim>& v, std::array<S, dim>& unit) {
  using std::sqrt;
  S norm2 = 0.0;
  for (int c = 0; c < dim; ++c) norm2 += v[c] * v[c];
  if (valueOf(norm2) <= 0.0) return S(0.0);
  const S norm = sqrt(norm2);
  for (int c = 0; c < dim; ++c) unit[c] = v[c] / norm;
  return norm;
}

/// |lambdā_tau| with the slip augmentation `alpha`, and the unit direction (zero when the norm is zero).
template <int dim, class S>
S augmentedTangent(const NodeTerms<dim, S>& t, const S& D, double alpha, const FrictionalParameters& p,
                   std::array<S, dim>& direction) {
  direction = {};
  return normalize<dim, S>(
      tangential(t, [&](int s) { return S(p.k * t.beta[s] + alpha * p.epsTau * t.slip[s] / D); }), direction);
}

/// The unit direction of the tangential part of `slip` (a fixed vector) in
/// the frame's tangent slots, written into `direction` unless that part is zero.
template <int dim, class S>
void fixedDirection(const NodeTerms<dim, S>& t, const std::array<double, dim>& slip, std::array<S, dim>& direction) {
  std::array<S, dim> unit{};
  const auto q = tangential(t, [&](int s) {
    S v = 0.0;
    for (int c = 0; c < dim; ++c) v += t.frame.b[s][c] * slip[c];
    return v;
  });
  if (valueOf(normalize<dim, S>(q, unit)) > 0.0) direction = unit;
}

void checkParameters(double D, const FrictionalParameters& p) {
  COULOMB_REQUIRE(D > 0.0, "contact: nodal mortar weight D_j must be > 0, got " << D);
  COULOMB_REQUIRE(p.k > 0.0 && p.epsN > 0.0 && p.epsTau > 0.0 && p.thickness > 0.0 && p.slipAugmentation > 0.0,
                  "contact: frictional parameters k, eps_n, eps_tau, thickness and slip augmentation must be > 0");
}

}  // namespace

template <int dim>
FrictionalNodeState<dim> frictionalState(const FrictionalNodeInput<dim>& in, ContactState previous,
                                         const FrictionalParameters& p) {
  checkParameters(in.D, p);
  FrictionalNodeState<dim> out;
  const auto terms = nodeTerms<dim, double>(in.residual, in.normal, in.slip, in.D, in.gap, in.prescribed,
                                            isActive(previous), p);
  if (!terms.frame.usable) return out;
  out.lambdaN = terms.lambdaN;
  out.augmentedNormal = terms.augmentedNormal;
  for (int c = 0; c < dim; ++c) out.traction[c] = p.k * terms.lambda[c];
  if (terms.augmentedNormal > 0.0) return out;  // (4.73/4.74): the gap zone
  out.threshold = frictionThreshold(p.law, terms.augmentedNormal);
  // (4.77): a stick node (or one that just closed) is tested with the full
  // augmentation (MPC: its reaction alone), a slipping one with the slip
  // augmentation alpha.
  std::array<double, dim> direction{};
  const double stickAugmentation = p.multiPointConstraint ? 0.0 : 1.0;
  out.tangentNorm = augmentedTangent<dim, double>(terms, in.D, previous == kSlip ? p.slipAugmentation : stickAugmentation,
                                                  p, direction);
  // A node that just closed has no recovered traction: the stick guess
  // (Algorithm 3, line 6), deterministic whatever the round-off of its tiny
  // first threshold; one that closes again within the step is judged on its
  // augmented values (lambda = 0), from the stick side.
  if (isActive(previous))
    out.state = stickSlipState(out.tangentNorm, out.threshold, previous, p.slipThreshold);
  else
    out.state = in.reclosing ? stickSlipState(out.tangentNorm, out.threshold, ContactState::Stick, p.slipThreshold)
                             : ContactState::Stick;
  return out;
}

template <int dim>
FrictionalNodeRows<dim> frictionalRows(const FrictionalNodeInput<dim>& in, ContactState state,
                                       const FrictionalParameters& p) {
  checkParameters(in.D, p);
  COULOMB_REQUIRE(isActive(state), "contact: frictional rows of an inactive node");
  constexpr int N = kFrictionalInputs<dim>;
  using Fad = Sacado::Fad::SFad<double, N>;
  std::array<Fad, dim> r, n, w;
  for (int c = 0; c < dim; ++c) {
    r[c] = Fad(N, c, in.residual[c]);
    n[c] = Fad(N, dim + c, in.normal[c]);
    w[c] = Fad(N, 2 * dim + c, in.slip[c]);
  }
  const Fad D(N, 3 * dim, in.D), gap(N, 3 * dim + 1, in.gap);
  const auto terms = nodeTerms<dim, Fad>(r, n, w, D, gap, in.prescribed, true, p);
  FrictionalNodeRows<dim> out;
  out.usable = terms.frame.usable;
  if (!out.usable) return out;
  const auto& f = terms.frame;
  const double t = p.thickness;
  std::array<Fad, dim> rows{};
  rows[f.gapSlot] = f.gapRowSign * p.epsN * t * gap;
  std::array<Fad, dim> direction{};
  Fad threshold = 0.0;
  if (state == kSlip) {
    augmentedTangent<dim, Fad>(terms, D, p.slipAugmentation, p, direction);
    if (p.slipDirectionFromSlip) fixedDirection<dim, Fad>(terms, in.lastSlip, direction);
    threshold = frictionThreshold(p.law, terms.augmentedNormal);
  }
  for (int i = 0; i < f.numFree; ++i) {
    const int s = f.free[i];
    if (s == f.gapSlot) continue;
    if (state == ContactState::Stick) {
      rows[s] = p.epsN * t * terms.slip[s];
    } else {
      // b_s.r_F = k t D beta_s: the recovered tangential force minus the cone's.
      rows[s] = p.k * t * D * terms.beta[s] - t * D * threshold * direction[s];
    }
  }
  for (int c = 0; c < dim; ++c) {
    out.rows[c] = rows[c].val();
    out.lambda[c] = terms.lambda[c].val();
    for (int i = 0; i < N; ++i) {
      out.dRows[c][i] = rows[c].dx(i);
      out.dLambda[c][i] = terms.lambda[c].dx(i);
    }
  }
  return out;
}

namespace {

/// Pressure, trial traction and the traction of `state` for one scalar type.
template <int dim, class S>
void penaltyTerms(const std::array<S, dim>& n, const std::array<S, dim>& w, const S& D, const S& gap,
                  const std::array<double, dim>& oldTraction, ContactState state, const FrictionalParameters& p,
                  S& pressure, std::array<S, dim>& trial, std::array<S, dim>& traction, S& trialNorm, S& threshold) {
  using std::sqrt;
  pressure = valueOf(gap) < 0.0 ? S(-p.epsN * gap / D) : S(0.0);
  S nOld = 0.0;
  for (int c = 0; c < dim; ++c) nOld += n[c] * oldTraction[c];
  for (int c = 0; c < dim; ++c) trial[c] = oldTraction[c] - nOld * n[c];
  S nw = 0.0;
  for (int c = 0; c < dim; ++c) nw += n[c] * w[c];
  for (int c = 0; c < dim; ++c) trial[c] += p.epsTau * (w[c] - nw * n[c]) / D;
  S norm2 = 0.0;
  for (int c = 0; c < dim; ++c) norm2 += trial[c] * trial[c];
  trialNorm = valueOf(norm2) > 0.0 ? S(sqrt(norm2)) : S(0.0);
  threshold = frictionThreshold(p.law, S(-pressure));
  for (int c = 0; c < dim; ++c)
    traction[c] = state == ContactState::Stick ? trial[c]
                  : valueOf(trialNorm) > 0.0   ? S(threshold * trial[c] / trialNorm)
                                               : S(0.0);
}

}  // namespace

template <int dim>
ContactState penaltyFrictionalState(const PenaltyFrictionalInput<dim>& in, ContactState previous,
                                    const FrictionalParameters& p) {
  checkParameters(in.D, p);
  if (in.gap > 0.0) return ContactState::Inactive;
  double pressure = 0, trialNorm = 0, threshold = 0;
  std::array<double, dim> trial{}, traction{};
  penaltyTerms<dim, double>(in.normal, in.slip, in.D, in.gap, in.oldTraction, ContactState::Stick, p, pressure, trial,
                            traction, trialNorm, threshold);
  return stickSlipState(trialNorm, threshold, isActive(previous) ? previous : ContactState::Stick, p.slipThreshold);
}

template <int dim>
PenaltyFrictionalForce<dim> penaltyFrictionalForce(const PenaltyFrictionalInput<dim>& in, ContactState state,
                                                   const FrictionalParameters& p) {
  checkParameters(in.D, p);
  COULOMB_REQUIRE(isActive(state), "contact: penalty frictional force of an inactive node");
  constexpr int N = kPenaltyFrictionalInputs<dim>;
  using Fad = Sacado::Fad::SFad<double, N>;
  std::array<Fad, dim> n, w;
  for (int c = 0; c < dim; ++c) {
    n[c] = Fad(N, c, in.normal[c]);
    w[c] = Fad(N, dim + c, in.slip[c]);
  }
  const Fad D(N, 2 * dim, in.D), gap(N, 2 * dim + 1, in.gap);
  Fad pressure, trialNorm, threshold;
  std::array<Fad, dim> trial, traction;
  penaltyTerms<dim, Fad>(n, w, D, gap, in.oldTraction, state, p, pressure, trial, traction, trialNorm, threshold);
  PenaltyFrictionalForce<dim> out;
  out.pressure = pressure.val();
  for (int c = 0; c < dim; ++c) {
    const Fad f = p.thickness * D * (traction[c] - pressure * n[c]);
    out.force[c] = f.val();
    out.traction[c] = traction[c].val();
    for (int i = 0; i < N; ++i) out.dForce[c][i] = f.dx(i);
  }
  return out;
}

#define COULOMB_FRICTIONAL_NODE_INSTANTIATE(DIM)                                                              \
  template FrictionalNodeState<DIM> frictionalState<DIM>(const FrictionalNodeInput<DIM>&, ContactState,       \
                                                         const FrictionalParameters&);                        \
  template FrictionalNodeRows<DIM> frictionalRows<DIM>(const FrictionalNodeInput<DIM>&, ContactState,         \
                                                       const FrictionalParameters&);                          \
  template ContactState penaltyFrictionalState<DIM>(const PenaltyFrictionalInput<DIM>&, ContactState,         \
                                                    const FrictionalParameters&);                             \
  template PenaltyFrictionalForce<DIM> penaltyFrictionalForce<DIM>(const PenaltyFrictionalInput<DIM>&,        \
                                                                   ContactState, const FrictionalParameters&);
COULOMB_FRICTIONAL_NODE_INSTANTIATE(2)
COULOMB_FRICTIONAL_NODE_INSTANTIATE(3)
#undef COULOMB_FRICTIONAL_NODE_INSTANTIATE

}  // namespace coulomb::contact
