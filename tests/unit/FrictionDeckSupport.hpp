#pragma once
// Shared by the frictional deck tests (contact_friction_*_mpi.cpp): the
// material of the patch decks and the per-node traction check.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {

// The homogeneous state of xml/friction_patch_2d.xml (see its comment).
inline constexpr double kE = 210000, kNu = 0.3, kMu = 0.3;
inline const double kPressure = kE * 0.01 / (1 - kNu * kNu);  // 2307.69
inline const double kEpsXX = kNu / (1 - kNu) * 0.01;
inline const double kShearModulus = kE / (2 * (1 + kNu));
inline const double kImposedSlip = 0.002;  // the slide of the patch decks

inline const std::string kCoulombLaw = "<Parameter name=\"Friction Law\" type=\"string\" value=\"Coulomb\"/>";

struct ActiveNodes {
  int stick = 0, slip = 0;
};
/// Counts the active slave nodes of the last step by state and checks each
/// one's tangential traction (its magnitude, with the sign of its x
/// component: the normals tilt slightly where the punch ends deform)
/// against `expected(pressure)`.
template <class Expected>
ActiveNodes checkTractions(const io::ExodusResults& r, Expected expected, double tolerance, int dim = 2) {
  const auto& state = lastNodal(r, "contact_state");
  const auto& pressure = lastNodal(r, "contact_pressure");
  const auto& tx = lastNodal(r, "contact_tangential_traction_x");
  const auto& ty = lastNodal(r, "contact_tangential_traction_y");
  const auto* tz = dim == 3 ? &lastNodal(r, "contact_tangential_traction_z") : nullptr;
  ActiveNodes nodes;
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state[i] < 0.5) continue;
    (state[i] > 1.5 ? nodes.stick : nodes.slip)++;
    const double magnitude = std::sqrt(tx[i] * tx[i] + ty[i] * ty[i] + (tz ? (*tz)[i] * (*tz)[i] : 0.0));
    const double traction = std::copysign(magnitude, tx[i]);
    EXPECT_NEAR(traction, expected(pressure[i]), tolerance) << "node " << i + 1 << " pressure " << pressure[i];
  }
  return nodes;
}

}  // namespace coulomb::test
