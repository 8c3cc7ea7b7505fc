// The condensation of the dual multipliers is exact: one Newton step of the
// condensed displacement system J du = -F (ContactModel) equals the
// displacement part of the same step of the uncondensed saddle-point system
//   [K + K_c  C] [du]     [r - f_c]
//   [  G_s    0] [dl] = - [  g_s  ]
// with lambda_n of each active slave node as an unknown of its own. Both are
// solved with the gathered direct solver ("Amesos2"), from a state away from
// equilibrium (the converged Hertz solution, perturbed), in 2D and
// in 3D (the quarter model: slave nodes with prescribed components).
// Then whole runs of both forms (deck `Contact/System Form`): the same
// active sets, Newton counts and converged solution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "ContactTestSupport.hpp"
#include "TestSupport.hpp"
#include "coulomb/contact/ContactModel.hpp"
#include "coulomb/fem/Assembler.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"
#include "coulomb/solver/LinearSolverFactory.hpp"

namespace coulomb::test {
namespace {

using TpetraOperator = Tpetra::Operator<Scalar, LocalOrdinal, GlobalOrdinal>;

/// x = A^{-1} b with the gathered direct solver.
void directSolve(const Teuchos::RCP<CrsMatrix>& A, const Vector& b, Vector& x) {
  Teuchos::ParameterList parameters("Linear Solver");
  parameters.set("Linear Solver Type", "Amesos2");
  auto solver = solver::buildLinearSolver(parameters, 1, static_cast<long long>(A->getGlobalNumRows()));
  auto space = Thyra::createVectorSpace<double>(A->getRangeMap());
  auto op = Thyra::createConstLinearOp<double>(Teuchos::rcp_implicit_cast<const TpetraOperator>(A), space, space);
  auto lows = Thyra::linearOpWithSolve(*solver.factory, op);
  auto xThyra = Thyra::createVector<double>(Teuchos::rcpFromRef(x), space);
  auto bThyra = Thyra::createConstVector<double>(Teuchos::rcpFromRef(b), space);
  const auto status = Thyra::solve<double>(*lows, Thyra::NOTRANS, *bThyra, xThyra.ptr());
  ASSERT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED) << status.message;
}

/// The relative residual of the saddle point's du in the condensed system,
/// for one Newton step from the perturbed converged state of `deck`.
double condensedAgainstSaddlePoint(const std::string& deck) {
  const std::string dir = scratchDirectory("contact_saddle_" + deck);
  solver::Simulation simulation(std::string(COULOMB_SOURCE_DIR) + "/xml/" + deck + ".xml", worldComm(), nullptr,
                                dir + "/out.e");
  simulation.run();
  const double time = 1.0;
  const auto map = simulation.dofMap().ownedMap();
  auto& assembler = simulation.assembler();
  auto& contact = *simulation.contact();
  Vector u(simulation.displacement(), Teuchos::Copy), r(map), F(map), w(map);
  // Away from equilibrium: the converged state plus a smooth perturbation of
  // 2 % of the largest displacement (prescribed DoFs kept).
  auto wd = w.getDataNonConst(0);
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    wd[i] = std::sin(0.37 * static_cast<double>(map->getGlobalElement(static_cast<LocalOrdinal>(i))));
  u.update(0.02 * u.normInf(), w, 1.0);
  assembler.constraints().setPrescribedValues(time, u);
  assembler.assemble(time, u, &r, nullptr);
  contact.update(u, r);
  auto K = assembler.createMatrix();
  assembler.assemble(time, u, nullptr, K.get());

  // Condensed: J du = -F.
  F.assign(r);
  contact.condenseResidual(F);
  F.scale(-1.0);
  Vector du(map);
  const auto J = contact.condensedTangent(K);
  directSolve(J, F, du);

  // Saddle point: the DoF map plus one lambda_n per active slave node (owned by the node's owner).
  const auto& saddle = contact.contributions().saddle;
  std::vector<GlobalOrdinal> gids(map->getNodeElementList().begin(), map->getNodeElementList().end());
  for (const auto& g : saddle.gap) gids.push_back(g.row);
  auto extended = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                       Teuchos::ArrayView<const GlobalOrdinal>(gids), 0, map->getComm()));
  std::vector<linalg::MatrixTriplet> triplets = contact.contributions().contactStiffness;
  const auto& columns = *K->getColMap();
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    Teuchos::ArrayView<const LocalOrdinal> indices;
    Teuchos::ArrayView<const double> values;
    K->getLocalRowView(static_cast<LocalOrdinal>(i), indices, values);
    for (int k = 0; k < indices.size(); ++k)
      triplets.push_back({map->getGlobalElement(static_cast<LocalOrdinal>(i)), columns.getGlobalElement(indices[k]),
                          values[k]});
  }
  // The multiplier columns scaled like the stiffness (unknown lambda_n / s,
  // s = 1e5 here ~ eps_n h / k): with k = 1 the columns are about D_j, five
  // orders below K, and the direct solve would lose those digits.
  const double s = 1e5;
  for (auto t : saddle.columns) {
    t.value *= s;
    triplets.push_back(t);
  }
  triplets.insert(triplets.end(), saddle.rows.begin(), saddle.rows.end());
  auto A = linalg::matrixFromTriplets(triplets, extended);
  Vector residual(map, Teuchos::Copy);
  residual.assign(r);
  linalg::addEntries(saddle.force, residual);  // r - f_c
  Vector b(extended), x(extended);
  {
    auto bd = b.getDataNonConst(0);
    const auto rd = residual.getData(0);
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) bd[i] = -rd[i];
  }
  std::vector<linalg::VectorEntry> gap;
  for (const auto& g : saddle.gap) gap.push_back({g.row, -g.value});
  linalg::addEntries(gap, b);
  directSolve(A, b, x);

  // The saddle point's du put into the condensed system: its relative
  // residual ||J du_s - (-F)|| / ||F|| is the backward error, free of the
  // conditioning of either system (which bounds how close the two computed
  // solutions can be, here ~1e-6 relative).
  Vector duSaddle(map), check(map);
  {
    auto sd = duSaddle.getDataNonConst(0);
    const auto xd = x.getData(0);
    for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) sd[i] = xd[i];
  }
  J->apply(duSaddle, check);
  check.update(-1.0, F, 1.0);
  const double backward = check.norm2() / F.norm2();
  duSaddle.update(-1.0, du, 1.0);
  const double forward = duSaddle.normInf() / du.normInf();  // collective: on every rank
  if (worldComm()->getRank() == 0)
    std::printf("%s: backward error %.2e, forward difference %.2e\n", deck.c_str(), backward, forward);
  EXPECT_LT(forward, 1e-7);
  EXPECT_GT(du.normInf(), 0.0);
  EXPECT_GT(contact.lastSummary().activeSet.active, 5u);
  return backward;
}

}  // namespace

TEST(ContactCondensation, SameNewtonStepAsTheSaddlePointSystem2D) {
  EXPECT_LT(condensedAgainstSaddlePoint("hertz2d"), 1e-9);
}

TEST(ContactCondensation, SameNewtonStepAsTheSaddlePointSystem3DWithSymmetryPlanes) {
  EXPECT_LT(condensedAgainstSaddlePoint("hertz3d_quarter"), 1e-9);
}

namespace {

/// Runs `deck` condensed and in the saddle-point form (multipliers as
/// unknowns), both with the direct solver, and compares the runs. The
/// iterates are not bit-identical: the condensed form recovers lambda from
/// the bulk residual at each iterate, the saddle point carries it as an
/// unknown, so they differ at second order in the increment; the active
/// sets, the Newton counts and the converged solution must agree.
void sameRunInBothForms(const std::string& deck, const std::string& mesh) {
  ShippedDeck condensed(deck, mesh), saddle(deck, mesh);
  const std::string contact = "<ParameterList name=\"Contact\">";
  condensed.replace(contact,
                    "<ParameterList name=\"Linear Solver\"><Parameter name=\"Linear Solver Type\" type=\"string\" "
                    "value=\"Amesos2\"/></ParameterList>\n  " + contact);
  saddle.replace(contact, contact + "\n    <Parameter name=\"System Form\" type=\"string\" value=\"Saddle Point\"/>");
  // Both at a Newton tolerance far below where the quadratic iterates land
  // (at the default 1e-8 of the force scale the last residuals of hertz3d
  // steps 4 and 5 fall either side of it in the two forms, whose residuals
  // differ by the multiplier rows: 15 vs 17 iterations for the same
  // iterates; at 1e-10 both take 18).
  const std::string tight =
      "<ParameterList name=\"Newton\"><Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1e-10\"/>"
      "</ParameterList>\n  ";
  condensed.replace(contact, tight + contact);
  saddle.replace(contact, tight + contact);
  const auto a = runDeckText("saddle_form_" + deck + "_condensed", condensed.text);
  const auto b = runDeckText("saddle_form_" + deck + "_saddle_point", saddle.text);
  ASSERT_EQ(a.summary.steps, b.summary.steps);
  ASSERT_EQ(a.summary.cutbacks + b.summary.cutbacks, 0);
  // Both converge quadratically once the set is fixed: a wrong block of the
  // saddle-point tangent shows as extra iterations (a flipped master K_c: 22 vs 17).
  EXPECT_LE(std::abs(a.summary.newtonIterations - b.summary.newtonIterations), 1);
  for (int s = 0; s < a.summary.steps; ++s) {
    // One more or fewer iteration where the last residual lands near the
    // tolerance (the two residual vectors are scaled differently).
    EXPECT_LE(std::abs(a.summary.stepNewtonIterations[s] - b.summary.stepNewtonIterations[s]), 1) << "step " << s;
    const auto& activeA = a.summary.stepActiveNodes[s];
    const auto& activeB = b.summary.stepActiveNodes[s];
    for (std::size_t k = 0; k < std::min(activeA.size(), activeB.size()); ++k)
      EXPECT_EQ(activeA[k], activeB[k]) << "step " << s << ", iteration " << k;
    EXPECT_EQ(activeA.back(), activeB.back()) << "step " << s;
  }
  Vector difference(a.simulation->displacement(), Teuchos::Copy);
  difference.update(-1.0, b.simulation->displacement(), 1.0);
  const double du = difference.normInf() / a.simulation->displacement().normInf();
  if (worldComm()->getRank() != 0) {
    EXPECT_LT(du, 1e-8);
    return;
  }
  const auto& pa = lastNodal(a.results, "contact_pressure");
  const auto& pb = lastNodal(b.results, "contact_pressure");
  double pMax = 0, dp = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    pMax = std::max(pMax, pa[i]);
    dp = std::max(dp, std::abs(pa[i] - pb[i]));
  }
  std::printf("%s: saddle point vs condensed: |du|/|u| %.2e, |dp|/p_max %.2e, %d vs %d Newton iterations\n",
              deck.c_str(), du, dp / pMax, b.summary.newtonIterations, a.summary.newtonIterations);
  EXPECT_LT(du, 1e-8);
  EXPECT_GT(pMax, 0.0);
  EXPECT_LT(dp, 1e-6 * pMax);
  EXPECT_GT(b.summary.stepActiveNodes.back().back(), 5);
}

}  // namespace

TEST(ContactSaddlePointForm, SameRunAsTheCondensedForm2D) { sameRunInBothForms("hertz2d", "hertz2d.e"); }

TEST(ContactSaddlePointForm, SameRunAsTheCondensedForm3DWithSymmetryPlanes) {
  sameRunInBothForms("hertz3d_quarter", "hertz3d_quarter.e");
}

}  // namespace coulomb::test
