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
/// the master: covered nodes deviate by up to 6e-5, partly covered ones by
/// 1e-2 to 1e-1 (docs/architecture.md, "Coverage").
constexpr double kCoverageTolerance = 1e-3;
/// D_j / int N_j below which a node's support lies mostly off the master and
/// the node is no contact node (ContactPair::contactWeight).
constexpr double kMinimumCoverage = 0.05;
}  // namespace

bool ContactPair::contactWeight(const NodalMortarEntry& entry) const {
  if (!(entry.D > minimumD_)) return false;
  const double support = nodalSupportMeasure(*interface_, x_, interface_->slaveNodeIndex(entry.node));
  return entry.D >= kMinimumCoverage * support;
}

bool ContactPair::coveredByMaster(const NodalMortarEntry& entry, const InterfaceConfiguration& x) const {
  const double support = nodalSupportMeasure(*interface_, x, interface_->slaveNodeIndex(entry.node));
  return std::abs(entry.D - support) <= kCoverageTolerance * support;
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
  // And only where the node's support lies on the master now and at the
  // step start: the moving edge of a partial overlap counts as slip in the
  // objective form (docs/architecture.md, "Coverage").
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
          addOwn(row, c, m.first - m.second);
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
        addOwn(row, c, -entry.D);
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
