#include "coulomb/solver/Deck.hpp"

#include <filesystem>
#include <limits>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/core/Error.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/io/Choices.hpp"
#include "coulomb/io/ParameterValidation.hpp"
#include "coulomb/io/RangeValidator.hpp"

namespace coulomb::solver {

using Teuchos::ParameterList;
using Teuchos::rcp;

namespace {

// The deck's choices of the run, each declared once (io::Choices).
const io::Choices<bool> kPredictors{{"Extrapolate", true}, {"Previous", false}};  ///< true: extrapolate
const io::Choices<bool> kBoundaryIncrements{{"Tangent", true}, {"Imposed", false}};  ///< true: through the tangent
const io::Choices<bool> kLinearTolerances{{"Adaptive", true}, {"Fixed", false}};  ///< true: adaptive

template <typename T>
Teuchos::RCP<Teuchos::EnhancedNumberValidator<T>> range(T lo, T hi) {
  return rcp(new Teuchos::EnhancedNumberValidator<T>(lo, hi));
}

std::string resolve(const std::string& file, const std::string& deckPath) {
  const std::filesystem::path p(file);
  if (p.is_absolute()) return file;
  return (std::filesystem::path(deckPath).parent_path() / p).lexically_normal().string();
}

}  // namespace

Teuchos::RCP<const ParameterList> validDeckParameters() {
  static Teuchos::RCP<const ParameterList> cached = [] {
    auto valid = rcp(new ParameterList("Coulomb"));
    ParameterList& mesh = valid->sublist("Mesh", false, std::string(io::kRequired) + "The Exodus II mesh");
    mesh.set("File", "", std::string(io::kRequired) + "Exodus II mesh file, relative to the deck's folder");
    fem::addValidModelParameters(*valid);
    contact::addValidContactParameters(*valid);

    ParameterList& stepping = valid->sublist("Load Stepping", false, "Pseudo-time load stepping from t = 0");
    stepping.set("Number of Steps", 1, "equal steps to reach the final time", range<int>(1, 1000000));
    stepping.set("Final Time", 1.0, "pseudo time of the last step", io::positive());
    stepping.set("Maximum Cutbacks", 5, "times a step may be halved in a row and retried when Newton fails (never below Final Time / Number of Steps / 2^this); sub-steps land on every step end and load-function knot", range<int>(0, 50));
    stepping.set("Predictor", "Extrapolate",
                 "first Newton iterate of a step: Extrapolate (the last step's increment, scaled to this step) or "
                 "Previous (the last converged state)",
                 kPredictors.validator());
    stepping.set("Boundary Increment", "Imposed",
                 "how a step's first iterate meets new prescribed values: Imposed (they are written into the "
                 "predictor, and the interior follows from the second iterate on: a large boundary increment can "
                 "invert the elements next to the boundary first) or Tangent (the prescribed DoFs keep the "
                 "predictor's values and the first Newton step moves them the rest of the way together with the "
                 "interior, through the tangent, as a linear solve would)",
                 kBoundaryIncrements.validator());

    ParameterList& newton = valid->sublist("Newton", false, "Newton convergence");
    const NewtonSettings defaults;
    newton.set("Maximum Iterations", defaults.maximumIterations, "iterations before a step counts as failed",
               range<int>(1, 1000));
    newton.set("Relative Tolerance", defaults.relativeTolerance, "converged when ||f|| <= tol x the iterate's force scale max(||reactions||, ||loads||, "
               "||contact forces||) (or ||f_0|| of the step when larger; never below 1000 machine eps x it)",
               range<double>(0.0, 1.0));
    newton.set("Absolute Tolerance", defaults.absoluteTolerance, "also converged when ||f|| <= tol [force]; 0: no absolute test",
               io::nonNegative());
    newton.set("Linear Tolerance", "Adaptive",
               "Krylov tolerance of each Newton solve: Adaptive (as loose as the iterate can use, "
               "solver/LinearTolerance.hpp) or Fixed (NOX's 'Direction'/'Newton'/'Linear Solver'/'Tolerance', "
               "default 1e-10, or its forcing term); a deck that sets either NOX key gets Fixed",
               kLinearTolerances.validator());
    newton.set("Maximum Linear Tolerance", defaults.linearTolerance.maximum,
               "loosest relative Krylov tolerance of the Adaptive choice", range<double>(1e-10, 0.5));
    newton.set("Reuse Constant Tangent", true,
               "linear elastic model with contact (condensed): the bulk stiffness K, which does not change, is taken "
               "back from the last Jacobian instead of being assembled again (the same values bit for bit); false "
               "assembles it at every Newton iteration");
    newton.set("Reuse Preconditioner", defaults.reusePreconditioner,
               "with contact and an iterative linear solver: a Newton iteration whose contact set (active nodes, "
               "stick/slip) did not change since the last solve of the load step, whose matrix has the same "
               "structure and whose last solve converged keeps the last built preconditioner instead of building a "
               "new one (never in the first solve of a step); false builds one at every Newton iteration");

    ParameterList& output = valid->sublist("Output", false, "Results");
    output.set("File", "", "Exodus II result file, relative to the deck's folder (default: deck name with .e)");
    output.set("Print Timers", false, "print Teuchos timers (assembly, MueLu setup, Belos solve...) at the end");

    valid->sublist("Nonlinear Solver", false,
                   std::string(io::kPassthrough) + "NOX parameters, passed to NOX::Solver::buildSolver as given");
    valid->sublist("Linear Solver", false,
                   std::string(io::kPassthrough) + "Stratimikos parameters (Belos, MueLu, Ifpack2, Amesos2), as given");
    return Teuchos::RCP<const ParameterList>(valid);
  }();
  return cached;
}

void printDeckHelp(std::ostream& out) {
  out << "Coulomb input deck: a Teuchos XML ParameterList. Sublists named '*' stand for\n"
         "sublists you name yourself (one per material, block, condition, function).\n"
         "[required] marks required entries; [passthrough] lists go to Trilinos unchanged.\n\n";
  validDeckParameters()->print(out, Teuchos::ParameterList::PrintOptions().showDoc(true).showTypes(true).indent(2));
}

Teuchos::RCP<ParameterList> readDeck(const std::string& path) {
  auto deck = io::readXmlDeck(path);
  io::validateParameters(*deck, *validDeckParameters());
  return deck;
}

RunSettings parseRunSettings(const ParameterList& deck, const std::string& deckPath) {
  const ParameterList& valid = *validDeckParameters();
  const ParameterList empty;
  auto sub = [&](const char* name) -> const ParameterList& { return deck.isSublist(name) ? deck.sublist(name) : empty; };
  RunSettings run;
  run.meshFile = resolve(deck.sublist("Mesh").get<std::string>("File"), deckPath);
  const auto& stepping = valid.sublist("Load Stepping");
  run.numberOfSteps = io::valueOrDefault<int>(sub("Load Stepping"), stepping, "Number of Steps");
  run.finalTime = io::valueOrDefault<double>(sub("Load Stepping"), stepping, "Final Time");
  run.maximumCutbacks = io::valueOrDefault<int>(sub("Load Stepping"), stepping, "Maximum Cutbacks");
  run.extrapolate = kPredictors.value(io::valueOrDefault<std::string>(sub("Load Stepping"), stepping, "Predictor"));
  run.boundaryThroughTangent =
      kBoundaryIncrements.value(io::valueOrDefault<std::string>(sub("Load Stepping"), stepping, "Boundary Increment"));
  const auto& newton = valid.sublist("Newton");
  run.newton.maximumIterations = io::valueOrDefault<int>(sub("Newton"), newton, "Maximum Iterations");
  run.newton.relativeTolerance = io::valueOrDefault<double>(sub("Newton"), newton, "Relative Tolerance");
  run.newton.absoluteTolerance = io::valueOrDefault<double>(sub("Newton"), newton, "Absolute Tolerance");
  run.newton.linearTolerance.maximum = io::valueOrDefault<double>(sub("Newton"), newton, "Maximum Linear Tolerance");
  run.reuseConstantTangent = io::valueOrDefault<bool>(sub("Newton"), newton, "Reuse Constant Tangent");
  run.newton.reusePreconditioner = io::valueOrDefault<bool>(sub("Newton"), newton, "Reuse Preconditioner");
  const bool userFixesLinearTolerance = noxSetsLinearTolerance(sub("Nonlinear Solver"));
  const bool adaptive = kLinearTolerances.value(io::valueOrDefault<std::string>(sub("Newton"), newton, "Linear Tolerance"));
  if (userFixesLinearTolerance && sub("Newton").isParameter("Linear Tolerance") && adaptive)
    throw Error("deck: 'Newton/Linear Tolerance' = Adaptive contradicts the NOX 'Nonlinear Solver/Direction/Newton' "
                "tolerance or forcing term the deck sets");
  run.newton.linearTolerance.adaptive = adaptive && !userFixesLinearTolerance;
  std::string output = io::valueOrDefault<std::string>(sub("Output"), valid.sublist("Output"), "File");
  if (output.empty()) output = std::filesystem::path(deckPath).filename().replace_extension(".e").string();
  run.outputFile = resolve(output, deckPath);
  run.printTimers = io::valueOrDefault<bool>(sub("Output"), valid.sublist("Output"), "Print Timers");
  run.nonlinearSolver = sub("Nonlinear Solver");
  run.linearSolver = sub("Linear Solver");
  return run;
}

}  // namespace coulomb::solver
