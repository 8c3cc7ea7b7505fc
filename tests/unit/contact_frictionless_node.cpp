// Frictionless condensed nodes: the frictional kernel (FrictionalNode.hpp)
// on its slip branch with a zero threshold, as AlmFrictional.cpp runs it for
// pairs without friction. The normal multiplier recovered from the slave
// rows of the bulk residual is the one whose force k t D lambda_n n they
// carry (equilibrium of the a-row, also with prescribed components), the
// tangential rows ask for no tangential force, and the state rules of ALM
// (4.73/4.74) and MPC on the recovered value: compression stays, tension
// opens, a node that was open is judged on its gap alone, a node whose free
// components cannot carry the normal stays open.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "coulomb/contact/laws/FrictionalNode.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {
namespace {

constexpr double kK = 2.5, kT = 0.4, kD = 0.03, kEps = 1e5;

FrictionalParameters parameters(bool mpc = false) {
  FrictionalParameters p;
  p.k = kK;
  p.epsN = p.epsTau = kEps;
  p.thickness = kT;
  p.multiPointConstraint = mpc;
  p.law = FrictionLaw{};  // no friction: every active node on the slip branch, threshold 0
  p.pureSlip = true;
  return p;
}

/// Node with normal n whose residual is the force of lambda_n plus `extra`
/// on the prescribed components (which the recovery must ignore).
template <int dim>
FrictionalNodeInput<dim> loaded(const std::array<double, dim>& n, double lambdaN, double gap,
                                  const std::array<bool, dim>& prescribed = {}) {
  FrictionalNodeInput<dim> in;
  in.normal = n;
  in.prescribed = prescribed;
  in.D = kD;
  in.gap = gap;
  for (int c = 0; c < dim; ++c) in.residual[c] = prescribed[c] ? 1e3 : kK * kT * kD * lambdaN * n[c];
  return in;
}

TEST(FrictionlessNode, RecoversTheMultiplierOfItsForce2D) {
  const auto node = frictionalState<2>(loaded<2>({0.6, -0.8}, -0.7, 0.0), ContactState::Slip, parameters());
  EXPECT_EQ(node.state, ContactState::Slip);
  EXPECT_NEAR(node.lambdaN, -0.7, 1e-14);
  // Its rows: the gap row is eps_n t g~ = 0, the tangent row b.r_F = 0 (no
  // tangential force to carry), the recovered multiplier lambda_n n.
  const auto rows = frictionalRows<2>(loaded<2>({0.6, -0.8}, -0.7, 0.0), ContactState::Slip, parameters());
  ASSERT_TRUE(rows.usable);
  const std::array<double, 2> n{0.6, -0.8};
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(rows.rows[c], 0.0, 1e-15);
    EXPECT_NEAR(rows.lambda[c], -0.7 * n[c], 1e-14);
  }
  // A tangential residual is not carried: it stays in the tangent row.
  auto sheared = loaded<2>({0.6, -0.8}, -0.7, 0.0);
  sheared.residual[0] += 0.8 * 1e-3, sheared.residual[1] += 0.6 * 1e-3;
  const auto shearedRows = frictionalRows<2>(sheared, ContactState::Slip, parameters());
  EXPECT_NEAR(std::abs(shearedRows.rows[0]) + std::abs(shearedRows.rows[1]), 1e-3, 1e-12);
}

TEST(FrictionlessNode, RecoversTheMultiplierWithAPrescribedComponent3D) {
  // x prescribed: the a-row is n_F / |n_F| over y, z; the x residual is a support's.
  const std::array<double, 3> n{2.0 / 7.0, -3.0 / 7.0, 6.0 / 7.0};
  const auto node =
      frictionalState<3>(loaded<3>(n, -1.3, 0.0, {true, false, false}), ContactState::Slip, parameters());
  EXPECT_EQ(node.state, ContactState::Slip);
  EXPECT_NEAR(node.lambdaN, -1.3, 1e-14);
}

TEST(FrictionlessNode, TensionOpensAnActiveNode) {
  const std::array<double, 2> n{0.0, 1.0};
  EXPECT_EQ(frictionalState<2>(loaded<2>(n, 0.5, 0.0), ContactState::Slip, parameters()).state,
            ContactState::Inactive);
  // MPC: the reaction alone decides for a tied node, whatever its gap.
  EXPECT_EQ(frictionalState<2>(loaded<2>(n, 0.5, -1e-3), ContactState::Slip, parameters(true)).state,
            ContactState::Inactive);
  EXPECT_EQ(frictionalState<2>(loaded<2>(n, -0.5, 1e-3), ContactState::Slip, parameters(true)).state,
            ContactState::Slip);
}

TEST(FrictionlessNode, AnOpenNodeIsJudgedOnItsGap) {
  const std::array<double, 2> n{0.0, 1.0};
  // Its rows held plain equilibrium: no multiplier is read from them.
  const auto closing = frictionalState<2>(loaded<2>(n, 0.5, -1e-6), ContactState::Inactive, parameters());
  EXPECT_EQ(closing.state, ContactState::Slip);
  EXPECT_EQ(closing.lambdaN, 0.0);
  EXPECT_EQ(frictionalState<2>(loaded<2>(n, -0.5, 1e-6), ContactState::Inactive, parameters()).state,
            ContactState::Inactive);
  EXPECT_EQ(frictionalState<2>(loaded<2>(n, -0.5, 1e-6), ContactState::Inactive, parameters(true)).state,
            ContactState::Inactive);
}

TEST(FrictionlessNode, ANormalTheFreeComponentsCannotCarryStaysOpen) {
  // Normal along x, x prescribed (a node on a symmetry plane seen edge-on).
  const auto node = frictionalState<3>(loaded<3>({1.0, 0.0, 0.0}, -1.0, -1e-3, {true, false, false}),
                                         ContactState::Slip, parameters());
  EXPECT_EQ(node.state, ContactState::Inactive);
}

TEST(FrictionlessNode, BadKernelInputIsAnInternalError) {
  auto in = loaded<2>({0.0, 1.0}, -1.0, 0.0);
  in.D = 0.0;
  EXPECT_THROW(frictionalState<2>(in, ContactState::Slip, parameters()), InternalError);
}

}  // namespace
}  // namespace coulomb::contact
