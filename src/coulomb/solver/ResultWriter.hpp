#pragma once
/// @file ResultWriter.hpp
/// @brief Writes converged steps to one Exodus II file: rank 0 gathers the
/// nodal fields of all ranks and writes them (a single file, whatever the
/// number of ranks). The file is written as "<name>.part" and renamed to its
/// final name only when the run completes, so a failed run never leaves a
/// result that looks complete.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::io {
class ExodusWriter;
}

namespace coulomb::solver {

/// @brief One nodal field: owned-node MultiVector, one column per component.
struct NodalField {
  std::vector<std::string> names;  ///< one per column, e.g. displacement_x
  Teuchos::RCP<const MultiVector> values;
};

class ResultWriter {
public:
  /// Collective. `globalNames`: names of the global variables of every step.
  ResultWriter(const std::string& path, const mesh::Mesh& mesh, const Teuchos::RCP<const Map>& ownedNodeMap,
               std::vector<std::string> nodalNames, std::vector<std::string> globalNames);
  ~ResultWriter();

  /// Collective: gathers and appends one step.
  void writeStep(double time, const std::vector<NodalField>& fields, const std::vector<double>& globals);
  /// Collective: closes and renames "<path>.part" to `path`.
  void finish();
  /// Collective: closes "<path>.part" and keeps it under that name (a run
  /// stopped before its end: the file holds the steps written so far).
  void abandon();

  static std::string partialPath(const std::string& path) { return path + ".part"; }

private:
  void close(bool complete);

  std::string path_;
  const mesh::Mesh& mesh_;
  Teuchos::RCP<const Map> rootNodeMap_;
  Teuchos::RCP<const Import> gather_;
  std::unique_ptr<io::ExodusWriter> writer_;  // rank 0 only
};

}  // namespace coulomb::solver
