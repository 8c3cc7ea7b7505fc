#pragma once
/// @file RunReport.hpp
/// @brief What a run tells a person: the problem's size (`coulomb --check`
/// and the start of a run) and the closing summary (what was solved, steps,
/// per contact pair the peak pressure and the final Q/P against mu, where
/// the result is).
#include <ostream>
#include <string>
#include <vector>

namespace coulomb::solver {

/// @brief One contact pair as a person describes it.
struct PairDescription {
  std::string name, slave, master;
  std::string formulation;  ///< ALM, Penalty, ...
  std::string law;          ///< "frictionless", "Coulomb friction mu = 0.3", ...
  double mu = -1;           ///< Coulomb's uniform mu; < 0: none (frictionless, Tresca, a nodal field)
  bool frictional = false;
  long long slaveFaces = 0, masterFaces = 0, slaveNodes = 0;
};

/// @brief The size of a problem as read (the same on every rank).
struct ProblemSize {
  int dimension = 3;
  long long nodes = 0, elements = 0, dofs = 0;
  std::vector<std::string> blocks;
  std::vector<PairDescription> pairs;
  int numberOfSteps = 1;
  double finalTime = 1;
  std::string meshFile, outputFile;
};

/// @brief One contact pair over a run: updated after every converged step.
struct PairRecord {
  double peakPressure = 0, peakTime = 0;  ///< largest nodal contact pressure of any step, and when
  double normalForce = 0, tangentialForce = 0;  ///< P and Q of the last step (magnitudes)
  long long active = 0, stick = 0;               ///< slave nodes in contact / sticking at the last step
};

/// @brief `coulomb --check`: the problem size, one fact a line.
void printProblemSize(std::ostream& out, const ProblemSize& size);

/// @brief The end of a run: what was solved, steps, per pair the peak
/// pressure and Q/P against mu at the last step, and the result file.
void printRunSummary(std::ostream& out, const ProblemSize& size, const std::vector<PairRecord>& pairs, int steps,
                     int cutbacks, double finalTime, double wallSeconds);

/// @brief "stick or partial slip" / "gross slip" from Q/P against mu (the
/// words of the summary; 1 % below mu counts as sliding: the cone is met to
/// the Newton tolerance, not exactly).
std::string slidingState(double ratio, double mu);

}  // namespace coulomb::solver
