/// @file ActiveSet.cpp
/// @brief Active-set update rule and summary (seed 4.73/4.74), see ActiveSet.hpp.
#include "coulomb/contact/laws/ActiveSet.hpp"

#include <ostream>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

const char* toString(ContactState state) {
  switch (state) {
    case ContactState::Inactive:
      return "Inactive";
    case ContactState::Slip:
      return "Slip";
    case ContactState::Stick:
      return "Stick";
  }
  return "Unknown";
}

std::ostream& operator<<(std::ostream& out, ContactState state) { return out << toString(state); }

double augmentedNormalMultiplier(double lambdaN, double weightedGap, double D, double k, double epsN) {
  COULOMB_CHECK(D > 0.0, "contact: nodal mortar weight D_j must be > 0, got " << D);
  return k * lambdaN + epsN * weightedGap / D;
}

ContactState almContactState(double lambdaN, double weightedGap, double D, double k, double epsN, double touching) {
  return augmentedNormalMultiplier(lambdaN, weightedGap, D, k, epsN) <= epsN * touching ? ContactState::Slip
                                                                                       : ContactState::Inactive;
}

ContactState mpcContactState(bool wasActive, double lambdaN, double weightedGap) {
  const double decisive = wasActive ? lambdaN : weightedGap;
  return decisive <= 0.0 ? ContactState::Slip : ContactState::Inactive;
}

ContactState penaltyContactState(double weightedGap) {
  return weightedGap <= 0.0 ? ContactState::Slip : ContactState::Inactive;
}

ContactState stickSlipState(double tangentNorm, double threshold, ContactState previous, double slipThreshold) {
  // A sticking node exactly on the cone (|lambdā_tau| = Θ to round-off: e.g.
  // a node that slipped in the last step, restarted as stick, and is carried
  // rigidly) stays stick: the decision must not depend on the last bits,
  // which differ with the rank count.
  constexpr double kRoundOff = 1e-10;
  const double limit = previous == ContactState::Slip ? (1.0 - slipThreshold) * threshold : threshold * (1.0 + kRoundOff);
  return tangentNorm > limit ? ContactState::Slip : ContactState::Stick;
}

ActiveSetSummary& ActiveSetSummary::operator+=(const ActiveSetSummary& other) {
  nodes += other.nodes;
  active += other.active;
  inactive += other.inactive;
  stick += other.stick;
  changed += other.changed;
  stickSlipChanged += other.stickSlipChanged;
  return *this;
}

void countState(ActiveSetSummary& summary, ContactState state, ContactState previous) {
  ++summary.nodes;
  if (isActive(state)) ++summary.active;
  else ++summary.inactive;
  if (state == ContactState::Stick) ++summary.stick;
  if (isActive(state) != isActive(previous)) ++summary.changed;
  else if (state != previous) ++summary.stickSlipChanged;
}

std::ostream& operator<<(std::ostream& out, const ActiveSetSummary& summary) {
  out << "nodes " << summary.nodes << ": active " << summary.active << ", inactive " << summary.inactive
      << ", changed " << summary.changed;
  if (summary.stick > 0 || summary.stickSlipChanged > 0)
    out << ", stick " << summary.stick << ", stick/slip changed " << summary.stickSlipChanged;
  return out;
}

ActiveSetSummary summarizeActiveSet(const std::vector<ContactState>& current,
                                    const std::vector<ContactState>& previous) {
  COULOMB_CHECK(previous.empty() || previous.size() == current.size(),
                  "contact: active set sizes differ (" << current.size() << " nodes now, " << previous.size()
                                                       << " before)");
  ActiveSetSummary s;
  for (std::size_t i = 0; i < current.size(); ++i) countState(s, current[i], previous.empty() ? current[i] : previous[i]);
  return s;
}

}  // namespace coulomb::contact
