// The seed's friction semantics: pure slip (FrictionalPureSlip: every active
// node on the slip branch with the law's threshold against its slip, ALM and
// penalty) and the automatic pure slip of a pair whose every mu is zero
// (frictionless).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ContactTestSupport.hpp"
#include "FrictionDeckSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"

namespace coulomb::test {
namespace {

const std::string kPureSlip = "<Parameter name=\"Pure Slip\" type=\"bool\" value=\"true\"/>";

}  // namespace

// The imposed-slip patch (the punch dragged by 0.002 over the base, every
// node slipping) with Pure Slip: each active node carries mu p against its
// slip, with ALM and with penalty — as without Pure Slip. Before, Pure Slip
// dropped the friction (zero tangential traction, a frictionless answer).
TEST(PureSlip, ImposedSlipCarriesMuTimesPressure) {
  for (const char* formulation : {"ALM", "Penalty"}) {
    SCOPED_TRACE(formulation);
    ShippedDeck deck("friction_patch_2d", "contact_patch2d.e");
    deck.replace(kCoulombLaw, kCoulombLaw + kPureSlip + "<Parameter name=\"Formulation\" type=\"string\" value=\"" +
                                  formulation + "\"/>");
    auto run = runDeckText(std::string("pure_slip_patch_") + formulation, deck.text);
    EXPECT_TRUE(run.simulation->contact()->pairs().front()->frictional());
    if (worldComm()->getRank() != 0) continue;
    const double tolerance = std::string(formulation) == "ALM" ? 1e-8 * kPressure : 1e-6 * kPressure;
    const auto nodes = checkTractions(run.results, [](double p) { return -kMu * p; }, tolerance);
    EXPECT_EQ(nodes.slip, 8);
    EXPECT_EQ(nodes.stick, 0);
    EXPECT_EQ(lastGlobal(run.results, "contact_stick_nodes_punch"), 0.0);
  }
}

// A Coulomb pair whose nodal friction field is zero everywhere is the seed's
// automatic pure slip: frictionless (no stick/slip outputs, the frictionless
// answer). Before, it ran the frictional rows with mu = 0.
TEST(PureSlip, AllZeroFrictionFieldIsFrictionless) {
  const std::string dir = scratchDirectory("pure_slip_zero_field");
  const std::string meshCopy = dir + "/hertz2d_mu0.e";
  if (worldComm()->getRank() == 0) {
    const mesh::GlobalMesh m = io::readExodus(shippedMesh("hertz2d.e"));
    io::ExodusWriter writer(meshCopy, m, {"mu"}, {}, "hertz2d with a zero friction coefficient field");
    writer.writeStep(0.0, {std::vector<double>(static_cast<std::size_t>(m.numNodes()), 0.0)}, {});
    writer.close();
  }
  worldComm()->barrier();
  const std::string alm = "<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>";
  ShippedDeck deck("hertz2d", "hertz2d.e");
  deck.replace(shippedMesh("hertz2d.e"), meshCopy);
  deck.replace(alm, alm + kCoulombLaw + "<Parameter name=\"Friction Coefficient Field\" type=\"string\" value=\"mu\"/>");
  auto field = runDeckText("pure_slip_zero_field_run", deck.text);
  auto frictionless = runDeck("hertz2d");
  EXPECT_FALSE(field.simulation->contact()->pairs().front()->frictional());
  if (worldComm()->getRank() != 0) return;
  const auto& names = field.results.globalNames;
  EXPECT_EQ(std::count(names.begin(), names.end(), "contact_stick_nodes_cylinder"), 0);
  const double reference = lastGlobal(frictionless.results, "reaction_top_y");
  EXPECT_NEAR(lastGlobal(field.results, "reaction_top_y"), reference, 1e-9 * std::abs(reference));
}

}  // namespace coulomb::test
