/// Unit tests of the frictional kernels: the friction laws (FrictionLaw.hpp),
/// the stick/slip rule with hysteresis (ActiveSet.hpp) and the condensed
/// rows of a frictional node with their Sacado derivatives (FrictionalNode.hpp),
/// checked against central differences and against constructed solutions.
#include <gtest/gtest.h>

#include <cmath>

#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/contact/laws/FrictionalNode.hpp"
#include "coulomb/core/Error.hpp"

using namespace coulomb::contact;

namespace {

FrictionalParameters coulombParameters(double mu) {
  FrictionalParameters p;
  p.k = 2.0;
  p.epsN = 50.0;
  p.epsTau = 5.0;
  p.thickness = 1.5;
  p.slipAugmentation = 0.7;
  p.law.type = FrictionLawType::Coulomb;
  p.law.coefficient = mu;
  return p;
}

template <int dim>
std::array<double, dim> unit(std::array<double, dim> v) {
  double n = 0;
  for (double x : v) n += x * x;
  for (double& x : v) x /= std::sqrt(n);
  return v;
}

/// A generic node: tilted normal, residual with normal and tangential parts.
template <int dim>
FrictionalNodeInput<dim> genericNode() {
  FrictionalNodeInput<dim> in;
  if constexpr (dim == 2) {
    in.normal = unit<2>({0.3, -1.0});
    in.residual = {0.8, 2.1};
    in.slip = {0.05, -0.02};
  } else {
    in.normal = unit<3>({0.2, -0.1, -1.0});
    in.residual = {0.8, -0.4, 2.1};
    in.slip = {0.05, 0.03, -0.02};
  }
  in.D = 0.4;
  in.gap = -0.01;
  return in;
}

/// Central differences of rows and lambda with respect to input i.
template <int dim>
void checkDerivatives(const FrictionalNodeInput<dim>& base, ContactState state, const FrictionalParameters& p) {
  const auto exact = frictionalRows<dim>(base, state, p);
  ASSERT_TRUE(exact.usable);
  const double h = 1e-6;
  for (int i = 0; i < kFrictionalInputs<dim>; ++i) {
    auto perturbed = [&](double delta) {
      FrictionalNodeInput<dim> in = base;
      if (i < dim) in.residual[i] += delta;
      else if (i < 2 * dim) in.normal[i - dim] += delta;  // n as a free input (the caller chains dn/du)
      else if (i < 3 * dim) in.slip[i - 2 * dim] += delta;
      else if (i == 3 * dim) in.D += delta;
      else in.gap += delta;
      return frictionalRows<dim>(in, state, p);
    };
    const auto plus = perturbed(h), minus = perturbed(-h);
    for (int c = 0; c < dim; ++c) {
      const double fdRow = (plus.rows[c] - minus.rows[c]) / (2 * h);
      const double fdLambda = (plus.lambda[c] - minus.lambda[c]) / (2 * h);
      const double scaleRow = 1.0 + std::abs(exact.dRows[c][i]);
      const double scaleLambda = 1.0 + std::abs(exact.dLambda[c][i]);
      EXPECT_NEAR(exact.dRows[c][i], fdRow, 1e-6 * scaleRow) << "row " << c << " input " << i;
      EXPECT_NEAR(exact.dLambda[c][i], fdLambda, 1e-6 * scaleLambda) << "lambda " << c << " input " << i;
    }
  }
}

}  // namespace

// The penalty return map (penaltyFrictionalForce), with friction and, as the
// frictionless penalty runs it, with no law on the slip branch: the force on
// the slave is t D (t_tau - p n) with p = eps_n <-g~> / D, continuous (zero)
// at g~ = 0, no tangential part without a law; derivatives against central
// differences in every input (n, w, D, g~).
template <int dim>
void checkPenaltyForce(const FrictionalParameters& p, ContactState state) {
  const auto node = genericNode<dim>();
  PenaltyFrictionalInput<dim> base;
  base.normal = node.normal;
  base.slip = node.slip;
  base.D = node.D;
  base.gap = node.gap;
  for (int c = 0; c < dim; ++c) base.oldTraction[c] = 0.1 * (c + 1);
  const auto exact = penaltyFrictionalForce<dim>(base, state, p);
  EXPECT_NEAR(exact.pressure, p.epsN * 0.01 / node.D, 1e-12);
  double along = 0;
  for (int c = 0; c < dim; ++c) along += exact.force[c] * node.normal[c];
  EXPECT_NEAR(along, -p.thickness * node.D * exact.pressure, 1e-12);
  if (p.law.type == FrictionLawType::None)
    for (int c = 0; c < dim; ++c) EXPECT_NEAR(exact.force[c], along * node.normal[c], 1e-14);
  const double h = 1e-7;
  for (int i = 0; i < kPenaltyFrictionalInputs<dim>; ++i) {
    auto perturbed = [&](double delta) {
      PenaltyFrictionalInput<dim> in = base;
      if (i < dim) in.normal[i] += delta;
      else if (i < 2 * dim) in.slip[i - dim] += delta;
      else if (i == 2 * dim) in.D += delta;
      else in.gap += delta;
      return penaltyFrictionalForce<dim>(in, state, p);
    };
    const auto plus = perturbed(h), minus = perturbed(-h);
    for (int c = 0; c < dim; ++c)
      EXPECT_NEAR(exact.dForce[c][i], (plus.force[c] - minus.force[c]) / (2 * h), 1e-6 * (1 + std::abs(exact.dForce[c][i])))
          << "force " << c << " input " << i;
  }
  for (double gap : {-1e-12, 0.0, 1e-12}) {
    base.gap = gap;
    const auto f = penaltyFrictionalForce<dim>(base, ContactState::Slip, p);
    double largest = 0;
    for (int c = 0; c < dim; ++c) largest = std::max(largest, std::abs(f.force[c]));
    EXPECT_LE(largest, p.epsN * 1e-11) << "gap " << gap;  // no pressure, no friction threshold
  }
}

TEST(PenaltyFrictionalForce, ReturnMapDerivativesMatchCentralDifferences) {
  FrictionalParameters frictionless = coulombParameters(0.0);
  frictionless.law = FrictionLaw{};
  frictionless.pureSlip = true;
  checkPenaltyForce<2>(frictionless, ContactState::Slip);
  checkPenaltyForce<3>(frictionless, ContactState::Slip);
  checkPenaltyForce<2>(coulombParameters(0.3), ContactState::Slip);
  checkPenaltyForce<3>(coulombParameters(0.3), ContactState::Slip);
  checkPenaltyForce<2>(coulombParameters(0.3), ContactState::Stick);
  checkPenaltyForce<3>(coulombParameters(0.3), ContactState::Stick);
  PenaltyFrictionalInput<2> open;
  open.normal = {0.0, -1.0};
  open.D = 0.4;
  open.gap = 1e-3;
  EXPECT_EQ(penaltyFrictionalState<2>(open, ContactState::Slip, frictionless), ContactState::Inactive);
  open.gap = 0.0;  // touching counts as closed, on the slip branch without a law
  EXPECT_EQ(penaltyFrictionalState<2>(open, ContactState::Inactive, frictionless), ContactState::Slip);
}

TEST(FrictionLaw, CoulombTrescaNone) {
  FrictionLaw coulomb{FrictionLawType::Coulomb, 0.3, 0.0};
  EXPECT_DOUBLE_EQ(frictionThreshold(coulomb, -10.0), 3.0);  // mu <-lambdā_n>
  EXPECT_DOUBLE_EQ(frictionThreshold(coulomb, 2.0), 0.0);    // open: no friction
  FrictionLaw tresca{FrictionLawType::Tresca, 0.0, 7.0};
  EXPECT_DOUBLE_EQ(frictionThreshold(tresca, -10.0), 7.0);  // independent of the pressure
  EXPECT_DOUBLE_EQ(frictionThreshold(tresca, -1000.0), 7.0);
  EXPECT_DOUBLE_EQ(frictionThreshold(FrictionLaw{}, -10.0), 0.0);
  EXPECT_TRUE(FrictionLaw{}.frictionless());
  EXPECT_TRUE((FrictionLaw{FrictionLawType::Coulomb, 0.0, 0.0}.frictionless()));
  EXPECT_FALSE(coulomb.frictionless());
  EXPECT_FALSE(tresca.frictionless());
  EXPECT_STREQ(toString(FrictionLawType::Tresca), "Tresca");
}

TEST(FrictionLaw, StickSlipRuleWithHysteresis) {
  const double threshold = 10.0, hysteresis = 0.02;
  EXPECT_EQ(stickSlipState(9.9, threshold, ContactState::Stick, hysteresis), ContactState::Stick);
  EXPECT_EQ(stickSlipState(10.1, threshold, ContactState::Stick, hysteresis), ContactState::Slip);
  EXPECT_EQ(stickSlipState(9.9, threshold, ContactState::Inactive, hysteresis), ContactState::Stick);
  // A slipping node keeps slipping down to (1 - 0.02) x 10 = 9.8.
  EXPECT_EQ(stickSlipState(9.9, threshold, ContactState::Slip, hysteresis), ContactState::Slip);
  EXPECT_EQ(stickSlipState(9.7, threshold, ContactState::Slip, hysteresis), ContactState::Stick);
  // Zero threshold (no pressure yet): any tangential load slips, none sticks.
  EXPECT_EQ(stickSlipState(1e-12, 0.0, ContactState::Stick, hysteresis), ContactState::Slip);
  EXPECT_EQ(stickSlipState(0.0, 0.0, ContactState::Stick, hysteresis), ContactState::Stick);
  EXPECT_TRUE(isActive(ContactState::Stick));
  EXPECT_TRUE(isActive(ContactState::Slip));
  EXPECT_FALSE(isActive(ContactState::Inactive));
  EXPECT_EQ(static_cast<int>(ContactState::Stick), 2);
}

TEST(FrictionalNode, DerivativesMatchCentralDifferences) {
  const auto p = coulombParameters(0.3);
  for (ContactState state : {ContactState::Stick, ContactState::Slip}) {
    checkDerivatives<2>(genericNode<2>(), state, p);
    checkDerivatives<3>(genericNode<3>(), state, p);
    // A node on a symmetry plane (u_y prescribed), as in the sliding punch.
    auto onPlane = genericNode<3>();
    onPlane.prescribed = {false, true, false};
    checkDerivatives<3>(onPlane, state, p);
  }
  auto tresca = p;
  tresca.law = FrictionLaw{FrictionLawType::Tresca, 0.0, 1.3};
  checkDerivatives<3>(genericNode<3>(), ContactState::Slip, tresca);
}

TEST(FrictionalNode, RecoversTheMultiplierFromTheResidual) {
  const auto p = coulombParameters(0.3);
  auto in = genericNode<3>();
  const std::array<double, 3> lambda{0.4, -0.3, 1.1};
  for (int c = 0; c < 3; ++c) in.residual[c] = p.k * p.thickness * in.D * lambda[c];
  const auto rows = frictionalRows<3>(in, ContactState::Stick, p);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rows.lambda[c], lambda[c], 1e-14);
  const auto state = frictionalState<3>(in, ContactState::Stick, p);
  double ln = 0;
  for (int c = 0; c < 3; ++c) ln += lambda[c] * in.normal[c];
  EXPECT_NEAR(state.lambdaN, ln, 1e-14);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(state.traction[c], p.k * lambda[c], 1e-14);
  // Not previously active: nothing is recovered.
  const auto fresh = frictionalState<3>(in, ContactState::Inactive, p);
  EXPECT_EQ(fresh.lambdaN, 0.0);
}

/// A node at a slip solution of the Coulomb law: closed (g~ = 0), traction
/// on the cone along the weighted slip. Its rows vanish; so do those of a
/// stick solution (w = 0).
TEST(FrictionalNode, RowsVanishAtSolutions) {
  const auto p = coulombParameters(0.4);
  FrictionalNodeInput<3> in;
  in.normal = unit<3>({0.1, 0.2, -1.0});
  in.D = 0.3;
  in.gap = 0.0;
  // Tangent t ⟂ n, pressure 5: traction = -5 n + 0.4 × 5 t on the slave.
  std::array<double, 3> t = {1.0, 0.0, 0.0};
  double tn = 0;
  for (int c = 0; c < 3; ++c) tn += t[c] * in.normal[c];
  for (int c = 0; c < 3; ++c) t[c] -= tn * in.normal[c];
  t = unit<3>(t);
  const double pressure = 5.0;
  for (int c = 0; c < 3; ++c) {
    const double traction = -pressure * in.normal[c] + 0.4 * pressure * t[c];
    in.residual[c] = p.thickness * in.D * traction;  // k t D lambda = t D × traction
    in.slip[c] = 0.02 * t[c];                        // the master moves along t relative to the slave
  }
  const auto slip = frictionalRows<3>(in, ContactState::Slip, p);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(slip.rows[c], 0.0, 1e-12) << c;
  const auto decided = frictionalState<3>(in, ContactState::Slip, p);
  EXPECT_EQ(decided.state, ContactState::Slip);
  EXPECT_NEAR(decided.threshold, 0.4 * pressure, 1e-12);
  // Slip against the traction is not a solution: the rule sends the node to
  // stick (|lambdā_tau| = 2 - alpha eps_tau 0.02 / D < Θ = 2), whose rows
  // then ask for zero slip.
  auto wrong = in;
  for (int c = 0; c < 3; ++c) wrong.slip[c] = -in.slip[c];
  EXPECT_EQ(frictionalState<3>(wrong, ContactState::Slip, p).state, ContactState::Stick);
  const auto wrongRows = frictionalRows<3>(wrong, ContactState::Stick, p);
  double norm = 0;
  for (double r : wrongRows.rows) norm += r * r;
  EXPECT_NEAR(std::sqrt(norm), p.epsN * p.thickness * 0.02, 1e-12);
  // Stick: no slip, traction inside the cone.
  auto stick = in;
  stick.slip = {};
  for (int c = 0; c < 3; ++c) stick.residual[c] = p.thickness * in.D * (-pressure * in.normal[c] + 0.1 * t[c]);
  const auto stickRows = frictionalRows<3>(stick, ContactState::Stick, p);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(stickRows.rows[c], 0.0, 1e-12) << c;
  EXPECT_EQ(frictionalState<3>(stick, ContactState::Stick, p).state, ContactState::Stick);
  // Open node: inactive whatever the tangential load.
  auto open = in;
  open.gap = 1.0;
  open.residual = {};
  EXPECT_EQ(frictionalState<3>(open, ContactState::Inactive, p).state, ContactState::Inactive);
}

// MPC decides by reactions and gaps, without the penalty augmentation:
// where the two rules disagree on the way to a solution, each does what it
// says (and at solutions both agree, RowsVanishAtSolutions above).
TEST(FrictionalNode, MultiPointConstraintStatesComeFromReactionsAndGaps) {
  // (The normal rule of MPC: contact_frictionless_node.cpp, TensionOpensAnActiveNode.)
  EXPECT_EQ(almContactState(0.5, -1.0, 1.0, 1.0, 10.0), ContactState::Slip);  // eps_n g~ / D wins

  auto alm = coulombParameters(0.4), mpc = alm;
  mpc.multiPointConstraint = true;
  FrictionalNodeInput<3> in;
  in.normal = {0.0, 0.0, -1.0};
  in.D = 0.5;
  // Pressure 5 (k lambda_n = -5), tangential reaction 1 < mu p = 2, but a
  // large slip of the iterate: ALM's augmented test (k beta + eps_tau w / D)
  // slips, MPC's reaction test sticks.
  const double ktD = alm.k * alm.thickness * in.D;
  in.residual = {ktD * 1.0 / alm.k, 0.0, ktD * 5.0 / alm.k};
  in.slip = {0.5, 0.0, 0.0};
  in.gap = 0.0;
  EXPECT_EQ(frictionalState<3>(in, ContactState::Stick, alm).state, ContactState::Slip);  // |1 + 5 × 0.5 / 0.5| > 2
  EXPECT_EQ(frictionalState<3>(in, ContactState::Stick, mpc).state, ContactState::Stick);  // |1| < 2
  // Penetrating: ALM's threshold from lambdā_n = -5 - 50 × 0.2 / 0.5, MPC's from the reaction.
  in.gap = -0.2;
  EXPECT_NEAR(frictionalState<3>(in, ContactState::Stick, alm).threshold, 0.4 * 25.0, 1e-12);
  EXPECT_NEAR(frictionalState<3>(in, ContactState::Stick, mpc).threshold, 0.4 * 5.0, 1e-12);
  // A tangential reaction above mu p slips under MPC too.
  in.residual[0] = ktD * 2.5 / alm.k;
  in.slip = {};
  EXPECT_EQ(frictionalState<3>(in, ContactState::Stick, mpc).state, ContactState::Slip);
  // The slip rows carry the Coulomb force of the reaction: zero at a slip
  // solution (traction mu p along the slip), and their derivatives are exact.
  in.residual = {ktD * 2.0 / alm.k, 0.0, ktD * 5.0 / alm.k};
  in.slip = {0.01, 0.0, 0.0};
  in.gap = 0.0;
  const auto rows = frictionalRows<3>(in, ContactState::Slip, mpc);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(rows.rows[c], 0.0, 1e-12) << c;
  checkDerivatives<3>(genericNode<3>(), ContactState::Slip, mpc);
  checkDerivatives<2>(genericNode<2>(), ContactState::Slip, mpc);
}

namespace {
/// A node on the plane z = 0 (n = -z, D = 0.5) whose recovered traction is
/// (tx, ty) tangential and pressure 5, slipping by `slip` at this iterate;
/// tD = t D of p.
FrictionalNodeInput<3> pressedNode(const FrictionalParameters& p, double tx, double ty,
                                   const std::array<double, 3>& slip, double& tD) {
  FrictionalNodeInput<3> in;
  in.normal = {0.0, 0.0, -1.0};
  in.D = 0.5;
  tD = p.thickness * in.D;
  in.residual = {tD * tx, tD * ty, tD * 5.0};
  in.slip = slip;
  return in;
}
}  // namespace

// Slip Reset Frequency < 0: the slip rows take the direction of the node's
// slip in the last converged step (fixed for the step), not the augmented
// multiplier's; exact derivatives (through the frame, i.e. n).
TEST(FrictionalNode, SlipDirectionFromTheSlip) {
  auto p = coulombParameters(0.4);
  p.slipDirectionFromSlip = true;
  double tD = 0;
  // Traction (1, 1.5) tangential; this iterate's slip along x is not the direction.
  auto in = pressedNode(p, 1.0, 1.5, {0.02, 0.0, 0.0}, tD);
  in.lastSlip = {0.0, 0.03, 0.0};  // the last step slipped along +y
  const auto rows = frictionalRows<3>(in, ContactState::Slip, p);
  // Frame of n = -z: the gap slot is z; the tangent slots x and y carry
  // b.r_F - t D Θ d with d = (0, 1): (tD 1, tD (1.5 - 2)).
  EXPECT_NEAR(std::abs(rows.rows[0]), tD * 1.0, 1e-12);
  EXPECT_NEAR(std::abs(rows.rows[1]), tD * 0.5, 1e-12);
  p.slipDirectionFromSlip = false;  // the augmented direction mixes in the traction's x part
  EXPECT_GT(std::abs(std::abs(frictionalRows<3>(in, ContactState::Slip, p).rows[0]) - tD), 0.1 * tD);
  p.slipDirectionFromSlip = true;
  auto node3 = genericNode<3>();
  node3.lastSlip = {0.02, -0.01, 0.005};
  checkDerivatives<3>(node3, ContactState::Slip, p);
  auto node2 = genericNode<2>();
  node2.lastSlip = {-0.02, 0.01};
  checkDerivatives<2>(node2, ContactState::Slip, p);
}

// Pure slip (the seed's FrictionalPureSlip): the slip rows take the
// direction of this iterate's weighted slip (not the augmented multiplier's),
// with its derivatives; a node below the cone slips all the same.
TEST(FrictionalNode, PureSlipFollowsTheSlip) {
  auto p = coulombParameters(0.4);
  p.pureSlip = true;
  double tD = 0;
  // Traction (0.1, 1.5) tangential: inside the cone (Θ = μ 5 = 2); slipping along x.
  const auto in = pressedNode(p, 0.1, 1.5, {0.02, 0.0, 0.0}, tD);
  EXPECT_EQ(frictionalState<3>(in, ContactState::Stick, p).state, ContactState::Slip);
  EXPECT_EQ(frictionalState<3>(in, ContactState::Slip, p).state, ContactState::Slip);
  // Tangent slots x and y: b.r_F - t D Θ d with d = (±1, 0), Θ = μ p = 2: (tD (0.1 ∓ 2), tD 1.5).
  const auto rows = frictionalRows<3>(in, ContactState::Slip, p);
  EXPECT_NEAR(std::abs(rows.rows[0]), tD * 1.9, 1e-12);
  EXPECT_NEAR(std::abs(rows.rows[1]), tD * 1.5, 1e-12);
  p.pureSlip = false;  // the stick/slip rule: inside the cone, stick
  EXPECT_EQ(frictionalState<3>(in, ContactState::Stick, p).state, ContactState::Stick);
  p.pureSlip = true;
  checkDerivatives<3>(genericNode<3>(), ContactState::Slip, p);
  checkDerivatives<2>(genericNode<2>(), ContactState::Slip, p);
}

// The stick and slip groups of (4.78) and the tangential/normal ratio.
TEST(FrictionConvergence, TangentialGroupsAndRatio) {
  ContactSettings s;
  s.stickRelativeTolerance = s.slipRelativeTolerance = 1e-6;
  s.stickAbsoluteTolerance = s.slipAbsoluteTolerance = 1e-8;
  s.tangentNormalRatio = 1e-4;
  ContactIterationSummary summary;
  summary.contactForce = 1000.0;
  ASSERT_EQ(summary.criteria(s).size(), 1u);  // no tangential force: the normal group alone
  EXPECT_STREQ(summary.criteria(s)[0].name, "normal contact rows");
  summary.tangentialForce = 300.0;
  summary.stickResidual = 5e-3;  // > 1e-6 × 1000 + 1e-8
  EXPECT_FALSE(summary.criteriaMet(s));
  summary.stickResidual = 5e-7;
  summary.slipResidual = 2e-3;
  EXPECT_FALSE(summary.criteriaMet(s));
  summary.slipResidual = 0.9e-3;
  EXPECT_TRUE(summary.criteriaMet(s));
  // Negligible tangential forces: the groups are not asked.
  summary.slipResidual = 1.0;
  summary.tangentialForce = 0.09;
  EXPECT_TRUE(summary.criteriaMet(s));
  summary.tangentialForce = 0.11;
  EXPECT_FALSE(summary.criteriaMet(s));
}

TEST(FrictionalNode, RejectsBadInput) {
  auto p = coulombParameters(0.3);
  auto in = genericNode<2>();
  in.D = 0.0;
  EXPECT_THROW(frictionalRows<2>(in, ContactState::Slip, p), coulomb::InternalError);
  in = genericNode<2>();
  p.slipAugmentation = 0.0;
  EXPECT_THROW(frictionalState<2>(in, ContactState::Slip, p), coulomb::InternalError);
  EXPECT_THROW(frictionalRows<2>(in, ContactState::Inactive, coulombParameters(0.3)), coulomb::InternalError);
}

// A slipping node whose iterate slid against the direction its slip rows
// gave it, by more than the hysteresis: the rule (4.75) alone would slip it
// the other way (and the next iterate back: the 2-cycle of
// tests/zoo/sharp_punch_2d); it sticks instead (FrictionalNode.cpp,
// slipReversed). Slipping on along the direction, or without a direction
// to compare with, is (4.75) unchanged.
TEST(FrictionalNode, SlipAgainstItsDirectionSticks) {
  const auto p = coulombParameters(0.3);  // k 2, eps_tau 5, t 1.5, alpha 0.7
  FrictionalNodeInput<2> in;
  in.normal = {0.0, -1.0};
  in.D = 0.5;
  in.gap = 0.0;
  // Pressure 10 (Θ = 3), traction -3 along x on the slave: the slip rows' d = -x.
  const double tD = p.thickness * in.D;
  in.residual = {tD * -3.0, tD * 10.0};
  in.previousDirection = {-1.0, 0.0};
  in.slip = {2.0, 0.0};  // lambdā_tau = -3 + 0.7 × 5 × 2 / 0.5 = 11 > 0.98 Θ, against d
  const auto reversed = frictionalState<2>(in, ContactState::Slip, p);
  EXPECT_NEAR(reversed.threshold, 3.0, 1e-12);
  EXPECT_NEAR(reversed.tangentNorm, 11.0, 1e-12);
  EXPECT_EQ(reversed.state, ContactState::Stick);
  auto along = in;  // slid along d: lambdā_tau = -3 - 14
  along.slip = {-2.0, 0.0};
  EXPECT_EQ(frictionalState<2>(along, ContactState::Slip, p).state, ContactState::Slip);
  auto unknown = in;  // no direction of the last iterate: the rule alone
  unknown.previousDirection = {};
  EXPECT_EQ(frictionalState<2>(unknown, ContactState::Slip, p).state, ContactState::Slip);
  // A sticking node with the same values slips (|lambdā_tau| = |-3 + 5 × 2 / 0.5| = 17 > Θ).
  EXPECT_EQ(frictionalState<2>(in, ContactState::Stick, p).state, ContactState::Slip);
  // A direction fixed for the step (Slip Reset Frequency < 0: the last
  // step's slip) does not flip with lambdā_tau: the rule (4.75) alone; with
  // no last slip the direction is lambdā_tau's again.
  auto fixedDirection = p;
  fixedDirection.slipDirectionFromSlip = true;
  auto lastStep = in;
  lastStep.lastSlip = {-0.01, 0.0};
  EXPECT_EQ(frictionalState<2>(lastStep, ContactState::Slip, fixedDirection).state, ContactState::Slip);
  lastStep.lastSlip = {};
  EXPECT_EQ(frictionalState<2>(lastStep, ContactState::Slip, fixedDirection).state, ContactState::Stick);
  // The direction the slip rows use, the unit lambdā_tau (world components).
  const auto rows = frictionalRows<2>(along, ContactState::Slip, p);
  EXPECT_NEAR(rows.direction[0], -1.0, 1e-14);
  EXPECT_NEAR(rows.direction[1], 0.0, 1e-14);
  EXPECT_EQ(frictionalRows<2>(along, ContactState::Stick, p).direction[0], 0.0);

  // 3D: lambdā_tau turned by more than 90 degrees from d sticks, by less slips on.
  FrictionalNodeInput<3> node;
  node.normal = {0.0, 0.0, -1.0};
  node.D = 0.5;
  node.residual = {tD * -3.0, 0.0, tD * 10.0};
  node.previousDirection = {-1.0, 0.0, 0.0};
  const double c120 = std::cos(2.0944), s120 = std::sin(2.0944), c60 = 0.5, s60 = std::sqrt(0.75);
  const double length = 3.0;  // alpha eps_tau |w| / D = 7 |w|: |w| = 3 dominates the -3 of k beta
  node.slip = {-length * c120, length * s120, 0.0};  // 120 degrees from d = -x
  EXPECT_EQ(frictionalState<3>(node, ContactState::Slip, p).state, ContactState::Stick);
  node.slip = {-length * c60, length * s60, 0.0};  // 60 degrees
  EXPECT_EQ(frictionalState<3>(node, ContactState::Slip, p).state, ContactState::Slip);
}

// A slipping node that slid against its slip direction d by a little: the
// slip augmentation takes less than the hysteresis (2 %) off |lambdā_tau|, so
// the rule alone keeps it slipping, and its slip rows would converge with the
// friction force along the slip (negative dissipation). It sticks; a slip
// against d at the round-off of w does not change the state.
TEST(FrictionalNode, SlightSlipAgainstItsDirectionSticks) {
  const auto p = coulombParameters(0.3);  // k 2, eps_tau 5, t 1.5, alpha 0.7
  FrictionalNodeInput<2> in;
  in.normal = {0.0, -1.0};
  in.D = 0.5;
  const double tD = p.thickness * in.D;
  in.residual = {tD * -3.0, tD * 10.0};  // Θ = 3, k beta = -3: d = -x
  in.previousDirection = {-1.0, 0.0};
  in.slip = {0.005, 0.0};  // lambdā_tau = -3 + 0.7 × 5 × 0.005 / 0.5 = -2.965, |.| > 0.98 Θ = 2.94
  const auto slight = frictionalState<2>(in, ContactState::Slip, p);
  EXPECT_NEAR(slight.tangentNorm, 2.965, 1e-12);
  EXPECT_EQ(slight.state, ContactState::Stick);
  auto roundOff = in;
  roundOff.slip = {1e-13, 0.0};
  EXPECT_EQ(frictionalState<2>(roundOff, ContactState::Slip, p).state, ContactState::Slip);
  auto along = in;
  along.slip = {-0.005, 0.0};
  EXPECT_EQ(frictionalState<2>(along, ContactState::Slip, p).state, ContactState::Slip);
}

// A node that closes is judged on its augmented values (lambda = 0) from the
// stick side: the master passed over it by w before it closed. Penetration
// g~ = -0.1 (D 0.5, eps_n 50): lambdā_n = 50 × -0.1 / 0.5 = -10, Θ = 3.
TEST(FrictionalNode, ClosingNodeIsJudgedOnItsSlip) {
  auto p = coulombParameters(0.3);  // k 2, eps_n 50, eps_tau 5
  p.roundOffSlip = 1e-10;
  FrictionalNodeInput<2> in;
  in.normal = {0.0, -1.0};
  in.D = 0.5;
  in.gap = -0.1;
  in.slip = {0.5, 0.0};  // |lambdā_tau| = 5 × 0.5 / 0.5 = 5 > Θ
  const auto passed = frictionalState<2>(in, ContactState::Inactive, p);
  EXPECT_NEAR(passed.threshold, 3.0, 1e-12);
  EXPECT_NEAR(passed.tangentNorm, 5.0, 1e-12);
  EXPECT_EQ(passed.state, ContactState::Slip);
  in.slip = {0.2, 0.0};  // 2 < Θ: the cone holds it
  EXPECT_EQ(frictionalState<2>(in, ContactState::Inactive, p).state, ContactState::Stick);
  // A slip at the round-off of the coordinates against a threshold at the
  // round-off too (a node just touching): stick, whatever the last bits.
  in.gap = -1e-17;
  in.slip = {4e-11, 0.0};  // |w| / D = 8e-11 < roundOffSlip (Θ = 3e-16)
  EXPECT_EQ(frictionalState<2>(in, ContactState::Inactive, p).state, ContactState::Stick);
  in.slip = {1e-9, 0.0};  // above the floor: judged, and the tiny cone does not hold it
  EXPECT_EQ(frictionalState<2>(in, ContactState::Inactive, p).state, ContactState::Slip);
}

namespace {

/// A node of the prescribed tangential DoF type: component x prescribed and
/// driven (a pusher), n tilted slightly so that the driven direction u has a
/// component in the free row (the coupling of Θ with lambda_n).
template <int dim>
FrictionalNodeInput<dim> drivenNode() {
  FrictionalNodeInput<dim> in;
  if constexpr (dim == 2) {
    in.normal = unit<2>({0.002, -1.0});
    in.oldTraction = {0.4, 3.0};
  } else {
    in.normal = unit<3>({0.002, -0.001, -1.0});
    in.oldTraction = {0.4, -0.2, 3.0};
  }
  in.prescribed[0] = in.driven[0] = true;
  in.D = 0.4;
  in.gap = 0.0;
  return in;
}

}  // namespace

// A slave node whose tangential DoF is prescribed (the corner of a pushed
// block, tests/zoo/incline_block_2d) keeps its friction: no free row sees
// that direction, so its traction is explicit (FrictionalNode.hpp, driven
// directions): in slip exactly Θ = mu p along the slip, in stick the return
// map's trial u.t_old + eps_tau u.w / D. Checked on constructed states, and
// the derivatives against central differences.
TEST(FrictionalNode, PrescribedTangentialDofCarriesItsFriction) {
  const double mu = 0.4;
  const auto p = coulombParameters(mu);
  const double pressure = 5.0;
  // 2D: the tangent t ⟂ n closest to +x (the driven direction), the master
  // slides along +t relative to the slave (seed sign), so the traction on the
  // slave is -p n + mu p t and the free row (y) is in equilibrium with it.
  auto in = drivenNode<2>();
  const std::array<double, 2> t2{-in.normal[1], in.normal[0]};  // (1, 0.002)/|.|
  std::array<double, 2> traction{};
  for (int c = 0; c < 2; ++c) {
    traction[c] = -pressure * in.normal[c] + mu * pressure * t2[c];
    in.slip[c] = 0.5 * t2[c];  // trial 0.4 + eps_tau 0.5 / D = 6.7 > Θ = 2: beyond the penalty's elastic slip
  }
  in.residual = {0.0, p.thickness * in.D * traction[1]};  // x is prescribed: no row
  const auto slip = frictionalRows<2>(in, ContactState::Slip, p);
  ASSERT_TRUE(slip.usable);
  for (int c = 0; c < 2; ++c) EXPECT_NEAR(p.k * slip.lambda[c], traction[c], 1e-12 * pressure) << c;
  for (int c = 0; c < 2; ++c) EXPECT_NEAR(slip.rows[c], 0.0, 1e-12) << c;  // the gap row (g~ = 0); x has none
  EXPECT_NEAR(slip.direction[0], t2[0], 1e-14);
  const auto decided = frictionalState<2>(in, ContactState::Slip, p);
  EXPECT_EQ(decided.state, ContactState::Slip);
  EXPECT_NEAR(decided.threshold, mu * pressure, 1e-12 * pressure);
  EXPECT_NEAR(decided.lambdaN * p.k, -pressure, 1e-12 * pressure);
  // Stick: the trial, u.t_old + eps_tau u.w / D = 0.53, inside the cone.
  auto stick = in;
  for (int c = 0; c < 2; ++c) stick.slip[c] = 0.01 * t2[c];
  double trial = 0;
  for (int c = 0; c < 2; ++c) trial += t2[c] * stick.oldTraction[c] + p.epsTau * t2[c] * stick.slip[c] / stick.D;
  const auto stuck = frictionalRows<2>(stick, ContactState::Stick, p);
  double along = 0, normal = 0;
  for (int c = 0; c < 2; ++c) along += p.k * stuck.lambda[c] * t2[c], normal += p.k * stuck.lambda[c] * in.normal[c];
  EXPECT_NEAR(along, trial, 1e-12);
  // ... with the free row in equilibrium: k t D lambda_y = r_y.
  EXPECT_NEAR(p.k * p.thickness * in.D * stuck.lambda[1], stick.residual[1], 1e-12);
  EXPECT_LT(std::abs(trial), mu * -normal);
  EXPECT_EQ(frictionalState<2>(stick, ContactState::Stick, p).state, ContactState::Stick);
  // A prescribed component that is not driven (a symmetry plane) carries no
  // friction: the multiplier lies along n.
  auto plane = in;
  plane.driven = {};
  const auto none = frictionalRows<2>(plane, ContactState::Slip, p);
  EXPECT_NEAR(none.lambda[0] * in.normal[1] - none.lambda[1] * in.normal[0], 0.0, 1e-14);

  // 3D, x prescribed (one driven direction, one tangent slot y): sliding
  // along the slope t = (x - (n.x) n)/|.| carries mu p along t.
  auto in3 = drivenNode<3>();
  std::array<double, 3> t3{1.0, 0.0, 0.0};
  const double nx = in3.normal[0];
  for (int c = 0; c < 3; ++c) t3[c] -= nx * in3.normal[c];
  t3 = unit<3>(t3);
  std::array<double, 3> traction3{};
  for (int c = 0; c < 3; ++c) {
    traction3[c] = -pressure * in3.normal[c] + mu * pressure * t3[c];
    in3.slip[c] = 0.5 * t3[c];
    in3.residual[c] = c == 0 ? 0.0 : p.thickness * in3.D * traction3[c];
  }
  in3.oldTraction = traction3;  // the last step slid the same way (the trial along t: d = t exactly)
  const auto slip3 = frictionalRows<3>(in3, ContactState::Slip, p);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.k * slip3.lambda[c], traction3[c], 1e-12 * pressure) << c;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(slip3.rows[c], 0.0, 1e-12) << c;
  EXPECT_EQ(frictionalState<3>(in3, ContactState::Slip, p).state, ContactState::Slip);

  // Derivatives (Sacado) against central differences: stick and slip, 2D
  // and 3D, one or two driven components, a driven one beside a symmetry plane.
  for (ContactState state : {ContactState::Stick, ContactState::Slip}) {
    auto node2 = genericNode<2>();
    node2.prescribed[0] = node2.driven[0] = true;
    node2.oldTraction = {0.3, -0.1};
    checkDerivatives<2>(node2, state, p);
    auto node3 = genericNode<3>();
    node3.prescribed[0] = node3.driven[0] = true;
    node3.oldTraction = {0.3, 0.2, -0.1};
    checkDerivatives<3>(node3, state, p);
    node3.prescribed[1] = node3.driven[1] = true;
    checkDerivatives<3>(node3, state, p);
    node3.driven[1] = false;
    checkDerivatives<3>(node3, state, p);
  }
  auto tresca = p;
  tresca.law = FrictionLaw{FrictionLawType::Tresca, 0.0, 1.3};
  auto node3 = genericNode<3>();
  node3.prescribed[0] = node3.driven[0] = true;
  checkDerivatives<3>(node3, ContactState::Slip, tresca);
}
