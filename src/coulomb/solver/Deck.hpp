#pragma once
/// @file Deck.hpp
/// @brief The whole input deck: its valid-parameter list (every component's
/// sublist), reading and validation, and the typed run settings.
#include <optional>
#include <ostream>
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/solver/NewtonSolver.hpp"

namespace coulomb::solver {

/// @brief Settings of the run itself (mesh, stepping, Newton, output).
struct RunSettings {
  std::string meshFile;      ///< resolved relative to the deck's folder
  int numberOfSteps = 1;
  double finalTime = 1.0;
  int maximumCutbacks = 5;
  bool extrapolate = true;   ///< predictor: last increment scaled to the step (else the last state)
  /// "Boundary Increment" = Tangent: the prescribed DoFs keep the predictor's
  /// values and the first Newton step takes the rest of their increment
  /// through the tangent (fem/DirichletConstraints.hpp); Imposed: the
  /// predictor carries the prescribed values (the default).
  bool boundaryThroughTangent = false;
  bool reuseConstantTangent = true;  ///< ModelEvaluator::reuseConstantTangent
  NewtonSettings newton;
  std::string outputFile;    ///< resolved relative to the deck's folder
  bool printTimers = false;
  Teuchos::ParameterList nonlinearSolver;  ///< "Nonlinear Solver" (NOX), untouched
  Teuchos::ParameterList linearSolver;     ///< "Linear Solver" (Stratimikos), untouched
};

/// @brief Every parameter Coulomb accepts, with types, defaults, validators and docs.
Teuchos::RCP<const Teuchos::ParameterList> validDeckParameters();

/// @brief Prints validDeckParameters() for `coulomb --help-deck`.
void printDeckHelp(std::ostream& out);

/// @brief Reads and validates the XML deck at `path` (coulomb::Error on any problem).
Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path);

/// @brief Typed run settings of a validated deck read from `deckPath`.
RunSettings parseRunSettings(const Teuchos::ParameterList& deck, const std::string& deckPath);

}  // namespace coulomb::solver
