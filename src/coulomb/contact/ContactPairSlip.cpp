/// @file ContactPairSlip.cpp
/// @brief ContactPair::weightedSlip: the weighted slip of a slave node over
/// the step (seed 4.69b, or 4.65a) and its derivative, for the frictional
/// formulations.
#include <cmath>
#include <map>
#include <string>

#include "coulomb/contact/ContactPair.hpp"
#include "coulomb/contact/formulation/RowSink.hpp"
#include "coulomb/contact/interface/NodalSupport.hpp"
#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

namespace {
/// The relative deviation |D_j - S_j| / S_j of a node's support from full
/// coverage (S_j its D_j under a covering master, nodalSupportMeasures)
/// below which it counts as wholly on the master, and above which as partly
/// off it; in between the objective slip's weight falls smoothly from 1 to 0
/// (objectiveWeight). Covered nodes deviate by up to 6e-5, partly covered
/// ones by 1e-2 to 1e-1, rim nodes sliding along a coincident master rim
/// (pressed_torsion_3d on HEX20) by 5e-4 to 2e-3 (docs/architecture.md,
/// "Coverage").
constexpr double kCoveredDeviation = 2.5e-4;
constexpr double kCoverageTolerance = 1e-3;
/// D_j / S_j below which a node's support lies mostly off the master and
/// the node is no contact node (ContactPair::contactWeight).
constexpr double kMinimumCoverage = 0.05;
}  // namespace

double ContactPair::supportMeasure(long long node) const {
  // The entry may be mortarDerivatives_'s (the same values, other storage).
  const NodalMortarEntry* own = mortar_.find(node);
  if (own == nullptr) throw Error("internal: no mortar entry of slave node " + std::to_string(node + 1));
  return support_[static_cast<std::size_t>(own - mortar_.entries.data())];
}

bool ContactPair::contactWeight(const NodalMortarEntry& entry) const {
  if (!(entry.D > minimumD_)) return false;
  return entry.D >= kMinimumCoverage * supportMeasure(entry.node);
}

double ContactPair::objectiveWeight(const NodalMortarEntry& entry, DerivativeRow* derivative) const {
  const double support = supportMeasure(entry.node);
  const double deviation = std::abs(entry.D - support) / support;
  if (deviation <= kCoveredDeviation) return 1.0;
  if (deviation >= kCoverageTolerance) return 0.0;
  // smoothstep of t = 1 at kCoveredDeviation, 0 at kCoverageTolerance: C1, so
  // the slip rows stay continuous as a node's coverage crosses the band.
  const double band = kCoverageTolerance - kCoveredDeviation;
  const double t = (kCoverageTolerance - deviation) / band;
  if (derivative) {
    // d deviation = [sign(D - S) (dD - dS) - deviation dS] / S; d weight = d weight/dt (-1 / band) d deviation.
    const double scale = -6.0 * t * (1.0 - t) / band / support;
    const double sign = entry.D > support ? 1.0 : -1.0;
    derivative->clear();
    addScaled(*derivative, entry.dD, scale * sign);
    addScaled(*derivative, nodalSupportMeasureDerivative(*interface_, x_, entry.node), -scale * (sign + deviation));
  }
  return t * t * (3.0 - 2.0 * t);
}

std::array<double, 3> ContactPair::weightedSlip(const NodalMortarEntry& entry,
                                                std::array<DerivativeRow, 3>* derivative) const {
  // Objective (4.69b): w = (D - D^t) x_j - sum_l (M_jl - M^t_jl) x_l, in the
  // translation-invariant form w = sum_l (M_jl - M^t_jl) (x_j - x_l) (the
  // same slip with the lumped D, D_j = sum_l M_jl; without the round-off
  // that grows with the distance from the origin). Non-objective (4.65a,
  // seed sign): w = -[D (x_j - x^t_j) - sum_l M_jl (x_l - x^t_l)], the only
  // one for a node without operators at the step start.
  // docs/architecture.md, "Frictional contact", has both and their tests.
  const NodalMortarEntry* previous = stepStartMortar_.find(entry.node);
  // The objective form only where the node's support lies on the master now
  // and at the step start: the moving edge of a partial overlap counts as
  // slip in it (docs/architecture.md, "Coverage"). A node at the edge of
  // full coverage takes a blend, w = a w_objective + (1 - a) w_non-objective
  // with a = objectiveWeight at the step start times now: a sharp switch
  // made rim nodes at the threshold change form at every iterate and Newton
  // cycle (pressed_torsion_3d on HEX20, a node at 0.91e-3 / 1.02e-3).
  double weight = 0.0;
  DerivativeRow dWeight;  // only where the weight is neither 0 nor 1
  if (settings_.slipMeasure == SlipMeasure::Objective && previous != nullptr) {
    const double start = stepStartWeight_[static_cast<std::size_t>(previous - stepStartMortar_.entries.data())];
    if (start > 0.0) weight = start * objectiveWeight(entry, derivative ? &dWeight : nullptr);
    for (auto& [key, value] : dWeight) value *= start;
  }
  if (weight > 0.0 && settings_.operatorThreshold > 0.0) {
    // Relative change of D_j and the M_jl over the step (the seed's OPERATOR_THRESHOLD).
    double change = std::abs(entry.D - previous->D), size = std::abs(entry.D);
    std::map<long long, double> difference;
    for (const auto& [l, m] : entry.M) difference[l] += m, size += std::abs(m);
    for (const auto& [l, m] : previous->M) difference[l] -= m;
    for (const auto& [l, d] : difference) change += std::abs(d);
    if (!(change > settings_.operatorThreshold * size)) weight = 0.0;
  }
  auto point = [this](const InterfaceConfiguration& x, long long node) {
    return x.point(interface_->interfaceNodeIndex(node));
  };
  // The slave node's own position is its transformed one on Quad8 / Tri6
  // faces, x~_j = sum_k T^-1_jk x_k (the variables D is diagonal in,
  // SlaveTransform.hpp): the terms (k, T^-1_jk), {(j, 1)} elsewhere.
  const auto& own = slaveTransform_->forceTerms(interface_->slaveNodeIndex(entry.node));
  std::array<double, 3> xjValue{}, xtjValue{};
  for (const auto& term : own) {
    const long long k = interface_->slaveNodes()[term.slave];
    for (int c = 0; c < dim_; ++c) {
      xjValue[c] += term.coefficient * point(x_, k)[c];
      xtjValue[c] += term.coefficient * point(stepStartX_, k)[c];
    }
  }
  const double* xj = xjValue.data();
  const double* xtj = xtjValue.data();
  // row += value d x~_j,c / dx
  auto addOwn = [&](DerivativeRow& row, int c, double value) {
    for (const auto& term : own) row[{interface_->slaveNodes()[term.slave], c}] += value * term.coefficient;
  };
  // Objective (4.69b) into w, derivative.
  auto objectiveSlip = [&](std::array<double, 3>& w, std::array<DerivativeRow, 3>* derivative) {
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
          addOwn(row, c, m.first - m.second);
          row[{l, c}] -= m.first - m.second;
        }
      }
  };
  // Non-objective (4.65a) into w, derivative.
  auto nonObjectiveSlip = [&](std::array<double, 3>& w, std::array<DerivativeRow, 3>* derivative) {
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
        addOwn(row, c, -entry.D);
        for (const auto& [l, m] : entry.M) {
          const auto dM = entry.dM.find(l);
          if (dM != entry.dM.end()) addScaled(row, dM->second, point(x_, l)[c] - point(stepStartX_, l)[c]);
          row[{l, c}] += m;
        }
      }
  };
  std::array<double, 3> w{};
  if (derivative)
    for (auto& row : *derivative) row.clear();
  if (weight == 1.0) {
    objectiveSlip(w, derivative);
  } else if (weight == 0.0) {
    nonObjectiveSlip(w, derivative);
  } else {
    std::array<double, 3> wo{}, wn{};
    std::array<DerivativeRow, 3> dwo, dwn;
    objectiveSlip(wo, derivative ? &dwo : nullptr);
    nonObjectiveSlip(wn, derivative ? &dwn : nullptr);
    for (int c = 0; c < dim_; ++c) {
      w[c] = weight * wo[c] + (1.0 - weight) * wn[c];
      if (!derivative) continue;
      // d/dx [a wo + (1 - a) wn], a through D_j and S_j.
      auto& row = (*derivative)[c];
      addScaled(row, dwo[c], weight);
      addScaled(row, dwn[c], 1.0 - weight);
      addScaled(row, dWeight, wo[c] - wn[c]);
    }
  }
  return w;
}

}  // namespace coulomb::contact
