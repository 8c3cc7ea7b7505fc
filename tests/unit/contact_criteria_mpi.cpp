// Contact/Convergence Criterion (the seed's residual, increment and mixed
// criteria) and Ensure Contact on Cattaneo–Mindlin (a stick core, slipping
// edges): every criterion converges to the same answer (the tolerances
// bound the error of each), and a criterion that judges increments needs
// more Newton iterations than the residual one — an increment is small one
// iteration after the residual is (quadratic convergence: |du_k| ~ |e_(k-1)|),
// so a deck whose criterion were ignored would show the residual's count.
// Measured (np 1): Residual 33, Increment 45, Mixed 41 Newton iterations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

ContactRun runWith(const std::string& name, const std::string& contactParameters, const std::string& pairParameters) {
  ShippedDeck deck("cattaneo_mindlin_2d", "hertz2d.e");
  deck.replace("<ParameterList name=\"Pairs\">", contactParameters + "<ParameterList name=\"Pairs\">");
  const std::string alm = "<Parameter name=\"Formulation\" type=\"string\" value=\"ALM\"/>";
  deck.replace(alm, alm + pairParameters);
  return runDeckText(name, deck.text);
}

std::string criterion(const std::string& name) {
  return "<Parameter name=\"Convergence Criterion\" type=\"string\" value=\"" + name + "\"/>";
}

TEST(ContactCriteria, IncrementAndMixedConvergeToTheResidualAnswer) {
  auto residual = runWith("criterion_residual", "", "");
  auto increment = runWith("criterion_increment", criterion("Increment"), "");
  auto mixed = runWith("criterion_mixed", criterion("Mixed"), "");
  EXPECT_GT(increment.summary.newtonIterations, residual.summary.newtonIterations);
  EXPECT_GT(mixed.summary.newtonIterations, residual.summary.newtonIterations);
  if (worldComm()->getRank() != 0) return;
  for (const auto* run : {&increment, &mixed})
    for (const char* field : {"displacement_x", "displacement_y", "contact_pressure", "contact_tangential_traction_x"})
      EXPECT_LT(nodalDifference(residual.results, run->results, field), 1e-5) << field;
  EXPECT_EQ(residual.results.nodal.back()[residual.results.nodalIndex("contact_state")],
            increment.results.nodal.back()[increment.results.nodalIndex("contact_state")]);
}

// A loose displacement increment tolerance stops the Increment criterion
// earlier than the default one (the tolerance is read and used).
TEST(ContactCriteria, IncrementToleranceIsUsed) {
  auto tight = runWith("criterion_increment_tight", criterion("Increment"), "");
  auto loose = runWith("criterion_increment_loose",
                       criterion("Increment") +
                           "<Parameter name=\"Increment Relative Tolerance\" type=\"double\" value=\"1e-2\"/>"
                           "<Parameter name=\"Normal Relative Tolerance\" type=\"double\" value=\"1e-2\"/>"
                           "<Parameter name=\"Stick Relative Tolerance\" type=\"double\" value=\"1e-2\"/>"
                           "<Parameter name=\"Slip Relative Tolerance\" type=\"double\" value=\"1e-2\"/>",
                       "");
  EXPECT_LT(loose.summary.newtonIterations, tight.summary.newtonIterations);
}

// Ensure Contact on a pressed contact changes nothing (its failing side:
// tests/regression/bad_input/contact_ensure_contact_separating.xml).
TEST(ContactCriteria, EnsureContactPassesWhenInContact) {
  auto plain = runWith("ensure_contact_off", "", "");
  auto ensured = runWith("ensure_contact_on", "", "<Parameter name=\"Ensure Contact\" type=\"bool\" value=\"true\"/>");
  EXPECT_EQ(ensured.summary.steps, plain.summary.steps);
  EXPECT_EQ(ensured.summary.newtonIterations, plain.summary.newtonIterations);
}

}  // namespace
}  // namespace coulomb::test
