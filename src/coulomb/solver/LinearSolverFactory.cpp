#include "coulomb/solver/LinearSolverFactory.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/VertexCoarsening.hpp"
#include "coulomb/solver/GatheredDirectSolver.hpp"
#include "coulomb/solver/PMultigrid.hpp"

namespace coulomb::solver {

/// Below this size the default preconditioner is Ifpack2, not MueLu.
constexpr long long kSmallProblemDofs = 5000;

Teuchos::RCP<Teuchos::ParameterList> defaultLinearSolverParameters(int dofsPerNode, long long numGlobalDofs,
                                                                   bool symmetric, long long cornerDofs) {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Linear Solver"));
  p->set("Linear Solver Type", "Belos");
  auto& belos = p->sublist("Linear Solver Types").sublist("Belos");
  if (symmetric) {
    belos.set("Solver Type", "Pseudo Block CG");
    auto& cg = belos.sublist("Solver Types").sublist("Pseudo Block CG");
    cg.set("Convergence Tolerance", 1e-9);
    cg.set("Maximum Iterations", 1000);
    // A finite-strain tangent far from the solution may be indefinite: CG then
    // returns an unconverged direction and Newton decides, instead of throwing.
    cg.set("Assert Positive Definiteness", false);
  } else {
    belos.set("Solver Type", "Pseudo Block GMRES");
    auto& gmres = belos.sublist("Solver Types").sublist("Pseudo Block GMRES");
    gmres.set("Convergence Tolerance", 1e-9);
    gmres.set("Maximum Iterations", 1000);
    // The Krylov basis is the largest allocation of a contact solve (hertz3d_r2:
    // 201 vectors = 107 MB at the peak); contact solves take 10-60 iterations.
    gmres.set("Num Blocks", 100);
  }
  if (numGlobalDofs < kSmallProblemDofs) {
    // Small systems: a multigrid hierarchy would have one or two tiny levels,
    // where per-rank aggregates of one or two nodes give a singular coarse
    // matrix (KLU2 then fails on some ranks only), and a one-level hierarchy
    // would factor the distributed matrix with KLU2, wrong at np >= 2.
    // Symmetric Gauss-Seidel is robust and fast enough here.
    p->set("Preconditioner Type", "Ifpack2");
    auto& ifpack2 = p->sublist("Preconditioner Types").sublist("Ifpack2");
    ifpack2.set("Prec Type", "RELAXATION");
    ifpack2.sublist("Ifpack2 Settings").set("relaxation: type", "Symmetric Gauss-Seidel");
    return p;
  }
  p->set("Preconditioner Type", "MueLu");
  auto& muelu = p->sublist("Preconditioner Types").sublist("MueLu");
  muelu.set("verbosity", "none");
  muelu.set("number of equations", dofsPerNode);
  // Measured on the 67k-DoF hertz3d_r2 bulk system (tests/performance/README.md):
  // plain aggregation with the rigid-body modes sets up 3x faster than
  // smoothed aggregation; a degree-2 Chebyshev smoother makes a solve 0.65 s
  // (45 CG iterations) against 1.06 s (30) with symmetric Gauss-Seidel.
  muelu.set("multigrid algorithm", "unsmoothed");
  if (symmetric) {
    muelu.set("smoother: type", "CHEBYSHEV");
    muelu.sublist("smoother: params").set("chebyshev: degree", 2);
  } else {
    // GMRES needs no symmetric preconditioner: one forward Gauss-Seidel sweep
    // before the coarse correction and one backward sweep after it still make
    // a symmetric V-cycle, with half the sweeps of symmetric Gauss-Seidel on
    // both sides (hertz3d_r2: 1065 against 863 GMRES iterations, 43.7 against
    // 47.5 s).
    //
    // l1 Gauss-Seidel: on more than one rank each rank sweeps its own rows
    // (processor-block Gauss-Seidel); Ifpack2 adds half the magnitudes of a
    // row's entries in other ranks' columns to its diagonal where the
    // diagonal is not dominant over them. The same smoother on one rank (no
    // such entries); at np = 2 hertz3d_r2 takes 405 instead of 423 GMRES
    // iterations (385 at np = 1).
    muelu.set("smoother: pre type", "RELAXATION");
    auto& pre = muelu.sublist("smoother: pre params");
    pre.set("relaxation: type", "Gauss-Seidel");
    pre.set("relaxation: use l1", true);
    muelu.set("smoother: post type", "RELAXATION");
    auto& post = muelu.sublist("smoother: post params");
    post.set("relaxation: type", "Gauss-Seidel");
    post.set("relaxation: backward mode", true);
    post.set("relaxation: use l1", true);
  }
  // Three nodes at least, so that an aggregate carries all rigid-body modes
  // (two nodes lose the rotation about their axis: singular coarse matrix).
  muelu.set("aggregation: min agg size", 3);
  muelu.set("max levels", 10);
  muelu.set("coarse: max size", 2000);
  // The coarsest level is moved to one rank (sub-communicator) before KLU2
  // factors it: distributed KLU2 is wrong in Debian's 13.2 (60 instead of 28
  // iterations at np = 2 on the same system). It has at most "coarse: max
  // size" rows, so "min rows per proc" no smaller than that puts it on one
  // rank; no larger keeps the levels above it distributed (hertz3d_r2 np 2:
  // level 1, 4848 rows, stayed on one rank at 5000: MueLu setup 2.0 -> 1.7 s).
  muelu.set("repartition: enable", true);
  muelu.set("repartition: start level", 1);
  muelu.set("repartition: min rows per proc", 2000);
  muelu.set("repartition: use subcommunicators", true);
  if (cornerDofs >= kSmallProblemDofs) {
    // Quadratic cells: MueLu on the corner nodes under one p-coarsening
    // (PMultigrid.hpp). Two l1 Gauss-Seidel sweeps forward before and two
    // backward after the coarse correction: the HEX20 tube of
    // tube_crush_3d (tube3d.geo r = 2, 23k DoFs) takes 141 GMRES iterations
    // against 284 with MueLu alone, 325 with one sweep each side, 323 with
    // one symmetric sweep; the hertz3d TET10 mesh 386 against 766. Not
    // below 5000 corner DoFs: MueLu would make that level its only one and
    // factor it with KLU2 distributed (wrong in 13.2, see above).
    p->set("Preconditioner Type", std::string(kPMultigridName));
    auto& pmg = p->sublist("Preconditioner Types").sublist(kPMultigridName);
    pmg.set("Coarse MueLu", muelu);
    // Three sweeps each side on MueLu's levels (the corner nodes first): a
    // corner sweep costs about a tenth of a sweep on the quadratic matrix,
    // and the sharper coarse correction saves GMRES iterations (hertz3d
    // HEX20 --ref 1.25: 211 -> 167, 40.4 -> 36.7 s; TET10: 386 -> 317,
    // 51.9 -> 48.7 s; four sweeps: 160 and 315 GMRES, no faster).
    // (GMRES; CG's Chebyshev smoother is left as it is.)
    if (!symmetric)
      for (const char* side : {"smoother: pre params", "smoother: post params"})
        pmg.sublist("Coarse MueLu").sublist(side).set("relaxation: sweeps", 3);
    auto& pre = pmg.sublist("Pre Smoother");
    pre.set("relaxation: type", "Gauss-Seidel");
    pre.set("relaxation: sweeps", 2);
    pre.set("relaxation: use l1", true);
    auto& post = pmg.sublist("Post Smoother");
    post.setParameters(pre);
    post.set("relaxation: backward mode", true);
  }
  return p;
}

namespace {

/// A user who names any MueLu smoother key chose the smoother: the default
/// smoother keys must not be merged beside it. (MueLu gives "smoother: pre/post
/// type" precedence over "smoother: type", so a merged default pre/post pair
/// silently replaced a deck's "smoother: type" = RILUK.)
void keepUserSmoother(const Teuchos::ParameterList& user, Teuchos::ParameterList& defaults) {
  const auto* userTypes = user.getPtr<Teuchos::ParameterList>("Preconditioner Types");
  if (!userTypes || !userTypes->isSublist("MueLu") || !defaults.isSublist("Preconditioner Types")) return;
  auto& muelu = defaults.sublist("Preconditioner Types").sublist("MueLu");
  const auto& userMuelu = userTypes->sublist("MueLu");
  auto isSmootherKey = [](const std::string& name) { return name.rfind("smoother:", 0) == 0; };
  bool userSetSmoother = false;
  for (auto it = userMuelu.begin(); it != userMuelu.end(); ++it) userSetSmoother |= isSmootherKey(userMuelu.name(it));
  if (!userSetSmoother) return;
  std::vector<std::string> names;
  for (auto it = muelu.begin(); it != muelu.end(); ++it)
    if (isSmootherKey(muelu.name(it))) names.push_back(muelu.name(it));
  for (const auto& name : names) muelu.remove(name);
}

/// The defaults fill in what the deck leaves out wherever the deck's choice
/// is the default's: a deck that names "Belos" and "MueLu" (the defaults)
/// gets the same tuned MueLu and GMRES keys as one that names nothing
/// (hertz3d_r2: 16.4 s against 27.9 s and 446 MB with MueLu's own defaults).
/// A deck that picks another solver, Krylov method or preconditioner (or
/// Ifpack2 method) gets exactly what it wrote for that choice; a deck that
/// names only "Belos" gets the default Krylov method (CG, or GMRES for a
/// nonsymmetric contact tangent), not Stratimikos' own.
void fillDefaultsOfSameChoices(const Teuchos::ParameterList& defaults, Teuchos::ParameterList& user) {
  auto sameChoice = [](const Teuchos::ParameterList& d, Teuchos::ParameterList& u, const std::string& key) {
    if (!u.isParameter(key)) u.set(key, d.get<std::string>(key));
    return u.get<std::string>(key) == d.get<std::string>(key);
  };
  if (!sameChoice(defaults, user, "Linear Solver Type")) return;
  const auto& solverType = defaults.get<std::string>("Linear Solver Type");
  const auto& defaultSolver = defaults.sublist("Linear Solver Types").sublist(solverType);
  auto& userSolver = user.sublist("Linear Solver Types").sublist(solverType);
  if (sameChoice(defaultSolver, userSolver, "Solver Type")) {
    const auto& krylov = defaultSolver.get<std::string>("Solver Type");
    userSolver.sublist("Solver Types").sublist(krylov).setParametersNotAlreadySet(
        defaultSolver.sublist("Solver Types").sublist(krylov));
  }
  if (!sameChoice(defaults, user, "Preconditioner Type")) {
    // Plain MueLu named where the default is P-Multigrid (quadratic cells):
    // the tuned MueLu keys all the same.
    const auto& types = defaults.sublist("Preconditioner Types");
    if (user.get<std::string>("Preconditioner Type") == "MueLu" && types.isSublist("MueLu"))
      user.sublist("Preconditioner Types").sublist("MueLu").setParametersNotAlreadySet(types.sublist("MueLu"));
    return;
  }
  const auto& preconditioner = defaults.get<std::string>("Preconditioner Type");
  const auto& defaultPrec = defaults.sublist("Preconditioner Types").sublist(preconditioner);
  auto& userPrec = user.sublist("Preconditioner Types").sublist(preconditioner);
  // Ifpack2 names its method inside ("Prec Type"): ILUT gets no relaxation keys.
  if (defaultPrec.isParameter("Prec Type") && !sameChoice(defaultPrec, userPrec, "Prec Type")) return;
  userPrec.setParametersNotAlreadySet(defaultPrec);
}

}  // namespace

LinearSolver buildLinearSolver(const Teuchos::ParameterList& user, int dofsPerNode,
                               long long numGlobalDofs, bool symmetric, long long cornerDofs) {
  LinearSolver solver;
  solver.parameters = Teuchos::rcp(new Teuchos::ParameterList(user));
  solver.parameters->setName("Linear Solver");
  const auto defaults = defaultLinearSolverParameters(dofsPerNode, numGlobalDofs, symmetric, cornerDofs);
  keepUserSmoother(user, *defaults);
  try {
    fillDefaultsOfSameChoices(*defaults, *solver.parameters);
  } catch (const Teuchos::Exceptions::InvalidParameter& e) {  // e.g. a 'Solver Type' that is not a string
    throw Error("deck: 'Linear Solver': " + std::string(e.what()).substr(0, 300));
  }
  const std::string type = solver.parameters->get<std::string>("Linear Solver Type");
  solver.isDirect = type == "Amesos2" || type == "Amesos";
  const std::string preconditioner = solver.parameters->isParameter("Preconditioner Type")
                                         ? solver.parameters->get<std::string>("Preconditioner Type")
                                         : std::string();
  solver.usesMueLu = preconditioner == "MueLu";
  solver.usesPMultigrid = preconditioner == kPMultigridName;

  Stratimikos::DefaultLinearSolverBuilder builder;
  Stratimikos::enableMueLu<LocalOrdinal, GlobalOrdinal, typename CrsMatrix::node_type>(builder);
  using Ifpack2Factory = Thyra::Ifpack2PreconditionerFactory<CrsMatrix>;
  builder.setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>, Ifpack2Factory>(), "Ifpack2");
  builder.setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>, PMultigridFactory>(), kPMultigridName);
  try {
    builder.setParameterList(solver.parameters);
    // "Amesos2" is the direct solve gathered on one rank (GatheredDirectSolver.hpp), correct at any rank
    // count. Stratimikos 13.2 already holds its own (distributed, wrong at np > 1) "Amesos2" strategy and
    // refuses a second factory of that name ("strings[4] = "Amesos2" is a duplicate"), so it is made here.
    if (type == "Amesos2") {
      auto direct = Teuchos::rcp(new GatheredDirectSolverFactory());
      direct->setParameterList(Teuchos::sublist(Teuchos::sublist(solver.parameters, "Linear Solver Types"), "Amesos2"));
      solver.factory = direct;
    } else {
      solver.factory = builder.createLinearSolveStrategy("");
    }
  } catch (const std::exception& e) {
    std::string message = e.what();
    for (auto& c : message)
      if (c == '\n') c = ' ';
    throw Error("deck: 'Linear Solver' is not accepted by Stratimikos: " + message.substr(0, 400));
  }
  return solver;
}

void setMueLuUserData(LinearSolver& solver, const Teuchos::RCP<MultiVector>& nullspace,
                      const Teuchos::RCP<MultiVector>& coordinates, const fem::VertexCoarsening* vertices) {
  auto& types = solver.parameters->sublist("Preconditioner Types");
  if (solver.usesMueLu) {
    auto& muelu = types.sublist("MueLu");
    muelu.set("Nullspace", nullspace);
    muelu.set("Coordinates", coordinates);
  }
  if (solver.usesPMultigrid) {
    COULOMB_CHECK(vertices != nullptr && !vertices->prolongator.is_null(), "P-Multigrid needs the corner level");
    auto& pmg = types.sublist(kPMultigridName);
    pmg.set("Prolongator", vertices->prolongator);
    pmg.set("Coarse Nullspace", vertices->nullspace);
    pmg.set("Coarse Coordinates", vertices->coordinates);
  }
}

}  // namespace coulomb::solver
