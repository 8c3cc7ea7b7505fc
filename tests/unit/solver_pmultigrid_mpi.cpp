// The P-Multigrid preconditioner (solver/PMultigrid.hpp), the default on
// meshes of quadratic cells: on the HEX20 tube of tube_crush_3d (tube3d.geo
// r = 2, 23k DoFs, 7.7k corner DoFs: frictional-free self-contact, GMRES)
// Newton to 1e-10 of the force scale must give the answer MueLu alone gives
// (to that tolerance), in fewer GMRES iterations: MueLu aggregates
// quadratic cells into a poor coarse space (284 against 141 with the adaptive
// tolerance when P-Multigrid came in). np = 1, 2, 3.
#include <gtest/gtest.h>

#include <Teuchos_TimeMonitor.hpp>

#include <cmath>
#include <iostream>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"

namespace coulomb::test {
namespace {

/// `newton`: more parameters of the deck's Newton list.
ContactRun runTube(const std::string& name, const std::string& linearSolver, const std::string& newton = "") {
  ShippedDeck deck("tube_crush_3d", "tube3d.e");
  deck.replace(shippedMesh("tube3d.e"), shippedMesh("tube3d_r2_hex20.e"));
  deck.text.insert(deck.text.rfind("</ParameterList>"),
                   "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" "
                   "value=\"1e-10\"/>" + newton + "</ParameterList>\n" + linearSolver);
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

// While the contact set stays, a solve whose tangent got a new pattern
// keeps the corner level (P^T A P and its MueLu hierarchy) of the last
// P-Multigrid and builds only the smoothers on the new matrix
// (PMultigridFactory::keepCoarseLevel): fewer MueLu setups, the answer of
// a run that builds every preconditioner anew.
TEST(PMultigrid, CornerLevelIsKeptOnlyWhileTheSetIsUnchanged) {
  auto setups = [] {
    const auto timer = Teuchos::TimeMonitor::lookupCounter("MueLu: ParameterListInterpreter (ParameterList)");
    return timer.is_null() ? 0 : timer->numCalls();
  };
  const int before = setups();
  const auto kept = runTube("tube_r2_hex20_reuse", "");
  const int between = setups();
  const auto rebuilt = runTube("tube_r2_hex20_rebuilt", "",
                               "<Parameter name=\"Reuse Preconditioner\" type=\"bool\" value=\"false\"/>");
  const int after = setups();
  int solves = 0, wholeKept = 0, cornerKept = 0;
  for (std::size_t s = 0; s < kept.summary.stepCoarseLevelKept.size(); ++s) {
    const auto& corner = kept.summary.stepCoarseLevelKept[s];
    const auto& whole = kept.summary.stepPreconditionerKept[s];
    const auto& changed = kept.summary.stepChangedNodes[s];
    ASSERT_EQ(corner.size(), changed.size());
    solves += kept.summary.stepNewtonIterations[s];
    for (std::size_t k = 0; k < corner.size(); ++k) {
      wholeKept += whole[k];
      if (!corner[k]) continue;
      ++cornerKept;
      EXPECT_FALSE(whole[k]);
      // Row k is the iterate the solve from iterate k - 1 reached: not the
      // step's first solve, and the set at k - 1 was unchanged (frictionless:
      // no stick/slip count, -1).
      ASSERT_GE(k, 2u) << "step " << s + 1;
      EXPECT_EQ(changed[k - 1], 0) << "step " << s + 1 << ", iteration " << k;
      EXPECT_LE(kept.summary.stepStickSlipChanged[s][k - 1], 0) << "step " << s + 1 << ", iteration " << k;
    }
  }
  std::cout << solves << " solves: preconditioner kept in " << wholeKept << ", corner level in " << cornerKept << "\n";
  EXPECT_GT(cornerKept, 0);  // the path under test was taken
  EXPECT_EQ(between - before, solves - wholeKept - cornerKept);
  int rebuiltSolves = 0;
  for (int n : rebuilt.summary.stepNewtonIterations) rebuiltSolves += n;
  EXPECT_EQ(after - between, rebuiltSolves);
  EXPECT_EQ(kept.summary.cutbacks, 0);
  if (worldComm()->getRank() != 0) return;
  for (const char* field : {"displacement_x", "displacement_y", "contact_pressure"})
    EXPECT_LT(nodalDifference(kept.results, rebuilt.results, field), 1e-7) << field;
  EXPECT_NEAR(lastGlobal(kept.results, "contact_force_inner_y"), lastGlobal(rebuilt.results, "contact_force_inner_y"),
              1e-8 * std::abs(lastGlobal(rebuilt.results, "contact_force_inner_y")));
}

}  // namespace
}  // namespace coulomb::test
