// The NCP node kernel of the Lagrange multiplier method (NcpNode.hpp, seed
// 4.79): Sacado derivatives of r against central differences in every branch
// (2D, 3D; frictionless, Coulomb, Tresca); r = 0 exactly at states that satisfy
// the Coulomb conditions and r != 0 at states that violate them; the branch
// rule of ncpState (zone, stick/slip, hysteresis, frictionless -> Slip); the
// continuity of r across the stick/slip and the active/inactive switches; the
// augmented outputs; the preconditions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

#include "coulomb/contact/laws/NcpNode.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

constexpr double kD = 0.4, kMu = 0.3, kTresca = 1.3;

/// k, c_n, c_tau all different from 1 so that a missing factor shows.
NcpParameters parameters(FrictionLawType type) {
  NcpParameters p;
  p.k = 2.0;
  p.cN = 50.0;
  p.cTau = 5.0;
  p.law.type = type;
  p.law.coefficient = type == FrictionLawType::Coulomb ? kMu : 0.0;
  p.law.threshold = type == FrictionLawType::Tresca ? kTresca : 0.0;
  return p;
}

template <int dim>
std::array<double, dim> unit(std::array<double, dim> v) {
  double n = 0;
  for (double x : v) n += x * x;
  for (double& x : v) x /= std::sqrt(n);
  return v;
}

template <int dim>
double norm(const std::array<double, dim>& v) {
  double n = 0;
  for (double x : v) n += x * x;
  return std::sqrt(n);
}

/// A tilted normal n and tangents e1 (and e2 in 3D) orthonormal to it.
template <int dim>
struct Frame {
  std::array<double, dim> n{}, e1{}, e2{};
  Frame() {
    if constexpr (dim == 2) {
      n = unit<2>({0.3, -1.0});
      e1 = {-n[1], n[0]};
    } else {
      n = unit<3>({0.2, -0.1, -1.0});
      e1 = unit<3>({0.0, n[2], -n[1]});  // n x (1, 0, 0)
      e2 = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
    }
  }
  /// alpha e1 + beta e2 (beta is dropped in 2D).
  std::array<double, dim> tangent(double alpha, double beta) const {
    std::array<double, dim> v{};
    for (int c = 0; c < dim; ++c) v[c] = alpha * e1[c] + (dim == 3 ? beta * e2[c] : 0.0);
    return v;
  }
};

/// The node with pressure p = -k lambda_n, tangential traction t_tau, slip
/// rate w_tau / D = `slipPerD` (a length; w gets a normal part too, which the
/// rows must ignore) and nodal gap g = g~ / D.
template <int dim>
NcpNodeInput<dim> node(double pressure, const std::array<double, dim>& traction,
                       const std::array<double, dim>& slipPerD, double gap, const NcpParameters& p) {
  const Frame<dim> f;
  NcpNodeInput<dim> in;
  in.normal = f.n;
  in.D = kD;
  in.gap = gap * kD;
  for (int c = 0; c < dim; ++c) {
    in.lambda[c] = (-pressure * f.n[c] + traction[c]) / p.k;
    in.slip[c] = kD * (slipPerD[c] + 0.01 * f.n[c]);
  }
  return in;
}

/// Inputs well inside each branch, for Coulomb (Θ = 0.3 × 3.05 = 0.915) and
/// Tresca (Θ = 1.3): stick |a| = 0.36, slip |a| = 2.77, inactive lambdā_n = 0.7.
template <int dim>
NcpNodeInput<dim> inside(ContactState branch, const NcpParameters& p) {
  const Frame<dim> f;
  switch (branch) {
    case ContactState::Inactive:
      return node<dim>(0.3, f.tangent(0.2, 0.1), f.tangent(0.1, 0.05), 0.02, p);
    case ContactState::Stick:
      return node<dim>(3.0, f.tangent(0.3, -0.2), f.tangent(0.01, 0.02), -0.001, p);
    case ContactState::Slip:
      break;
  }
  return node<dim>(3.0, f.tangent(0.5, 0.3), f.tangent(0.4, -0.3), -0.001, p);
}

/// The largest |Sacado - central difference| over all checks.
double gMaxDerivativeError = 0.0;

template <int dim>
void checkDerivatives(const NcpNodeInput<dim>& base, ContactState state, const NcpParameters& p) {
  const auto exact = ncpRows<dim>(base, state, p);
  const double h = 1e-6;
  for (int i = 0; i < kNcpInputs<dim>; ++i) {
    auto perturbed = [&](double delta) {
      NcpNodeInput<dim> in = base;
      if (i < dim) in.lambda[i] += delta;
      else if (i < 2 * dim) in.normal[i - dim] += delta;  // n as a free input (the caller chains dn/du)
      else if (i < 3 * dim) in.slip[i - 2 * dim] += delta;
      else if (i == 3 * dim) in.D += delta;
      else in.gap += delta;
      EXPECT_EQ(ncpState<dim>(in, state, p), ncpState<dim>(base, state, p)) << "input " << i << " leaves the branch";
      return ncpRows<dim>(in, state, p);
    };
    const auto plus = perturbed(h), minus = perturbed(-h);
    for (int c = 0; c < dim; ++c) {
      const double fd = (plus.r[c] - minus.r[c]) / (2 * h);
      const double error = std::abs(exact.dr[c][i] - fd);
      gMaxDerivativeError = std::max(gMaxDerivativeError, error);
      EXPECT_NEAR(exact.dr[c][i], fd, 1e-7 * (1.0 + std::abs(fd)))
          << dim << "D " << toString(p.law.type) << " " << state << ": dr[" << c << "]/dinput[" << i << "]";
    }
  }
}

template <int dim>
void checkAllBranches() {
  for (auto type : {FrictionLawType::None, FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    for (auto branch : {ContactState::Inactive, ContactState::Stick, ContactState::Slip}) {
      const auto in = inside<dim>(branch, p);
      // The inputs lie in the branch they test (a frictionless active node slips).
      const auto expected = type == FrictionLawType::None && isActive(branch) ? ContactState::Slip : branch;
      ASSERT_EQ(ncpState<dim>(in, ContactState::Stick, p), expected) << toString(type) << " " << branch;
      checkDerivatives<dim>(in, expected, p);
    }
  }
}

template <int dim>
std::array<double, dim> rowsOf(const NcpNodeInput<dim>& in, ContactState previous, const NcpParameters& p) {
  return ncpRows<dim>(in, ncpState<dim>(in, previous, p), p).r;
}

TEST(NcpNode, DerivativesMatchCentralDifferencesInEveryBranch) {
  checkAllBranches<2>();
  checkAllBranches<3>();
  std::cout << "[ NcpNode  ] largest |Sacado - central difference| = " << gMaxDerivativeError << "\n";
}

template <int dim>
void checkRoots() {
  const Frame<dim> f;
  const auto e = unit<dim>(f.tangent(0.6, 0.8));
  const std::array<double, dim> zero{};
  for (auto type : {FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    const double pressure = 3.0, theta = type == FrictionLawType::Coulomb ? kMu * pressure : kTresca;
    std::array<double, dim> inCone{}, onCone{};
    for (int c = 0; c < dim; ++c) {
      inCone[c] = 0.5 * theta * e[c];
      onCone[c] = theta * e[c];
    }
    // Stick: w_tau = 0, |t_tau| < Θ, g = 0.
    const auto stick = node<dim>(pressure, inCone, zero, 0.0, p);
    EXPECT_EQ(ncpState<dim>(stick, ContactState::Stick, p), ContactState::Stick);
    for (double r : rowsOf<dim>(stick, ContactState::Stick, p)) EXPECT_NEAR(r, 0.0, 1e-13) << toString(type);
    // Slip: |t_tau| = Θ, t_tau along +w_tau, g = 0 (also from a previous slip).
    std::array<double, dim> along{};
    for (int c = 0; c < dim; ++c) along[c] = 0.05 * e[c];
    const auto slip = node<dim>(pressure, onCone, along, 0.0, p);
    for (auto previous : {ContactState::Stick, ContactState::Slip}) {
      EXPECT_EQ(ncpState<dim>(slip, previous, p), ContactState::Slip);
      for (double r : rowsOf<dim>(slip, previous, p)) EXPECT_NEAR(r, 0.0, 1e-13) << toString(type);
    }
  }
  for (auto type : {FrictionLawType::None, FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    // Inactive: lambda = 0, g > 0, whatever the slip.
    const auto open = node<dim>(0.0, zero, f.tangent(0.3, -0.2), 0.01, p);
    EXPECT_EQ(ncpState<dim>(open, ContactState::Slip, p), ContactState::Inactive);
    for (double r : rowsOf<dim>(open, ContactState::Slip, p)) EXPECT_NEAR(r, 0.0, 1e-14) << toString(type);
  }
  // Frictionless: pressure, no tangential traction, g = 0, whatever the slip.
  const auto p = parameters(FrictionLawType::None);
  const auto closed = node<dim>(3.0, zero, f.tangent(0.3, -0.2), 0.0, p);
  for (double r : rowsOf<dim>(closed, ContactState::Stick, p)) EXPECT_NEAR(r, 0.0, 1e-13);
}

template <int dim>
void checkViolations() {
  const Frame<dim> f;
  const auto e = unit<dim>(f.tangent(0.6, 0.8));
  auto scaled = [&](double s) {
    std::array<double, dim> v{};
    for (int c = 0; c < dim; ++c) v[c] = s * e[c];
    return v;
  };
  const std::array<double, dim> zero{};
  for (auto type : {FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    const double theta = type == FrictionLawType::Coulomb ? kMu * 3.0 : kTresca;
    for (auto previous : {ContactState::Stick, ContactState::Slip}) {
      // On the cone but against the slip: a large slip reaches the slip
      // branch (r = 2Θ e), a small one the stick branch (r = -c_tau w_tau / D).
      EXPECT_NEAR(norm<dim>(rowsOf<dim>(node<dim>(3.0, scaled(-theta), scaled(1.0), 0.0, p), previous, p)),
                  2.0 * theta, 1e-12)
          << toString(type);
      EXPECT_NEAR(norm<dim>(rowsOf<dim>(node<dim>(3.0, scaled(-theta), scaled(0.05), 0.0, p), previous, p)),
                  p.cTau * 0.05, 1e-12)
          << toString(type);
      // Outside the cone along the slip: r = Θ e.
      EXPECT_NEAR(norm<dim>(rowsOf<dim>(node<dim>(3.0, scaled(2 * theta), scaled(0.05), 0.0, p), previous, p)),
                  theta, 1e-12)
          << toString(type);
    }
    // Inside the cone while slipping: r = -c_tau w_tau / D (against the slip).
    const auto r = rowsOf<dim>(node<dim>(3.0, scaled(0.5 * theta), scaled(0.02), 0.0, p), ContactState::Stick, p);
    for (int c = 0; c < dim; ++c) EXPECT_NEAR(r[c], -p.cTau * 0.02 * e[c], 1e-13) << toString(type);
  }
  for (auto type : {FrictionLawType::None, FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    // Penetration with lambda = 0: active, r = c_n g n.
    const auto penetrating = node<dim>(0.0, zero, zero, -0.01, p);
    EXPECT_TRUE(isActive(ncpState<dim>(penetrating, ContactState::Inactive, p)));
    EXPECT_NEAR(norm<dim>(rowsOf<dim>(penetrating, ContactState::Inactive, p)), p.cN * 0.01, 1e-12);
    // Pressure across an open gap (p < c_n g): inactive, r = p n.
    EXPECT_NEAR(norm<dim>(rowsOf<dim>(node<dim>(0.3, zero, zero, 0.02, p), ContactState::Stick, p)), 0.3, 1e-13);
    // Tension in contact (g = 0, lambda_n > 0): inactive, r = p n.
    EXPECT_NEAR(norm<dim>(rowsOf<dim>(node<dim>(-0.4, zero, zero, 0.0, p), ContactState::Stick, p)), 0.4, 1e-13);
  }
  // Frictionless with a tangential traction: r = t_tau.
  const auto p = parameters(FrictionLawType::None);
  EXPECT_NEAR(norm<dim>(rowsOf<dim>(node<dim>(3.0, scaled(0.7), scaled(0.1), 0.0, p), ContactState::Stick, p)), 0.7,
              1e-13);
}

TEST(NcpNode, CoulombStatesAreRootsAndViolationsAreNot) {
  checkRoots<2>();
  checkRoots<3>();
  checkViolations<2>();
  checkViolations<3>();
}

template <int dim>
void checkStateRule() {
  const Frame<dim> f;
  const std::array<double, dim> zero{};
  auto p = parameters(FrictionLawType::Coulomb);
  p.slipThreshold = 0.02;
  const double pressure = 3.0, theta = kMu * pressure;
  auto at = [&](double fraction) { return node<dim>(pressure, f.tangent(fraction * theta, 0.0), zero, 0.0, p); };
  // |a| against Θ: stick inside, slip outside, whatever the previous state.
  for (auto previous : {ContactState::Inactive, ContactState::Stick, ContactState::Slip}) {
    EXPECT_EQ(ncpState<dim>(at(0.5), previous, p), ContactState::Stick);
    EXPECT_EQ(ncpState<dim>(at(1.5), previous, p), ContactState::Slip);
  }
  // The hysteresis: a slipping node keeps slipping down to (1 - 0.02) Θ.
  EXPECT_EQ(ncpState<dim>(at(0.99), ContactState::Slip, p), ContactState::Slip);
  EXPECT_EQ(ncpState<dim>(at(0.99), ContactState::Stick, p), ContactState::Stick);
  EXPECT_EQ(ncpState<dim>(at(0.99), ContactState::Inactive, p), ContactState::Stick);
  EXPECT_EQ(ncpState<dim>(at(0.97), ContactState::Slip, p), ContactState::Stick);
  // |a| includes c_tau w_tau / D: no traction, but a slip beyond Θ / c_tau.
  EXPECT_EQ(ncpState<dim>(node<dim>(pressure, zero, f.tangent(0.2, 0.0), 0.0, p), ContactState::Stick, p),
            ContactState::Slip);
  EXPECT_EQ(ncpState<dim>(node<dim>(pressure, zero, f.tangent(0.1, 0.0), 0.0, p), ContactState::Stick, p),
            ContactState::Stick);
  // The normal zone lambdā_n = -(p - c_n g) <= c_n × touching gap.
  EXPECT_EQ(ncpState<dim>(node<dim>(1.0, zero, zero, 0.019, p), ContactState::Slip, p), ContactState::Stick);
  EXPECT_EQ(ncpState<dim>(node<dim>(1.0, zero, zero, 0.021, p), ContactState::Slip, p), ContactState::Inactive);
  EXPECT_EQ(ncpState<dim>(node<dim>(-1.0, zero, zero, -0.019, p), ContactState::Slip, p), ContactState::Inactive);
  p.touchingGap = 0.002;  // lambdā_n = 0.05 <= c_n × 0.002 = 0.1: closed (Θ = 0 there)
  EXPECT_TRUE(isActive(ncpState<dim>(node<dim>(1.0, zero, zero, 0.021, p), ContactState::Slip, p)));
  EXPECT_EQ(ncpState<dim>(node<dim>(1.0, zero, zero, 0.023, p), ContactState::Slip, p), ContactState::Inactive);
  // Tresca: the threshold does not depend on the pressure.
  const auto tresca = parameters(FrictionLawType::Tresca);
  auto trescaAt = [&](double pN, double t) { return node<dim>(pN, f.tangent(t, 0.0), zero, 0.0, tresca); };
  EXPECT_EQ(ncpState<dim>(trescaAt(0.1, 1.2), ContactState::Stick, tresca), ContactState::Stick);
  EXPECT_EQ(ncpState<dim>(trescaAt(100.0, 1.4), ContactState::Stick, tresca), ContactState::Slip);
  // A frictionless law slips whenever active (also Coulomb with mu = 0), even
  // without tangential load and from a stick state.
  auto muZero = parameters(FrictionLawType::Coulomb);
  muZero.law.coefficient = 0.0;
  for (const auto& q : {parameters(FrictionLawType::None), muZero}) {
    for (auto previous : {ContactState::Inactive, ContactState::Stick, ContactState::Slip}) {
      EXPECT_EQ(ncpState<dim>(node<dim>(pressure, zero, zero, 0.0, q), previous, q), ContactState::Slip);
      EXPECT_EQ(ncpState<dim>(node<dim>(pressure, f.tangent(0.5, 0.2), zero, 0.0, q), previous, q),
                ContactState::Slip);
      EXPECT_EQ(ncpState<dim>(node<dim>(0.0, zero, zero, 0.01, q), previous, q), ContactState::Inactive);
      // a = 0 exactly (n on an axis): |a| <= Θ = 0 would be stick for a law with friction.
      NcpNodeInput<dim> exact;
      exact.normal[dim - 1] = 1.0;
      exact.lambda[dim - 1] = -1.5;
      exact.D = kD;
      EXPECT_EQ(ncpState<dim>(exact, previous, q), ContactState::Slip);
      EXPECT_EQ(ncpState<dim>(exact, previous, parameters(FrictionLawType::Coulomb)), ContactState::Stick);
    }
    // C_tau = t_tau whatever the state the caller keeps: a frozen Stick has the rows of Slip.
    const auto in = inside<dim>(ContactState::Stick, q);
    const auto stick = ncpRows<dim>(in, ContactState::Stick, q), slip = ncpRows<dim>(in, ContactState::Slip, q);
    for (int c = 0; c < dim; ++c) {
      EXPECT_EQ(stick.r[c], slip.r[c]);
      for (int i = 0; i < kNcpInputs<dim>; ++i) EXPECT_EQ(stick.dr[c][i], slip.dr[c][i]);
    }
  }
}

TEST(NcpNode, StateRuleZoneStickSlipHysteresisAndFrictionless) {
  checkStateRule<2>();
  checkStateRule<3>();
}

/// |r(+h side) - r(-h side)| with the branch of ncpState on each side.
template <int dim>
double jump(const NcpNodeInput<dim>& below, const NcpNodeInput<dim>& above, ContactState stateBelow,
            ContactState stateAbove, const NcpParameters& p) {
  EXPECT_EQ(ncpState<dim>(below, ContactState::Stick, p), stateBelow);
  EXPECT_EQ(ncpState<dim>(above, ContactState::Stick, p), stateAbove);
  const auto rBelow = rowsOf<dim>(below, ContactState::Stick, p), rAbove = rowsOf<dim>(above, ContactState::Stick, p);
  std::array<double, dim> d{};
  for (int c = 0; c < dim; ++c) d[c] = rAbove[c] - rBelow[c];
  return norm<dim>(d);
}

template <int dim>
void checkContinuity() {
  const Frame<dim> f;
  const double h = 1e-6;  // relative distance from the switch; a jump would be O(1)
  for (auto type : {FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    const double pressure = 3.0, gap = -0.001, theta = type == FrictionLawType::Coulomb ? kMu * 3.05 : kTresca;
    // Stick/slip: t_tau = sigma t0 with b = c_tau w_tau / D fixed (|b| < Θ);
    // |a| = |sigma t0 + b| = Θ at the positive root sigma*.
    const auto t0 = f.tangent(0.5, 0.3), slip = f.tangent(0.02, -0.04);
    double tt = 0, tb = 0, bb = 0;
    for (int c = 0; c < dim; ++c) {
      tt += t0[c] * t0[c];
      tb += t0[c] * p.cTau * slip[c];
      bb += p.cTau * slip[c] * p.cTau * slip[c];
    }
    const double sigma = (-tb + std::sqrt(tb * tb - tt * (bb - theta * theta))) / tt;
    auto at = [&](double s) {
      std::array<double, dim> t{};
      for (int c = 0; c < dim; ++c) t[c] = s * t0[c];
      return node<dim>(pressure, t, slip, gap, p);
    };
    // On the switch the two branches agree...
    const auto onSwitch = ncpRows<dim>(at(sigma), ContactState::Stick, p).r;
    const auto slipRows = ncpRows<dim>(at(sigma), ContactState::Slip, p).r;
    EXPECT_NEAR(norm<dim>(ncpRows<dim>(at(sigma), ContactState::Stick, p).augmentedTangent), theta, 1e-12);
    for (int c = 0; c < dim; ++c) EXPECT_NEAR(onSwitch[c], slipRows[c], 1e-13) << toString(type);
    // ... and r on both sides differs by O(h).
    EXPECT_LT(jump<dim>(at(sigma * (1 - h)), at(sigma * (1 + h)), ContactState::Stick, ContactState::Slip, p), 10 * h)
        << toString(type);
  }
  // Active/inactive at p - c_n g = 0: g = (p / c_n)(1 -+ h). Coulomb's Θ
  // vanishes there (slip, and stick with a = 0); Tresca's does not, it is
  // discontinuous there by its nature and not checked.
  const auto t = f.tangent(0.5, 0.3), w = f.tangent(0.1, -0.2);
  for (auto type : {FrictionLawType::None, FrictionLawType::Coulomb}) {
    const auto p = parameters(type);
    const double pressure = 3.0, g = pressure / p.cN;
    auto at = [&](double s, const std::array<double, dim>& traction) {
      return node<dim>(pressure, traction, w, g * s, p);
    };
    EXPECT_LT(jump<dim>(at(1 - h, t), at(1 + h, t), ContactState::Slip, ContactState::Inactive, p), 10 * h) << toString(type);
    if (type == FrictionLawType::Coulomb) {
      std::array<double, dim> sticking{};  // a = t_tau + c_tau w_tau / D = 0
      for (int c = 0; c < dim; ++c) sticking[c] = -p.cTau * w[c];
      EXPECT_LT(jump<dim>(at(1 - h, sticking), at(1 + h, sticking), ContactState::Stick, ContactState::Inactive, p),
                10 * h);
    }
  }
}

TEST(NcpNode, ContinuousAcrossStickSlipAndActiveInactive) {
  checkContinuity<2>();
  checkContinuity<3>();
}

template <int dim>
void checkAugmentedOutputs() {
  for (auto type : {FrictionLawType::None, FrictionLawType::Coulomb, FrictionLawType::Tresca}) {
    const auto p = parameters(type);
    for (auto branch : {ContactState::Inactive, ContactState::Stick, ContactState::Slip}) {
      auto in = inside<dim>(branch, p);
      in.normal[0] += 0.05;  // the outputs are the formulas for the n given (no normalisation)
      double lambdaN = 0, wN = 0;
      for (int c = 0; c < dim; ++c) {
        lambdaN += in.lambda[c] * in.normal[c];
        wN += in.slip[c] * in.normal[c];
      }
      const auto rows = ncpRows<dim>(in, branch, p);
      EXPECT_NEAR(rows.augmentedNormal, p.k * lambdaN + p.cN * in.gap / in.D, 1e-13);
      for (int c = 0; c < dim; ++c) {
        const double a =
            p.k * (in.lambda[c] - lambdaN * in.normal[c]) + p.cTau * (in.slip[c] - wN * in.normal[c]) / in.D;
        EXPECT_NEAR(rows.augmentedTangent[c], a, 1e-13) << toString(type) << " " << branch;
      }
    }
  }
}

TEST(NcpNode, AugmentedOutputsAreTheirDefinitions) {
  checkAugmentedOutputs<2>();
  checkAugmentedOutputs<3>();
}

TEST(NcpNode, FrozenSlipWithoutDirectionCarriesNoFriction) {
  // A Slip state kept by the caller (no set update) at a = 0 exactly (binary
  // fractions, n on an axis): no direction, C_tau = t_tau, finite derivatives.
  const auto p = parameters(FrictionLawType::Coulomb);  // k = 2, c_tau = 5
  NcpNodeInput<3> in;
  in.normal = {0.0, 0.0, 1.0};
  in.D = 0.5;
  in.slip = {0.25, -0.5, 0.125};   // c_tau w_tau / D = (2.5, -5, 0)
  in.lambda = {-1.25, 2.5, -1.5};  // t_tau = (-2.5, 5, 0): a = 0; g~ = 0
  const auto rows = ncpRows<3>(in, ContactState::Slip, p);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(rows.augmentedTangent[c], 0.0);
  EXPECT_DOUBLE_EQ(rows.r[0], -2.5);
  EXPECT_DOUBLE_EQ(rows.r[1], 5.0);
  EXPECT_DOUBLE_EQ(rows.r[2], 0.0);  // active, g = 0: C_n = c_n g = 0
  for (int c = 0; c < 3; ++c)
    for (double d : rows.dr[c]) EXPECT_TRUE(std::isfinite(d));
}

TEST(NcpNode, RejectsNonPositiveWeightAndParameters) {
  const auto p = parameters(FrictionLawType::Coulomb);
  for (double D : {0.0, -0.4}) {
    auto in2 = inside<2>(ContactState::Stick, p);
    auto in3 = inside<3>(ContactState::Slip, p);
    in2.D = in3.D = D;
    EXPECT_THROW(ncpState<2>(in2, ContactState::Stick, p), InternalError);
    EXPECT_THROW(ncpRows<2>(in2, ContactState::Stick, p), InternalError);
    EXPECT_THROW(ncpState<3>(in3, ContactState::Slip, p), InternalError);
    EXPECT_THROW(ncpRows<3>(in3, ContactState::Slip, p), InternalError);
  }
  const auto in = inside<3>(ContactState::Stick, p);
  for (int which = 0; which < 3; ++which) {
    auto q = p;
    (which == 0 ? q.k : which == 1 ? q.cN : q.cTau) = 0.0;
    EXPECT_THROW(ncpState<3>(in, ContactState::Stick, q), InternalError);
    EXPECT_THROW(ncpRows<3>(in, ContactState::Stick, q), InternalError);
  }
  EXPECT_NO_THROW(ncpRows<3>(in, ContactState::Stick, p));
}

}  // namespace
}  // namespace coulomb::contact
