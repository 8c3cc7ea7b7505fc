/// @file ActiveSet.cpp
/// @brief Active-set update rule and summary (seed 4.73/4.74), see ActiveSet.hpp.
#include "coulomb/contact/ActiveSet.hpp"

#include <ostream>

#include "coulomb/core/Error.hpp"

namespace coulomb::contact {

const char* toString(ContactState state) {
  switch (state) {
    case ContactState::Inactive:
      return "Inactive";
    case ContactState::Active:
      return "Active";
  }
  return "Unknown";
}

std::ostream& operator<<(std::ostream& out, ContactState state) { return out << toString(state); }

double augmentedNormalMultiplier(double lambdaN, double weightedGap, double D, double k, double epsN) {
  COULOMB_REQUIRE(D > 0.0, "contact: nodal mortar weight D_j must be > 0, got " << D);
  return k * lambdaN + epsN * weightedGap / D;
}

ContactState almContactState(double lambdaN, double weightedGap, double D, double k, double epsN) {
  return augmentedNormalMultiplier(lambdaN, weightedGap, D, k, epsN) <= 0.0 ? ContactState::Active
                                                                           : ContactState::Inactive;
}

ContactState penaltyContactState(double weightedGap) {
  return weightedGap <= 0.0 ? ContactState::Active : ContactState::Inactive;
}

ActiveSetSummary& ActiveSetSummary::operator+=(const ActiveSetSummary& other) {
  nodes += other.nodes;
  active += other.active;
  inactive += other.inactive;
  changed += other.changed;
  return *this;
}

std::ostream& operator<<(std::ostream& out, const ActiveSetSummary& summary) {
  return out << "nodes " << summary.nodes << ": active " << summary.active << ", inactive " << summary.inactive
             << ", changed " << summary.changed;
}

ActiveSetSummary summarizeActiveSet(const std::vector<ContactState>& current,
                                    const std::vector<ContactState>& previous) {
  COULOMB_REQUIRE(previous.empty() || previous.size() == current.size(),
                  "contact: active set sizes differ (" << current.size() << " nodes now, " << previous.size()
                                                       << " before)");
  ActiveSetSummary s;
  s.nodes = current.size();
  for (std::size_t i = 0; i < current.size(); ++i) {
    if (current[i] == ContactState::Active)
      ++s.active;
    else
      ++s.inactive;
    if (!previous.empty() && previous[i] != current[i]) ++s.changed;
  }
  return s;
}

}  // namespace coulomb::contact
