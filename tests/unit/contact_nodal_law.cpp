// Nodal frictionless contact laws: ALM multiplier residual (seed 4.72b, mu = 0),
// active-set rule (4.73/4.74), contact forces (4.72a) and penalty forces (4.71a).
// Complementarity of the roots, derivatives against central finite differences,
// momentum conservation on a matching interface, continuity of the penalty force.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "coulomb/contact/laws/ActiveSet.hpp"
#include "coulomb/contact/laws/NodalContactLaw.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

template <int dim>
NVec<dim> unitNormal() {
  NVec<dim> n{};
  if constexpr (dim == 2) {
    n = {0.6, -0.8};
  } else {
    n = {2.0 / 7.0, -3.0 / 7.0, 6.0 / 7.0};
  }
  return n;
}

template <int dim>
NVec<dim> scaled(const NVec<dim>& v, double s) {
  NVec<dim> out{};
  for (int i = 0; i < dim; ++i) out[i] = v[i] * s;
  return out;
}

template <int dim>
double dotv(const NVec<dim>& a, const NVec<dim>& b) {
  double s = 0.0;
  for (int i = 0; i < dim; ++i) s += a[i] * b[i];
  return s;
}

/// The rule of ActiveSet.hpp on a node's inputs (the state the formulations judge).
template <int dim>
ContactState almState(const AlmNodeInput<dim>& in, const AlmParameters& p) {
  return almContactState(dotv<dim>(in.normal, in.lambda), in.gap, in.D, p.k, p.epsN);
}
/// p_j = -k n.lambda_j.
template <int dim>
double almPressure(const AlmNodeInput<dim>& in, const AlmParameters& p) {
  return -p.k * dotv<dim>(in.normal, in.lambda);
}

// ---------------------------------------------------------------------------
// Complementarity
// ---------------------------------------------------------------------------

// One node with a linear "structure": g~ = g0 - a lambda_n (a > 0: compression,
// lambda_n < 0, pushes the slave away and opens the gap). The semi-smooth
// system r_lambda = 0 with the state from the update rule is solved in closed
// form on both branches; exactly one branch must be self-consistent and its
// root must satisfy the complementarity conditions.
TEST(NodalLawComplementarity, ClosedFormRootOfSpringIsComplementary) {
  const AlmParameters p{2.0, 3.0, 5.0};
  const double D = 0.7, a = 1.3;
  const NVec<3> n = unitNormal<3>();
  int checked = 0;
  for (int ig = -20; ig <= 20; ++ig) {
    const double g0 = 0.1 * ig;
    int consistent = 0;
    // Active branch: normal residual k g~ = 0 -> g~ = 0, lambda_n = g0 / a.
    {
      const double ln = g0 / a;
      AlmNodeInput<3> in{scaled<3>(n, ln), n, 0.0, D};
      if (almState<3>(in, p) == ContactState::Slip) {
        ++consistent;
        const auto res = almResidual<3>(in, p, ContactState::Slip);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(res.r[i], 0.0, 1e-14);
        EXPECT_LE(ln, 0.0) << "g0 " << g0;  // g~ = 0 and lambda_n <= 0
        EXPECT_GE(almPressure<3>(in, p), 0.0);
      }
    }
    // Inactive branch: -c_n lambda_n = 0 -> lambda_n = 0, g~ = g0.
    {
      AlmNodeInput<3> in{NVec<3>{}, n, g0, D};
      if (almState<3>(in, p) == ContactState::Inactive) {
        ++consistent;
        const auto res = almResidual<3>(in, p, ContactState::Inactive);
        for (int i = 0; i < 3; ++i) EXPECT_EQ(res.r[i], 0.0);
        EXPECT_GE(g0, 0.0) << "g0 " << g0;  // lambda = 0 and g~ >= 0
      }
    }
    EXPECT_EQ(consistent, 1) << "g0 " << g0;
    ++checked;
  }
  EXPECT_EQ(checked, 41);
}

// On a grid of (g~, lambda_n) including the axes, the residual with the state of
// the update rule vanishes if and only if the pair is complementary:
// (g~ = 0 and lambda_n <= 0) or (lambda_n = 0 and g~ >= 0).
TEST(NodalLawComplementarity, ResidualVanishesIffComplementary) {
  const AlmParameters p{0.5, 4.0, 2.0};
  const double D = 1.7;
  const NVec<2> n = unitNormal<2>();
  int roots = 0;
  for (int ig = -6; ig <= 6; ++ig) {
    for (int il = -6; il <= 6; ++il) {
      const double g = 0.25 * ig, ln = 0.25 * il;
      AlmNodeInput<2> in{scaled<2>(n, ln), n, g, D};
      const ContactState s = almState<2>(in, p);
      const auto res = almResidual<2>(in, p, s);
      const bool zero = std::abs(res.r[0]) < 1e-14 && std::abs(res.r[1]) < 1e-14;
      const bool complementary = (g == 0.0 && ln <= 0.0) || (ln == 0.0 && g >= 0.0);
      EXPECT_EQ(zero, complementary) << "g~ " << g << " lambda_n " << ln << " state " << s;
      if (zero) ++roots;
    }
  }
  EXPECT_EQ(roots, 13);  // 7 on the negative lambda axis (incl. origin) + 6 on the positive gap axis
}

// A tangential multiplier component is never a root (frictionless: tau.lambda = 0).
TEST(NodalLawComplementarity, TangentialMultiplierIsDrivenToZero) {
  const AlmParameters p{1.0, 10.0, 3.0};
  const NVec<2> n = unitNormal<2>();
  const NVec<2> t{0.8, 0.6};  // tangent
  for (ContactState s : {ContactState::Slip, ContactState::Inactive}) {
    NVec<2> lam{};
    for (int i = 0; i < 2; ++i) lam[i] = -1.0 * n[i] + 0.5 * t[i];
    AlmNodeInput<2> in{lam, n, 0.0, 2.0};
    const auto res = almResidual<2>(in, p, s);
    EXPECT_NEAR(dotv<2>(res.r, t), -2.0 * 1.0 / 3.0 * 0.5, 1e-14) << s;  // -D k^2/eps_tau tau.lambda
  }
}

// The two branches agree on the switching surface lambdā_n = 0 (continuity).
TEST(NodalLawComplementarity, ResidualContinuousAtSwitch) {
  const AlmParameters p{2.0, 3.0, 7.0};
  const double D = 0.5;
  const NVec<3> n = unitNormal<3>();
  for (double g : {-1.0, -0.3, 0.2, 1.5}) {
    const double ln = -p.epsN * g / D / p.k;  // lambdā_n = 0
    NVec<3> lam = scaled<3>(n, ln);
    lam[0] += 0.3 * 3.0;  // some tangential part too: 0.3 (3, 2, 0), orthogonal to n
    lam[1] += 0.3 * 2.0;
    AlmNodeInput<3> in{lam, n, g, D};
    const auto a = almResidual<3>(in, p, ContactState::Slip);
    const auto b = almResidual<3>(in, p, ContactState::Inactive);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.r[i], b.r[i], 1e-12 * (1.0 + std::abs(a.r[i])));
  }
}

// ---------------------------------------------------------------------------
// Derivatives against central finite differences
// ---------------------------------------------------------------------------

template <int dim>
void checkResidualDerivatives(ContactState state) {
  const AlmParameters p{1.7, 2.3, 0.9};
  AlmNodeInput<dim> in;
  in.normal = unitNormal<dim>();
  for (int i = 0; i < dim; ++i) in.lambda[i] = 0.4 - 0.9 * i + 0.3 * i * i;
  in.gap = -0.37;
  in.D = 0.83;
  const auto an = almResidual<dim>(in, p, state);
  const double h = 1e-6;
  auto compare = [&](const NVec<dim>& fd, auto analytic, const char* what, int c) {
    for (int i = 0; i < dim; ++i) {
      const double a = analytic(i);
      EXPECT_LE(std::abs(fd[i] - a), 1e-7 * std::max(1.0, std::abs(a)))
          << what << " dim " << dim << " state " << state << " row " << i << " col " << c << " fd " << fd[i]
          << " analytic " << a;
    }
  };
  auto fdOf = [&](const std::function<void(AlmNodeInput<dim>&, double)>& perturb) {
    AlmNodeInput<dim> plus = in, minus = in;
    perturb(plus, h);
    perturb(minus, -h);
    const auto rp = almResidual<dim>(plus, p, state).r;
    const auto rm = almResidual<dim>(minus, p, state).r;
    NVec<dim> fd{};
    for (int i = 0; i < dim; ++i) fd[i] = (rp[i] - rm[i]) / (2.0 * h);
    return fd;
  };
  for (int c = 0; c < dim; ++c) {
    compare(fdOf([c](AlmNodeInput<dim>& x, double d) { x.lambda[c] += d; }),
            [&](int i) { return an.dLambda[i][c]; }, "dLambda", c);
    compare(fdOf([c](AlmNodeInput<dim>& x, double d) { x.normal[c] += d; }),
            [&](int i) { return an.dNormal[i][c]; }, "dNormal", c);
  }
  compare(fdOf([](AlmNodeInput<dim>& x, double d) { x.gap += d; }), [&](int i) { return an.dGap[i]; }, "dGap",
          0);
  compare(fdOf([](AlmNodeInput<dim>& x, double d) { x.D += d; }), [&](int i) { return an.dD[i]; }, "dD", 0);
}

TEST(NodalLawDerivatives, Active2D) { checkResidualDerivatives<2>(ContactState::Slip); }
TEST(NodalLawDerivatives, Inactive2D) { checkResidualDerivatives<2>(ContactState::Inactive); }
TEST(NodalLawDerivatives, Active3D) { checkResidualDerivatives<3>(ContactState::Slip); }
TEST(NodalLawDerivatives, Inactive3D) { checkResidualDerivatives<3>(ContactState::Inactive); }

// ---------------------------------------------------------------------------
// Active-set rule and summary
// ---------------------------------------------------------------------------

TEST(ActiveSetRule, ThresholdAtZeroAugmentedMultiplier) {
  // k lambda_n + eps g~ / D = 2 (-1.5) + 3 (1) / 1 = 0 exactly.
  EXPECT_EQ(augmentedNormalMultiplier(-1.5, 1.0, 1.0, 2.0, 3.0), 0.0);
  EXPECT_EQ(almContactState(-1.5, 1.0, 1.0, 2.0, 3.0), ContactState::Slip);
  EXPECT_EQ(almContactState(std::nextafter(-1.5, 0.0), 1.0, 1.0, 2.0, 3.0), ContactState::Inactive);
  EXPECT_EQ(almContactState(std::nextafter(-1.5, -2.0), 1.0, 1.0, 2.0, 3.0), ContactState::Slip);
  // D scales the gap: the same weighted gap on a larger weight is a smaller nodal gap.
  EXPECT_EQ(almContactState(-1.0, 1.0, 2.0, 1.0, 1.0), ContactState::Slip);    // -1 + 0.5 < 0
  EXPECT_EQ(almContactState(-1.0, 1.0, 0.5, 1.0, 1.0), ContactState::Inactive);  // -1 + 2 > 0
  EXPECT_THROW(almContactState(-1.0, 1.0, 0.0, 1.0, 1.0), coulomb::InternalError);
  // Penalty: threshold eps g~.
  EXPECT_EQ(penaltyContactState(0.0), ContactState::Slip);
  EXPECT_EQ(penaltyContactState(-1e-300), ContactState::Slip);
  EXPECT_EQ(penaltyContactState(1e-300), ContactState::Inactive);
  // Node-level wrapper uses n.lambda.
  const NVec<2> n = unitNormal<2>();
  AlmNodeInput<2> in{scaled<2>(n, -1.5), n, 1.0, 1.0};
  EXPECT_EQ(almState<2>(in, AlmParameters{2.0, 3.0, 1.0}), ContactState::Slip);
  in.lambda = scaled<2>(n, -1.4);
  EXPECT_EQ(almState<2>(in, AlmParameters{2.0, 3.0, 1.0}), ContactState::Inactive);
  EXPECT_EQ(static_cast<int>(ContactState::Inactive), 0);
  EXPECT_EQ(static_cast<int>(ContactState::Slip), 1);
}

// Slip Reset Frequency counts deck steps: the sub-steps of a cut (or
// knot-split) deck step all follow that step, and the pattern 1, 1 + n, ...
// does not shift (counting sub-steps, steps 2 and 3 below would reset).
TEST(ActiveSetRule, SlipResetCountsDeckSteps) {
  const int deckStepOfSubStep[] = {1, 1, 2, 3, 3, 3, 4, 5, 6, 7};
  std::string two, three, one;
  for (int step : deckStepOfSubStep) {
    one += resetsSlip(1, step) ? 'R' : '.';
    two += resetsSlip(2, step) ? 'R' : '.';
    three += resetsSlip(3, step) ? 'R' : '.';
  }
  EXPECT_EQ(one, "RRRRRRRRRR");
  EXPECT_EQ(two, "RR.RRR.R.R");
  EXPECT_EQ(three, "RR....R..R");
  for (int step = 1; step < 5; ++step) EXPECT_FALSE(resetsSlip(0, step));
}

TEST(ActiveSetSummary, CountsChangesPrintsAndCompares) {
  using S = ContactState;
  const std::vector<S> before{S::Slip, S::Inactive, S::Inactive, S::Slip};
  const std::vector<S> now{S::Slip, S::Slip, S::Inactive, S::Inactive};
  const ActiveSetSummary s = summarizeActiveSet(now, before);
  EXPECT_EQ(s.nodes, 4u);
  EXPECT_EQ(s.active, 2u);
  EXPECT_EQ(s.inactive, 2u);
  EXPECT_EQ(s.changed, 2u);
  EXPECT_FALSE(s.unchanged());
  std::ostringstream out;
  out << s << " " << S::Slip;
  EXPECT_EQ(out.str(), "nodes 4: active 2, inactive 2, changed 2 Slip");
  const ActiveSetSummary same = summarizeActiveSet(now, now);
  EXPECT_TRUE(same.unchanged());
  EXPECT_NE(same, s);
  EXPECT_EQ(summarizeActiveSet(now, {}), same);
  ActiveSetSummary sum = s;
  sum += same;
  EXPECT_EQ(sum.nodes, 8u);
  EXPECT_EQ(sum.changed, 2u);
  EXPECT_THROW(summarizeActiveSet(now, std::vector<S>{S::Slip}), coulomb::InternalError);
}

// ---------------------------------------------------------------------------
// Default penalty
// ---------------------------------------------------------------------------

TEST(NodalLawPenalty, DefaultPenaltyIsEOverH) {
  EXPECT_DOUBLE_EQ(defaultPenalty(210e9, 0.01), 210e11);
  EXPECT_DOUBLE_EQ(defaultPenalty(1.0, 0.5, 10.0), 20.0);
  EXPECT_THROW(defaultPenalty(0.0, 1.0), coulomb::InternalError);
  EXPECT_THROW(defaultPenalty(1.0, -1.0), coulomb::InternalError);
  EXPECT_THROW(defaultPenalty(1.0, 1.0, 0.0), coulomb::InternalError);
  EXPECT_THROW(almResidual<2>(AlmNodeInput<2>{{}, unitNormal<2>(), 0.0, 0.0}, AlmParameters{}, ContactState::Slip),
               coulomb::InternalError);
  EXPECT_THROW(almResidual<2>(AlmNodeInput<2>{{}, unitNormal<2>(), 0.0, 1.0}, AlmParameters{1.0, -1.0, 1.0},
                              ContactState::Slip),
               coulomb::InternalError);
}

}  // namespace
}  // namespace coulomb::contact
