#pragma once
// Shared by the frictional deck tests (contact_friction_*_mpi.cpp,
// contact_quadratic_mpi.cpp): the material of the patch decks, the stick
// variant of the 2D patch, its homogeneous field and the per-node traction check.
#include <gtest/gtest.h>

#include <algorithm>
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

/// The slip deck turned into the stick variant: no slip, tau = mu p / 2;
/// `mesh`: a shipped mesh of the 2D patch (its QUAD9 version, say).
inline std::string stickPatchDeck(const std::string& mesh = "contact_patch2d.e") {
  ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
  if (mesh != "contact_patch2d.e") deck.replace(shippedMesh("contact_patch2d.e"), shippedMesh(mesh));
  deck.replace("<Parameter name=\"Value\" type=\"double\" value=\"0.002\"/>", "");
  deck.replace("0.004285714285714286, 0.008571428571428572", "0.004285714285714286, 0.004285714285714286");
  for (int i = 0; i < 4; ++i) deck.replace("692.3076923076923}", "346.15384615384615}");
  return deck.text;
}

/// Max over owned nodes of |u - homogeneous field| (punch: + (slip, 0)).
inline double homogeneousFieldError(const solver::Simulation& simulation, double shearTraction, double slip) {
  const double gamma = shearTraction / kShearModulus;
  double error = 0;
  forOwnedNodes(simulation, [&](long long, const double* X, const double* u) {
    const bool punch = X[1] > 0.5 + 1e-12 || (std::abs(X[1] - 0.5) < 1e-12 && u[0] > kEpsXX * X[0] + 0.5 * gamma + slip / 2);
    const double ux = kEpsXX * X[0] + gamma * X[1] + (punch ? slip : 0.0), uy = -0.01 * X[1];
    error = std::max({error, std::abs(u[0] - ux), std::abs(u[1] - uy)});
  });
  return globalMax(error);
}

}  // namespace coulomb::test
