#pragma once
/// @file FrictionParameters.hpp
/// @brief The parameters of the frictional kernels (FrictionalNode.hpp) for
/// the frictional formulations: the pair's, then a node's on top.
#include "coulomb/contact/formulation/Formulation.hpp"
#include "coulomb/contact/laws/FrictionalNode.hpp"

namespace coulomb::contact {

/// The pair's part (eps_n, eps_tau and mu are the node's: nodeFrictionalParameters).
inline FrictionalParameters pairFrictionalParameters(const PairConstants& c) {
  const ContactPairSettings& s = *c.settings;
  FrictionalParameters p;
  p.k = c.k;
  p.thickness = c.thickness;
  p.slipAugmentation = s.slipAugmentation;
  p.slipThreshold = s.slipThreshold;
  // 1e-10 of the slave face size: far above the round-off of the
  // coordinates, far below any slip that matters.
  p.roundOffSlip = 1e-10 * c.faceSize;
  p.touchingGap = c.touchingGap();
  p.law = s.friction;
  p.multiPointConstraint = s.formulation == ContactFormulation::MPC;
  // Penalty pairs: the deck requires Slip Reset Frequency >= 0 (ContactSettings.cpp).
  p.slipDirectionFromSlip = s.slipResetFrequency < 0;
  p.pureSlip = s.pureSlip;
  return p;
}

/// `pair` with node n's eps_n, eps_tau = kappa eps_n and mu.
inline FrictionalParameters nodeFrictionalParameters(FrictionalParameters pair, const SlaveNode& n,
                                                     const PairConstants& c) {
  pair.law.coefficient = n.frictionCoefficient;
  pair.epsN = n.epsN;
  pair.epsTau = c.settings->tangentFactor * n.epsN;
  return pair;
}

}  // namespace coulomb::contact
