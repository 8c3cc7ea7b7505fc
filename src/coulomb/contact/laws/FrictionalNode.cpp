/// @file FrictionalNode.cpp
/// @brief The frictional node kernel (FrictionalNode.hpp): one generic
/// function of the scalar type, evaluated with doubles for the decision and
/// with Sacado forward AD for the rows and their derivatives.
#include "coulomb/contact/laws/FrictionalNode.hpp"

#include <cmath>

#include <Sacado.hpp>

#include "coulomb/contact/laws/CondensationFrame.hpp"
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
  std::array<S, dim> lambda{};    ///< lambda_n n + sum beta_s b_s + sum (tau_k / k) u_k
  S augmentedNormal = 0.0;
  /// Driven tangent directions (FrictionalNodeInput::driven): unit u_k ⟂ n
  /// and ⟂ every b_s, the first numDriven of u; along them the traction
  /// tau_k is explicit, the trial of the return map (4.71a) when sticking,
  /// Θ d_k when slipping.
  int numDriven = 0;
  std::array<std::array<S, dim>, dim> u{};
  std::array<S, dim> trial{};  ///< u_k.t_old + eps_tau u_k.w / D
  std::array<S, dim> tau{};    ///< traction along u_k
  S threshold = 0.0;           ///< Θ of a driven slipping node (consistent with its tau)
};

/// |(vO, vU)|, and (vO, vU) / |.| into (unitO, unitU) unless the norm is zero
/// (then they are left as they are). vO by tangent slot, vU by driven direction.
template <int dim, class S>
S normalize(const std::array<S, dim>& vO, const std::array<S, dim>& vU, int numDriven, std::array<S, dim>& unitO,
            std::array<S, dim>& unitU) {
  using std::sqrt;
  S norm2 = 0.0;
  for (int c = 0; c < dim; ++c) norm2 += vO[c] * vO[c];
  for (int k = 0; k < numDriven; ++k) norm2 += vU[k] * vU[k];
  if (valueOf(norm2) <= 0.0) return S(0.0);
  const S norm = sqrt(norm2);
  for (int c = 0; c < dim; ++c) unitO[c] = vO[c] / norm;
  for (int k = 0; k < numDriven; ++k) unitU[k] = vU[k] / norm;
  return norm;
}

/// |lambdā_tau| with the slip augmentation `alpha` on the frame's tangent
/// slots (k beta_s + alpha eps_tau b_s.w / D) and the trial on the driven
/// directions, and its unit direction (zero when the norm is zero).
template <int dim, class S>
S augmentedTangent(const NodeTerms<dim, S>& t, const S& D, double alpha, const FrictionalParameters& p,
                   std::array<S, dim>& directionO, std::array<S, dim>& directionU, double multiplierWeight = 1.0) {
  directionO = {};
  directionU = {};
  std::array<S, dim> v{};
  for (int i = 0; i < t.frame.numFree; ++i) {
    const int s = t.frame.free[i];
    if (s != t.frame.gapSlot) v[s] = multiplierWeight * p.k * t.beta[s] + alpha * p.epsTau * t.slip[s] / D;
  }
  return normalize<dim, S>(v, t.trial, t.numDriven, directionO, directionU);
}

/// The unit direction of the tangential part of `slip` (a fixed vector) in
/// the frame's tangent slots and the driven directions, written into the
/// directions unless that part is zero.
template <int dim, class S>
void fixedDirection(const NodeTerms<dim, S>& t, const std::array<double, dim>& slip, std::array<S, dim>& directionO,
                    std::array<S, dim>& directionU) {
  std::array<S, dim> qO{}, qU{}, unitO{}, unitU{};
  for (int i = 0; i < t.frame.numFree; ++i) {
    const int s = t.frame.free[i];
    if (s == t.frame.gapSlot) continue;
    for (int c = 0; c < dim; ++c) qO[s] += t.frame.b[s][c] * slip[c];
  }
  for (int k = 0; k < t.numDriven; ++k)
    for (int c = 0; c < dim; ++c) qU[k] += t.u[k][c] * slip[c];
  if (valueOf(normalize<dim, S>(qO, qU, t.numDriven, unitO, unitU)) > 0.0) directionO = unitO, directionU = unitU;
}

/// The slip direction d of the slip rows: the augmented multiplier's with
/// the slip augmentation, or (slipDirectionFromSlip) the last step's slip.
template <int dim, class S>
void slipDirection(const NodeTerms<dim, S>& t, const S& D, const FrictionalNodeInput<dim>& in,
                   const FrictionalParameters& p, std::array<S, dim>& directionO, std::array<S, dim>& directionU) {
  augmentedTangent<dim, S>(t, D, p.slipAugmentation, p, directionO, directionU);
  if (p.slipDirectionFromSlip) fixedDirection<dim, S>(t, in.lastSlip, directionO, directionU);
  if (p.pureSlip) {
    // The seed's pure slip: the tangent of the weighted slip itself, with its
    // derivatives (the multiplier left out of the augmentation).
    std::array<S, dim> o{}, u{};
    if (valueOf(augmentedTangent<dim, S>(t, D, 1.0, p, o, u, 0.0)) > 0.0) directionO = o, directionU = u;
  }
}

/// Σ_s vO_s b_s + Σ_k vU_k u_k: a tangent vector in world components.
template <int dim, class S>
std::array<double, dim> worldVector(const NodeTerms<dim, S>& t, const std::array<S, dim>& vO,
                                    const std::array<S, dim>& vU) {
  std::array<double, dim> out{};
  for (int i = 0; i < t.frame.numFree; ++i) {
    const int s = t.frame.free[i];
    if (s == t.frame.gapSlot) continue;
    for (int c = 0; c < dim; ++c) out[c] += valueOf(vO[s]) * valueOf(t.frame.b[s][c]);
  }
  for (int k = 0; k < t.numDriven; ++k)
    for (int c = 0; c < dim; ++c) out[c] += valueOf(vU[k]) * valueOf(t.u[k][c]);
  return out;
}

/// The driven tangent directions of a node: each driven component's unit
/// vector e_c, Gram-Schmidt against n/|n|, the b_s and the u's before it.
/// (e_c is prescribed, so ⟂ every b_s already, and e_P with n and the b_s
/// span the space: |v| >= the part of e_c off n, >= 0.2 for a usable frame.)
template <int dim, class S>
void drivenDirections(NodeTerms<dim, S>& t, const std::array<S, dim>& n, const std::array<bool, dim>& driven) {
  using std::sqrt;
  S n2 = 0.0;
  for (int c = 0; c < dim; ++c) n2 += n[c] * n[c];
  const S nNorm = sqrt(n2);
  for (int e = 0; e < dim; ++e) {
    if (!driven[e] || t.frame.numFree == dim) continue;
    bool free = false;
    for (int i = 0; i < t.frame.numFree; ++i) free = free || t.frame.free[i] == e;
    if (free) continue;  // a free component is never driven
    std::array<S, dim> v{};
    v[e] = 1.0;
    auto remove = [&v](const std::array<S, dim>& unit) {
      S dot = 0.0;
      for (int c = 0; c < dim; ++c) dot += v[c] * unit[c];
      for (int c = 0; c < dim; ++c) v[c] -= dot * unit[c];
    };
    std::array<S, dim> nUnit{};
    for (int c = 0; c < dim; ++c) nUnit[c] = n[c] / nNorm;
    remove(nUnit);
    for (int k = 0; k < t.numDriven; ++k) remove(t.u[k]);
    S length2 = 0.0;
    for (int c = 0; c < dim; ++c) length2 += v[c] * v[c];
    if (valueOf(length2) < 1e-12) continue;
    const S length = sqrt(length2);
    for (int c = 0; c < dim; ++c) v[c] /= length;
    t.u[t.numDriven++] = v;
  }
}

/// The node's terms. `recover`: the multiplier is recovered from r (the node
/// was active at the previous iterate); `state`: the law of the driven
/// directions (Stick: the trial; Active = slip: Θ d).
template <int dim, class S>
NodeTerms<dim, S> nodeTerms(const std::array<S, dim>& r, const std::array<S, dim>& n, const std::array<S, dim>& w,
                            const S& D, const S& gap, const FrictionalNodeInput<dim>& in, bool recover,
                            ContactState state, const FrictionalParameters& p) {
  NodeTerms<dim, S> terms;
  terms.frame = condensationFrame<dim, S>(n, in.prescribed);
  const auto& f = terms.frame;
  if (!f.usable) return terms;
  const double kt = p.k * p.thickness;
  if (recover) {
    S aR = 0.0;
    for (int i = 0; i < f.numFree; ++i) aR += f.a[f.free[i]] * r[f.free[i]];
    terms.lambdaN = aR / (kt * D * f.normFree);
  }
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
  }
  // MPC: the reaction of a tied node, the gap of an untied one (no augmentation).
  auto augmented = [&](const S& lambdaN) -> S {
    return !p.multiPointConstraint ? S(p.k * lambdaN + p.epsN * gap / D) : recover ? S(p.k * lambdaN)
                                                                                 : S(p.epsN * gap / D);
  };
  drivenDirections<dim, S>(terms, n, in.driven);
  if (terms.numDriven > 0) {
    // The driven directions carry an explicit traction: no free row of the
    // slave sees them (their components are prescribed), so the slave rows
    // cannot recover it. But it acts on the master (k t M_jl lambda) and on
    // the support of the prescribed DoF, and through n_F on the a-row:
    //   a.r_F / (k t D) = lambda_n |n_F| + sum_k (tau_k / k) a.u_k,
    // so lambda_n = lambda_n0 - sum_k (tau_k / k) a.u_k / |n_F|.
    std::array<S, dim> aU{};
    for (int k = 0; k < terms.numDriven; ++k) {
      for (int c = 0; c < dim; ++c) {
        terms.trial[k] += terms.u[k][c] * in.oldTraction[c] + p.epsTau * terms.u[k][c] * w[c] / D;
        aU[k] += f.a[c] * terms.u[k][c];
      }
      aU[k] /= f.normFree;
    }
    if (state == ContactState::Slip) {
      // tau_k = Θ d_k with Θ at lambdā_n = lambdā_n0 - Θ c, c = sum_k a.u_k d_k / |n_F|:
      // Coulomb Θ = mu <-lambdā_n> gives Θ = Θ0 / (1 - mu c) (c ~ the normal's
      // tilt into the driven directions, ~1e-4); Tresca's Θ is constant.
      std::array<S, dim> directionO{}, directionU{};
      slipDirection<dim, S>(terms, D, in, p, directionO, directionU);
      S c = 0.0;
      for (int k = 0; k < terms.numDriven; ++k) c += aU[k] * directionU[k];
      const S theta0 = frictionThreshold(p.law, augmented(terms.lambdaN));
      const double mu = p.law.coefficient;
      const bool coupled =
          p.law.type == FrictionLawType::Coulomb && valueOf(theta0) > 0.0 && 1.0 - mu * valueOf(c) >= 0.5;
      terms.threshold = coupled ? S(theta0 / (1.0 - mu * c)) : theta0;
      for (int k = 0; k < terms.numDriven; ++k) terms.tau[k] = terms.threshold * directionU[k];
    } else {
      for (int k = 0; k < terms.numDriven; ++k) terms.tau[k] = terms.trial[k];
    }
    if (recover)
      for (int k = 0; k < terms.numDriven; ++k) terms.lambdaN -= terms.tau[k] * aU[k] / p.k;
  }
  for (int c = 0; c < dim; ++c) terms.lambda[c] = terms.lambdaN * n[c];
  // Without a friction law the multiplier has no tangential part: the
  // tangent rows (b_s.r_F = 0) say that the bulk carries none, and until
  // they hold the master is not pushed by the slave's tangential residual
  // (with it: friction_r2 frictionless 31 Newton iterations against 30,
  // one_element_bodies_3d 3 against 2).
  for (int i = 0; i < f.numFree && p.law.type != FrictionLawType::None; ++i) {
    const int s = f.free[i];
    if (s == f.gapSlot) continue;
    for (int c = 0; c < dim; ++c) terms.lambda[c] += terms.beta[s] * f.b[s][c];
  }
  for (int k = 0; k < terms.numDriven; ++k)
    for (int c = 0; c < dim; ++c) terms.lambda[c] += terms.tau[k] / p.k * terms.u[k][c];
  terms.augmentedNormal = augmented(terms.lambdaN);
  return terms;
}

/// A slipping node whose iterate slid against the direction `previous` its
/// slip rows gave it (w.d < 0) far enough that the rule (4.75-4.77) would
/// reverse it (lambdā_tau.d < 0, `directionO/U` the unit lambdā_tau), or
/// that took more than kAgainst Θ off lambdā_tau along d: it sticks instead
/// (the traction that holds it lies between +Θ d and -Θ d). Without this, d
/// flipped at every iterate (a stick/slip 2-cycle), or the slip rows
/// converged with the friction force along the slip (negative dissipation);
/// docs/architecture.md, "Slip reversal → stick", has the cases and figures.
/// kAgainst lies far above the round-off of w and far below the hysteresis.
template <int dim>
bool slipReversed(const NodeTerms<dim, double>& t, const std::array<double, dim>& directionO,
                  const std::array<double, dim>& directionU, const FrictionalNodeInput<dim>& in, double threshold,
                  const FrictionalParameters& p) {
  constexpr double kAgainst = 1e-6;
  const auto augmented = worldVector<dim, double>(t, directionO, directionU);
  double along = 0.0, slid = 0.0;
  for (int c = 0; c < dim; ++c) {
    along += augmented[c] * in.previousDirection[c];
    slid += in.slip[c] * in.previousDirection[c];
  }
  if (!(slid < 0.0)) return false;
  return along < 0.0 || p.slipAugmentation * p.epsTau * (-slid) / in.D > kAgainst * threshold;
}

void checkParameters(double D, const FrictionalParameters& p) {
  COULOMB_CHECK(D > 0.0, "contact: nodal mortar weight D_j must be > 0, got " << D);
  COULOMB_CHECK(p.k > 0.0 && p.epsN > 0.0 && p.epsTau > 0.0 && p.thickness > 0.0 && p.slipAugmentation > 0.0,
                  "contact: frictional parameters k, eps_n, eps_tau, thickness and slip augmentation must be > 0");
}

}  // namespace

template <int dim>
FrictionalNodeState<dim> frictionalState(const FrictionalNodeInput<dim>& in, ContactState previous,
                                         const FrictionalParameters& p) {
  checkParameters(in.D, p);
  FrictionalNodeState<dim> out;
  // The driven directions follow the law of the rows of the previous iterate.
  const auto terms = nodeTerms<dim, double>(in.residual, in.normal, in.slip, in.D, in.gap, in,
                                            isActive(previous), previous == ContactState::Slip ? ContactState::Slip : ContactState::Stick, p);
  if (!terms.frame.usable) return out;
  out.lambdaN = terms.lambdaN;
  out.augmentedNormal = terms.augmentedNormal;
  for (int c = 0; c < dim; ++c) out.traction[c] = p.k * terms.lambda[c];
  // (4.73/4.74): the gap zone; surfaces within the touching gap count as
  // closed, as in almContactState.
  if (terms.augmentedNormal > p.epsN * p.touchingGap) return out;
  out.threshold = frictionThreshold(p.law, terms.augmentedNormal);
  // (4.77): a stick node (or one that just closed) is tested with the full
  // augmentation (MPC: its reaction alone), a slipping one with the slip
  // augmentation alpha.
  std::array<double, dim> directionO{}, directionU{};
  const double stickAugmentation = p.multiPointConstraint ? 0.0 : 1.0;
  out.tangentNorm = augmentedTangent<dim, double>(
      terms, in.D, previous == ContactState::Slip ? p.slipAugmentation : stickAugmentation, p, directionO, directionU);
  const auto direction = worldVector<dim, double>(terms, directionO, directionU);
  for (int c = 0; c < dim; ++c) out.augmentedTangent[c] = out.tangentNorm * direction[c];
  // A node that closes (first time in the step, or again) has no recovered
  // traction: it is judged on its augmented values (lambda = 0) from the
  // stick side, |eps_tau w / D| against Θ(eps_n g~ / D), not forced to
  // stick (Algorithm 3, line 6; docs/architecture.md, "Sets", has why). A
  // slip at the round-off of the coordinates (|w| / D <= roundOffSlip) is no
  // slip: the decision must not depend on bits that differ with the rank count.
  if (isActive(previous)) {
    out.state = stickSlipState(out.tangentNorm, out.threshold, previous, p.slipThreshold);
    // A direction fixed for the step (the last step's slip, slipDirectionFromSlip)
    // does not follow lambdā_tau: it cannot flip, and sliding against it on the
    // way is no sign of a stick state.
    bool fixed = false;
    if (p.slipDirectionFromSlip) {
      std::array<double, dim> o{}, u{};
      fixedDirection<dim, double>(terms, in.lastSlip, o, u);
      for (int c = 0; c < dim; ++c) fixed = fixed || o[c] != 0.0 || u[c] != 0.0;
    }
    if (p.pureSlip) {
      out.state = ContactState::Slip;
      return out;
    }
    if (previous == ContactState::Slip && out.state == ContactState::Slip && !fixed &&
        slipReversed<dim>(terms, directionO, directionU, in, out.threshold, p))
      out.state = ContactState::Stick;
  } else if (p.pureSlip) {
    out.state = ContactState::Slip;
  } else {
    double slip2 = 0.0;
    for (int c = 0; c < dim; ++c) slip2 += in.slip[c] * in.slip[c];
    out.state = std::sqrt(slip2) > p.roundOffSlip * in.D
                    ? stickSlipState(out.tangentNorm, out.threshold, ContactState::Stick, p.slipThreshold)
                    : ContactState::Stick;
  }
  return out;
}

template <int dim>
FrictionalNodeRows<dim> frictionalRows(const FrictionalNodeInput<dim>& in, ContactState state,
                                       const FrictionalParameters& p) {
  checkParameters(in.D, p);
  COULOMB_CHECK(isActive(state), "contact: frictional rows of an inactive node");
  constexpr int N = kFrictionalInputs<dim>;
  using Fad = Sacado::Fad::SFad<double, N>;
  std::array<Fad, dim> r, n, w;
  for (int c = 0; c < dim; ++c) {
    r[c] = Fad(N, c, in.residual[c]);
    n[c] = Fad(N, dim + c, in.normal[c]);
    w[c] = Fad(N, 2 * dim + c, in.slip[c]);
  }
  const Fad D(N, 3 * dim, in.D), gap(N, 3 * dim + 1, in.gap);
  const auto terms = nodeTerms<dim, Fad>(r, n, w, D, gap, in, true, state, p);
  FrictionalNodeRows<dim> out;
  out.usable = terms.frame.usable;
  if (!out.usable) return out;
  const auto& f = terms.frame;
  const double t = p.thickness;
  std::array<Fad, dim> rows{};
  rows[f.gapSlot] = f.gapRowSign * p.epsN * t * gap;
  std::array<Fad, dim> direction{}, directionU{};
  Fad threshold = 0.0;
  if (state == ContactState::Slip) {
    slipDirection<dim, Fad>(terms, D, in, p, direction, directionU);
    threshold = terms.numDriven > 0 ? terms.threshold : frictionThreshold(p.law, terms.augmentedNormal);
    out.direction = worldVector<dim, Fad>(terms, direction, directionU);
  }
  for (int i = 0; i < f.numFree; ++i) {
    const int s = f.free[i];
    if (s == f.gapSlot) continue;
    if (state == ContactState::Stick) {
      // -eps_n t (b_s.w): w is the master relative to the slave, so the row
      // of +(b_s.w) has about -eps_n t D on its own diagonal; negated, every
      // condensed row has a positive diagonal, which Ifpack2's l1
      // Gauss-Seidel needs: it adds the off-rank magnitudes to a diagonal it
      // finds small, and a negative one then nears zero (the frictional tube
      // at np 3 stalled GMRES at 1000 iterations in the first contact
      // iterate).
      rows[s] = -p.epsN * t * terms.slip[s];
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
  if (p.pureSlip) return ContactState::Slip;  // the traction threshold × trial / |trial|: against the slip
  return stickSlipState(trialNorm, threshold, isActive(previous) ? previous : ContactState::Stick, p.slipThreshold);
}

template <int dim>
PenaltyFrictionalForce<dim> penaltyFrictionalForce(const PenaltyFrictionalInput<dim>& in, ContactState state,
                                                   const FrictionalParameters& p) {
  checkParameters(in.D, p);
  COULOMB_CHECK(isActive(state), "contact: penalty frictional force of an inactive node");
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
    out.trial[c] = trial[c].val();
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
