#pragma once
/// @file Simulation.hpp
/// @brief One run of a deck: mesh, DoFs, assembly, linear and nonlinear
/// solvers, load stepping with cutback, and result output.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/solver/Deck.hpp"
#include "coulomb/solver/Progress.hpp"
#include "coulomb/solver/RunReport.hpp"

namespace coulomb::mesh {
class Mesh;
}
namespace coulomb::fem {
class DofMap;
class Assembler;
}

namespace coulomb::contact {
class ContactModel;
}

namespace coulomb::solver {

struct NewtonReport;

/// @brief What a finished run reports (the same on every rank).
struct RunSummary {
  int steps = 0;               ///< converged steps written
  int cutbacks = 0;
  int newtonIterations = 0;    ///< over converged steps
  int linearIterations = 0;
  double wallSeconds = 0;
  long long dofs = 0;
  std::vector<double> stepTimes;   ///< pseudo time of each converged step
  std::vector<int> stepNewtonIterations;
  std::vector<std::vector<double>> stepResidualNorms;  ///< Newton residual sequence per converged step
  std::vector<std::vector<long long>> stepActiveNodes;   ///< contact: active nodes per Newton iteration
  std::vector<std::vector<long long>> stepChangedNodes;  ///< contact: nodes that changed state, per iteration
  std::vector<std::vector<long long>> stepStickSlipChanged;  ///< frictional contact: stick <-> slip changes (else -1)
  /// contact: 1 where the solve that led to the iterate kept the last preconditioner (row 0: 0)
  std::vector<std::vector<int>> stepPreconditionerKept;
  /// contact, P-Multigrid: 1 where that solve built new smoothers under the last corner level
  std::vector<std::vector<int>> stepCoarseLevelKept;
  std::vector<long long> pairMaximumActive;              ///< contact: most active nodes of each pair in a step
  std::vector<PairRecord> pairs;  ///< contact: per pair, peak pressure and the last step's forces (the summary's)
};

class Simulation {
public:
  /// Reads and validates the deck and the mesh, builds all components.
  /// Collective; throws coulomb::Error on every rank on bad input.
  /// `outputOverride` (if not empty) replaces the deck's "Output/File",
  /// `meshOverride` its "Mesh/File" (both as given, relative to the caller).
  Simulation(const std::string& deckPath, const Teuchos::RCP<const Teuchos::Comm<int>>& comm, std::ostream* console,
             const std::string& outputOverride = "", const std::string& meshOverride = "");
  ~Simulation();

  /// Runs all load steps and writes the result. Collective.
  RunSummary run();

  /// Console detail of run() (Normal unless set).
  void setVerbosity(Verbosity verbosity);
  /// Nodes, elements, DoFs, blocks, contact pairs with their face counts,
  /// load stepping and files, as read (`coulomb --check`, the run's summary).
  ProblemSize problemSize() const;
  /// Collective: the result file's folder exists and is writable (what run()
  /// needs first; `coulomb --check` asks without writing); coulomb::Error otherwise.
  void checkOutputFolder() const;

  /// The converged displacement (owned map) after run().
  const Vector& displacement() const { return *displacement_; }
  const fem::DofMap& dofMap() const { return *dofs_; }
  const mesh::Mesh& mesh() const { return *mesh_; }
  const RunSettings& settings() const { return settings_; }
  /// The bulk assembler (tests check its Jacobian against finite differences).
  fem::Assembler& assembler() { return *assembler_; }
  /// Total reaction force per component on the named node set at the last step.
  std::vector<double> reactionTotal(const std::string& nodeSet) const;
  /// Contact in the saddle-point form: the converged (u, z) on
  /// ContactModel::saddlePointMap() after run(); else null.
  const Vector* saddlePointState() const { return saddlePointState_.get(); }
  /// The contact model (null without a "Contact" sublist with pairs).
  contact::ContactModel* contact() { return contact_.get(); }

private:
  struct Solvers;
  void writeStep(double time, const std::vector<double>& stepGlobals);
  /// Console line per contact pair after a converged step; records the active counts.
  void reportContact(RunSummary& summary, double time);
  /// One Newton solve of a step from `trial` (displacements; the multipliers
  /// too in the saddle-point form, kept in saddlePointState_).
  NewtonReport solve(Vector& trial);

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::ostream* console_;
  Verbosity verbosity_ = Verbosity::Normal;
  RunSettings settings_;
  std::unique_ptr<mesh::Mesh> mesh_;
  std::unique_ptr<fem::DofMap> dofs_;
  std::unique_ptr<fem::Assembler> assembler_;
  std::unique_ptr<contact::ContactModel> contact_;
  std::unique_ptr<Solvers> solvers_;
  Teuchos::RCP<Vector> displacement_;
  Teuchos::RCP<Vector> reactions_;
  Teuchos::RCP<Vector> saddlePointState_;  ///< contact saddle-point form: converged (u, z)
  std::vector<std::string> reactionSets_;  ///< node sets whose reaction totals are written
  std::vector<double> loadKnots_;          ///< times where a load function's slope changes
};

}  // namespace coulomb::solver
