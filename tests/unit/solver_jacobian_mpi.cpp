// The assembled tangent against central finite differences of the assembled
// residual (global, through Tpetra and the overlap export), Neo-Hookean at a
// finite deformation on a distorted TET4 and a HEX8 mesh; and the linear
// solver's true residual (what Stratimikos reports converged must be so).
#include <gtest/gtest.h>

#include <cmath>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "TestSupport.hpp"
#include "coulomb/fem/Assembler.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/fem/RigidBodyModes.hpp"
#include "coulomb/solver/LinearSolverFactory.hpp"

namespace coulomb::test {
namespace {

/// A Neo-Hookean cube, bottom fixed, top pulled and twisted: a finite,
/// inhomogeneous deformation.
std::string twistedCubeDeck(const std::string& name, const std::string& mesh) {
  const std::string dir = scratchDirectory(name);
  const std::string body =
      "<ParameterList name=\"Dirichlet Conditions\">" + dirichletXml("fix", "bottom", "all", 0.0) +
      dirichletXml("twist x", "top", "x", 0.1, {0.0, -0.3, 0.0}) + dirichletXml("twist y", "top", "y", -0.05, {0.3, 0.0, 0.0}) +
      dirichletXml("pull", "top", "z", 0.2) +
      "</ParameterList><ParameterList name=\"Load Stepping\"><Parameter name=\"Number of Steps\" type=\"int\" value=\"2\"/></ParameterList>";
  const std::string material = neoHookeanXml(1000, 0.35);
  const std::string meshFile = dir + "/distorted.e";
  writeDistortedCopy(shippedMesh(mesh), meshFile, 0.2);
  const std::string deck = dir + "/twist.xml";
  writeOnRoot(deck, deckXml(meshFile, material, body));
  return deck;
}

class AssembledJacobian : public ::testing::TestWithParam<const char*> {};

TEST_P(AssembledJacobian, MatchesCentralFiniteDifferences) {
  const std::string mesh = GetParam();
  solver::Simulation simulation(twistedCubeDeck("jacobian_" + mesh.substr(0, mesh.find('.')), mesh), worldComm(), nullptr);
  simulation.run();
  auto& assembler = simulation.assembler();
  const auto map = simulation.dofMap().ownedMap();
  const double time = 1.0;
  Vector u(map), direction(map), fPlus(map), fMinus(map), jv(map);
  u.assign(simulation.displacement());
  // A smooth direction, zero on prescribed DoFs (their columns are eliminated).
  direction.randomize();
  {
    auto d = direction.getDataNonConst(0);
    for (int dof : assembler.constraints().ownedConstrainedDofs()) d[dof] = 0.0;
  }
  direction.scale(1e-2 / direction.normInf());
  auto jacobian = assembler.createMatrix();
  assembler.assemble(time, u, nullptr, jacobian.get());
  jacobian->apply(direction, jv);

  const double h = 1e-4;
  Vector shifted(map);
  shifted.update(1.0, u, h, direction, 0.0);
  assembler.assemble(time, shifted, &fPlus, nullptr);
  shifted.update(1.0, u, -h, direction, 0.0);
  assembler.assemble(time, shifted, &fMinus, nullptr);
  Vector fd(map);
  fd.update(0.5 / h, fPlus, -0.5 / h, fMinus, 0.0);
  Vector difference(map);
  difference.update(1.0, jv, -1.0, fd, 0.0);
  const double relative = difference.norm2() / jv.norm2();
  EXPECT_LT(relative, 1e-6) << "|J v - FD| / |J v| on " << mesh;
  EXPECT_GT(jv.norm2(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(NeoHookean, AssembledJacobian, ::testing::Values("block3d.e", "block3d_tet.e"),
                         [](const auto& info) {
                           std::string n = info.param;
                           return n.substr(0, n.find('.'));
                         });

// An iterate whose prescribed DoFs lag behind their values by e p gets the
// coupling K_fp (e p) added to its free rows (fem/DirichletConstraints.hpp):
// its free residual is the linearisation of the one with the boundary in
// place, so it differs from that one by O(e^2), not O(e). Without the term
// the difference is e K_fp p and halving e halves it.
TEST_P(AssembledJacobian, LaggingBoundaryEntersThroughTheTangent) {
  const std::string mesh = GetParam();
  solver::Simulation simulation(twistedCubeDeck("lagging_" + mesh.substr(0, mesh.find('.')), mesh), worldComm(), nullptr);
  simulation.run();
  auto& assembler = simulation.assembler();
  const auto map = simulation.dofMap().ownedMap();
  const double time = 1.0;
  const auto prescribed = assembler.constraints().ownedConstrainedDofs();
  Vector u(map), lag(map);
  u.assign(simulation.displacement());
  lag.randomize();
  {
    auto d = lag.getDataNonConst(0);
    std::vector<double> kept(d.size(), 0.0);
    for (int dof : prescribed) kept[dof] = d[dof];
    for (std::size_t i = 0; i < kept.size(); ++i) d[i] = kept[i];
  }
  lag.scale(1e-2 / lag.normInf());
  auto freeResidual = [&](double e) {
    Vector shifted(map), f(map);
    shifted.update(1.0, u, -e, lag, 0.0);
    assembler.assemble(time, shifted, &f, nullptr, nullptr, true);
    auto d = f.getDataNonConst(0);
    for (int dof : prescribed) d[dof] = 0.0;
    return f;
  };
  const Vector inPlace = freeResidual(0.0);
  double change[2];
  const double lags[2] = {1e-2, 5e-3};
  for (int k = 0; k < 2; ++k) {
    Vector difference = freeResidual(lags[k]);
    difference.update(-1.0, inPlace, 1.0);
    change[k] = difference.norm2();
  }
  EXPECT_GT(change[1], 0.0);
  const double rate = std::log2(change[0] / change[1]);
  EXPECT_NEAR(rate, 2.0, 0.2) << "|f(u - e p) - f(u)| on the free rows: " << change[0] << ", " << change[1] << " on "
                              << mesh;
}

/// block3d.e (2187 DoFs) takes the small-problem default (Ifpack2),
/// block3d_n16.e (14739 DoFs) the MueLu one with its coarse level on one rank.
class LinearSolve : public ::testing::TestWithParam<const char*> {};

TEST_P(LinearSolve, TrueResidualOfDefaultSolverIsSmall) {
  const std::string mesh = GetParam();
  solver::Simulation simulation(twistedCubeDeck("linear_solve_" + mesh.substr(0, mesh.find('.')), mesh), worldComm(), nullptr);
  auto& assembler = simulation.assembler();
  const auto& dofs = simulation.dofMap();
  Vector u(dofs.ownedMap()), b(dofs.ownedMap()), x(dofs.ownedMap()), r(dofs.ownedMap());
  auto jacobian = assembler.createMatrix();
  assembler.constraints().setPrescribedValues(0.5, u);
  assembler.assemble(0.5, u, &b, jacobian.get());
  b.scale(-1.0);

  auto solver = solver::buildLinearSolver(Teuchos::ParameterList(), dofs.dofsPerNode(),
                                          static_cast<long long>(dofs.ownedMap()->getGlobalNumElements()));
  solver::setMueLuUserData(solver, fem::rigidBodyModes(simulation.mesh(), dofs), fem::nodalCoordinates(simulation.mesh(), dofs));
  auto space = Thyra::createVectorSpace<double>(dofs.ownedMap());
  auto op = Thyra::createConstLinearOp<double>(Teuchos::rcp_implicit_cast<const Tpetra::Operator<double, int, long long>>(jacobian), space, space);
  auto lows = Thyra::linearOpWithSolve(*solver.factory, op);
  auto xThyra = Thyra::createVector(Teuchos::rcpFromRef(x), space);
  auto bThyra = Thyra::createConstVector(Teuchos::rcpFromRef(static_cast<const Vector&>(b)), space);
  const auto status = Thyra::solve<double>(*lows, Thyra::NOTRANS, *bThyra, xThyra.ptr());
  EXPECT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED);
  jacobian->apply(x, r);
  r.update(1.0, b, -1.0);
  EXPECT_LT(r.norm2() / b.norm2(), 1e-8) << "true relative residual at np = " << worldComm()->getSize();
}

INSTANTIATE_TEST_SUITE_P(DefaultSolver, LinearSolve, ::testing::Values("block3d.e", "block3d_n16.e"),
                         [](const auto& info) {
                           std::string n = info.param;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace coulomb::test
