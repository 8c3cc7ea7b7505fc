#include "coulomb/solver/LinearSolverFactory.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "coulomb/core/Error.hpp"

namespace coulomb::solver {

Teuchos::RCP<Teuchos::ParameterList> defaultLinearSolverParameters(int dofsPerNode) {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Linear Solver"));
  p->set("Linear Solver Type", "Belos");
  auto& belos = p->sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", "Pseudo Block CG");
  auto& cg = belos.sublist("Solver Types").sublist("Pseudo Block CG");
  cg.set("Convergence Tolerance", 1e-9);
  cg.set("Maximum Iterations", 1000);
  // A finite-strain tangent far from the solution may be indefinite: CG then
  // returns an unconverged direction and Newton decides, instead of throwing.
  cg.set("Assert Positive Definiteness", false);
  p->set("Preconditioner Type", "MueLu");
  auto& muelu = p->sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("verbosity", "none");
  muelu.set("number of equations", dofsPerNode);
  muelu.set("multigrid algorithm", "sa");
  muelu.set("max levels", 10);
  muelu.set("coarse: max size", 1000);
  muelu.set("smoother: type", "CHEBYSHEV");
  muelu.sublist("smoother: params").set("chebyshev: degree", 2);
  muelu.set("coarse: type", "RELAXATION");
  muelu.sublist("coarse: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  muelu.sublist("coarse: params").set("relaxation: sweeps", 4);
  return p;
}

LinearSolver buildLinearSolver(const Teuchos::ParameterList& user, int dofsPerNode, int numRanks) {
  LinearSolver solver;
  solver.parameters = Teuchos::rcp(new Teuchos::ParameterList(user));
  solver.parameters->setName("Linear Solver");
  const auto defaults = defaultLinearSolverParameters(dofsPerNode);
  // Only fill MueLu/Belos defaults when the user kept those choices: a user
  // who picks another solver gets exactly what they wrote.
  if (!solver.parameters->isParameter("Linear Solver Type")) solver.parameters->setParametersNotAlreadySet(*defaults);
  else if (!solver.parameters->isParameter("Preconditioner Type") &&
           solver.parameters->get<std::string>("Linear Solver Type") == "Belos") {
    solver.parameters->set("Preconditioner Type", "MueLu");
    solver.parameters->sublist("Preconditioner Types").sublist("MueLu").setParametersNotAlreadySet(
        defaults->sublist("Preconditioner Types").sublist("MueLu"));
  }
  const std::string type = solver.parameters->get<std::string>("Linear Solver Type");
  solver.isDirect = type == "Amesos2" || type == "Amesos";
  COULOMB_REQUIRE(!(solver.isDirect && numRanks > 1),
                  "deck: 'Linear Solver/Linear Solver Type' = '"
                      << type << "' runs only on one rank (Amesos2 KLU2 in Debian's Trilinos 13.2 returns wrong "
                                 "solutions on more ranks); use Belos, or run with one rank");
  solver.usesMueLu = solver.parameters->isParameter("Preconditioner Type") &&
                     solver.parameters->get<std::string>("Preconditioner Type") == "MueLu";

  Stratimikos::DefaultLinearSolverBuilder builder;
  Stratimikos::enableMueLu<LocalOrdinal, GlobalOrdinal, typename CrsMatrix::node_type>(builder);
  using Ifpack2Factory = Thyra::Ifpack2PreconditionerFactory<CrsMatrix>;
  builder.setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>, Ifpack2Factory>(), "Ifpack2");
  try {
    builder.setParameterList(solver.parameters);
    solver.factory = builder.createLinearSolveStrategy("");
  } catch (const std::exception& e) {
    std::string message = e.what();
    for (auto& c : message)
      if (c == '\n') c = ' ';
    throw Error("deck: 'Linear Solver' is not accepted by Stratimikos: " + message.substr(0, 400));
  }
  return solver;
}

void setMueLuUserData(LinearSolver& solver, const Teuchos::RCP<MultiVector>& nullspace,
                      const Teuchos::RCP<MultiVector>& coordinates) {
  if (!solver.usesMueLu) return;
  auto& muelu = solver.parameters->sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("Nullspace", nullspace);
  muelu.set("Coordinates", coordinates);
}

}  // namespace coulomb::solver
