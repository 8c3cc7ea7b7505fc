// The P-Multigrid preconditioner (solver/PMultigrid.hpp), the default on
// meshes of quadratic cells: on the HEX20 tube of tube_crush_3d (tube3d.geo
// r = 2, 23k DoFs, 7.7k corner DoFs: frictional-free self-contact, GMRES)
// Newton to 1e-10 of the force scale must give the answer MueLu alone gives
// (to that tolerance), in fewer GMRES iterations: MueLu aggregates
// quadratic cells into a poor coarse space (284 against 141 with the adaptive
// tolerance when P-Multigrid came in). np = 1, 2, 3.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

ContactRun runTube(const std::string& name, const std::string& linearSolver) {
  ShippedDeck deck("tube_crush_3d", "tube3d.e");
  deck.replace(shippedMesh("tube3d.e"), shippedMesh("tube3d_r2_hex20.e"));
  deck.text.insert(deck.text.rfind("</ParameterList>"),
                   "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" "
                   "value=\"1e-10\"/></ParameterList>\n" + linearSolver);
  return runDeckText(name, deck.text);
}

TEST(PMultigrid, SameAnswerAsMueLuInFewerIterationsOnHex20Tube) {
  const auto pmg = runTube("tube_r2_hex20_pmultigrid", "");
  const auto muelu = runTube("tube_r2_hex20_muelu",
                             "<ParameterList name=\"Linear Solver\"><Parameter name=\"Preconditioner Type\" "
                             "type=\"string\" value=\"MueLu\"/></ParameterList>\n");
  EXPECT_EQ(pmg.summary.cutbacks, 0);
  EXPECT_EQ(muelu.summary.cutbacks, 0);
  std::cout << "GMRES iterations: P-Multigrid " << pmg.summary.linearIterations << ", MueLu "
            << muelu.summary.linearIterations << "\n";
  EXPECT_LT(pmg.summary.linearIterations, 0.7 * muelu.summary.linearIterations)
      << pmg.summary.linearIterations << " against " << muelu.summary.linearIterations;
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure"})
    EXPECT_LT(nodalDifference(pmg.results, muelu.results, field), 1e-7) << field;
  EXPECT_NEAR(lastGlobal(pmg.results, "contact_force_inner_y"), lastGlobal(muelu.results, "contact_force_inner_y"),
              1e-8 * std::abs(lastGlobal(muelu.results, "contact_force_inner_y")));
}

}  // namespace
}  // namespace coulomb::test
