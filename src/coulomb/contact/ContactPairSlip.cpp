/// @file ContactPairSlip.cpp
/// @brief ContactPair::weightedSlip: the weighted slip of a slave node over
/// the step (seed 4.69b, or 4.65a) and its derivative, for the frictional
/// formulations.
#include <cmath>
#include <map>

#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/contact/formulation/RowSink.hpp"

namespace coulomb::contact {

namespace {
/// |D_j - int N_j| / int N_j below which a node's support counts as wholly on
/// the master. Covered nodes of friction_patch_3d deviate by up to 6e-5 (the
/// quadrature of the dual basis through a distorted bilinear map), 2D ones
/// by 1e-16; a support partly off the master by 1e-2 to 1e-1 on both decks.
constexpr double kCoverageTolerance = 1e-3;
}  // namespace

bool ContactPair::coveredByMaster(const NodalMortarEntry& entry, const InterfaceConfiguration& x) const {
  const double support = nodalSupportMeasure(*interface_, x, interface_->slaveNodeIndex(entry.node));
  return std::abs(entry.D - support) <= kCoverageTolerance * support;
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
  // And only where the node's support lies on the master now and at the
  // step start: where part of it is off the master the overlap's moving
  // edge enters sum_l ΔM_jl (x_j - x_l) as slip (an over-count measured on
  // friction_patch_2d: 2.84e-3 at the node leaving the master against 1.95e-3
  // at its neighbours), and the non-objective measure is the right one.
  bool objective = settings_.slipMeasure == SlipMeasure::Objective && previous != nullptr &&
                   stepStartCovered_[static_cast<std::size_t>(previous - stepStartMortar_.entries.data())] &&
                   coveredByMaster(entry, x_);
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

}  // namespace coulomb::contact
