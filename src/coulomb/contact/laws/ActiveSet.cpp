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

ContactState almContactState(double lambdaN, double weightedGap, double D, double k, double epsN, double touching) {
  COULOMB_CHECK(D > 0.0, "contact: nodal mortar weight D_j must be > 0, got " << D);
  return k * lambdaN + epsN * weightedGap / D <= epsN * touching ? ContactState::Slip : ContactState::Inactive;
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

}  // namespace coulomb::contact
