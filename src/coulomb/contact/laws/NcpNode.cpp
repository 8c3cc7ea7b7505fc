/// @file NcpNode.cpp
/// @brief The nodal NCP rows of the Lagrange multiplier method (seed 4.79),
/// see NcpNode.hpp. The residual is written once, as a template on the
/// scalar: ncpState evaluates it in double, ncpRows with Sacado (forward
/// mode, one derivative per input: lambda, n, w, D, g~).
#include "coulomb/contact/laws/NcpNode.hpp"

#include <cmath>

#include <Sacado.hpp>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

namespace {

double valueOf(double x) { return x; }
template <class T>
double valueOf(const T& x) {
  return x.val();
}

void checkParameters(double D, const NcpParameters& p) {
  COULOMB_CHECK(D > 0.0, "NCP node: nodal mortar weight D_j must be > 0, got " << D);
  COULOMB_CHECK(p.k > 0.0 && p.cN > 0.0 && p.cTau > 0.0,
                "NCP node: k, c_n and c_tau must be > 0, got " << p.k << ", " << p.cN << ", " << p.cTau);
}

/// The quantities of (4.79) at one node, for one scalar type.
template <int dim, class S>
struct Terms {
  S lambdaN = 0.0;          ///< n.lambda
  S augmentedNormal = 0.0;  ///< lambdā_n = k lambda_n + c_n g~ / D = -(p - c_n g)
  S threshold = 0.0;        ///< Θ(lambdā_n)
  S norm = 0.0;             ///< |a|
  std::array<S, dim> tangent{};    ///< t_tau = P k lambda
  std::array<S, dim> slip{};       ///< w_tau / D = P w / D (a length)
  std::array<S, dim> augmented{};  ///< a = t_tau + c_tau w_tau / D
};

/// n is an input of its own (not normalised here): the caller chains dn/du,
/// so P = I - n n^T is differentiated as written.
template <int dim, class S>
Terms<dim, S> terms(const std::array<S, dim>& lambda, const std::array<S, dim>& n, const std::array<S, dim>& w,
                    const S& D, const S& gap, const NcpParameters& p) {
  using std::sqrt;
  Terms<dim, S> t;
  S wN = 0.0;
  for (int c = 0; c < dim; ++c) {
    t.lambdaN += lambda[c] * n[c];
    wN += w[c] * n[c];
  }
  t.augmentedNormal = p.k * t.lambdaN + p.cN * gap / D;
  t.threshold = frictionThreshold(p.law, t.augmentedNormal);
  S norm2 = 0.0;
  for (int c = 0; c < dim; ++c) {
    t.tangent[c] = p.k * (lambda[c] - t.lambdaN * n[c]);
    t.slip[c] = (w[c] - wN * n[c]) / D;
    t.augmented[c] = t.tangent[c] + p.cTau * t.slip[c];
    norm2 += t.augmented[c] * t.augmented[c];
  }
  // sqrt has no derivative at 0; |a| only enters the slip branch, where |a| > Θ >= 0.
  t.norm = valueOf(norm2) > 0.0 ? S(sqrt(norm2)) : S(0.0);
  return t;
}

/// R = C_n n + C_tau of the branch `state` (NcpNode.hpp).
template <int dim, class S>
std::array<S, dim> residual(const Terms<dim, S>& t, const std::array<S, dim>& n, ContactState state,
                            const NcpParameters& p) {
  // C_n = p - max(0, p - c_n g): active c_n g = lambdā_n - k lambda_n (the gap
  // closes), inactive p = -k lambda_n (the multiplier vanishes).
  const S normal = isActive(state) ? S(t.augmentedNormal - p.k * t.lambdaN) : S(-p.k * t.lambdaN);
  std::array<S, dim> r{};
  for (int c = 0; c < dim; ++c) {
    // Inactive node or frictionless law: C_tau = t_tau (no tangential traction).
    S tangential = t.tangent[c];
    if (isActive(state) && !p.law.frictionless()) {
      // (4.79) max(Θ, |a|) t_tau - Θ a = 0, divided by max(Θ, |a|) so that C_tau
      // is a traction like C_n and the two branches meet at |a| = Θ:
      //   stick: t_tau - a = -c_tau w_tau / D;   slip: t_tau - Θ a / |a|.
      if (state == ContactState::Stick) tangential = -p.cTau * t.slip[c];
      // A slip state frozen by the caller (nextState) may meet a = 0: no
      // direction, Θ a / |a| is taken as 0.
      else if (valueOf(t.norm) > 0.0) tangential = t.tangent[c] - t.threshold * t.augmented[c] / t.norm;
    }
    r[c] = normal * n[c] + tangential;
  }
  return r;
}

}  // namespace

template <int dim>
ContactState ncpState(const NcpNodeInput<dim>& in, ContactState previous, const NcpParameters& p) {
  checkParameters(in.D, p);
  const auto t = terms<dim, double>(in.lambda, in.normal, in.slip, in.D, in.gap, p);
  // The normal zone p - c_n g > 0 is lambdā_n < 0: the ALM rule (4.73/4.74)
  // with c_n for eps_n, touching gap included.
  if (almContactState(t.lambdaN, in.gap, in.D, p.k, p.cN, p.touchingGap) == ContactState::Inactive)
    return ContactState::Inactive;
  if (p.law.frictionless()) return ContactState::Slip;
  // The max in (4.79): stick while |a| <= Θ, with the slip -> stick hysteresis.
  return stickSlipState(t.norm, t.threshold, previous, p.slipThreshold);
}

template <int dim>
NcpNodeRows<dim> ncpRows(const NcpNodeInput<dim>& in, ContactState state, const NcpParameters& p) {
  checkParameters(in.D, p);
  constexpr int N = kNcpInputs<dim>;
  using Fad = Sacado::Fad::SFad<double, N>;
  std::array<Fad, dim> lambda, n, w;
  for (int c = 0; c < dim; ++c) {
    lambda[c] = Fad(N, c, in.lambda[c]);
    n[c] = Fad(N, dim + c, in.normal[c]);
    w[c] = Fad(N, 2 * dim + c, in.slip[c]);
  }
  const Fad D(N, 3 * dim, in.D), gap(N, 3 * dim + 1, in.gap);
  const auto t = terms<dim, Fad>(lambda, n, w, D, gap, p);
  const auto r = residual<dim, Fad>(t, n, state, p);
  NcpNodeRows<dim> out;
  out.augmentedNormal = t.augmentedNormal.val();
  for (int c = 0; c < dim; ++c) {
    out.r[c] = r[c].val();
    out.augmentedTangent[c] = t.augmented[c].val();
    for (int i = 0; i < N; ++i) out.dr[c][i] = r[c].dx(i);
  }
  return out;
}

#define COULOMB_NCP_NODE_INSTANTIATE(DIM)                                                            \
  template ContactState ncpState<DIM>(const NcpNodeInput<DIM>&, ContactState, const NcpParameters&); \
  template NcpNodeRows<DIM> ncpRows<DIM>(const NcpNodeInput<DIM>&, ContactState, const NcpParameters&);
COULOMB_NCP_NODE_INSTANTIATE(2)
COULOMB_NCP_NODE_INSTANTIATE(3)
#undef COULOMB_NCP_NODE_INSTANTIATE

}  // namespace coulomb::contact
