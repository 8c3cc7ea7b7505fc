#pragma once
/// @file ExodusWriter.hpp
/// @brief Writes a GlobalMesh and nodal/global result time steps to an Exodus II file.
///
/// Why Exodus: ParaView (5.11 and later) and the SEACAS tools read it
/// directly, with block/set names, and the results sit next to the mesh the
/// user gave us. Only rank 0 constructs a writer: the caller gathers the
/// distributed results into global node order first.
///
/// Files are netCDF-3 "64-bit offset" (Exodus' classic large-model format:
/// files beyond 2 GiB, up to 4 GiB per variable, i.e. ~500M nodes) with
/// 32-bit integers, exact up to 2^31 - 1 nodes and elements. Why not
/// netCDF-4/HDF5 with 64-bit integers: the Debian exodusII 6.02 corrupts
/// node/side set lists with EX_BULK_INT64_DB (stored as ushort), and HDF5's
/// file lock keeps ParaView and other readers out of a file while the run
/// still writes it; a 64-bit-offset file can be read after every step.
/// The exodusII headers stay out of this header: the open file is an int.
#include <string>
#include <vector>

#include "coulomb/mesh/GlobalMesh.hpp"

namespace coulomb::io {

/// @brief Throws coulomb::Error naming the folder of `path` when it is
/// missing or not writable (what a failed create means to a user).
void checkOutputFolder(const std::string& path);

class ExodusWriter {
public:
  /// Creates @p path (overwriting it), writes the title, coordinates, element
  /// blocks (with names), node sets and side sets (with names; Exodus
  /// numbering is 1-based in the file) and checks the nodal and global
  /// variable names; the variables are declared in the file with the first
  /// writeStep() (ParaView 5.11 crashes on files that declare variables but
  /// hold no step). Name vector fields "<name>_x", "<name>_y"[, "<name>_z"]:
  /// ParaView then shows one 3-component array ("<name>_" in its classic
  /// Exodus reader, "<name>" in the IOSS reader).
  /// @throws coulomb::Error naming @p path if the file cannot be written or the
  /// mesh is inconsistent (duplicate ids, node numbers out of range, ...).
  ExodusWriter(const std::string& path, const mesh::GlobalMesh& mesh, std::vector<std::string> nodalVariableNames,
               std::vector<std::string> globalVariableNames, const std::string& title = "Coulomb result");
  ~ExodusWriter();  ///< closes the file; never throws

  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;
  ExodusWriter(ExodusWriter&& other) noexcept;
  ExodusWriter& operator=(ExodusWriter&& other) noexcept;

  /// Appends one time step: nodalValues[v] holds numNodes() values of
  /// variable v in global node order, globalValues[g] one value per global
  /// variable. Flushes the file afterwards so that a reader (ParaView while
  /// the run goes on, or a run that dies later) sees only complete steps.
  /// @throws coulomb::Error naming the path on wrong sizes, a closed file or
  /// a failed write.
  void writeStep(double time, const std::vector<std::vector<double>>& nodalValues,
                 const std::vector<double>& globalValues);

  int numStepsWritten() const { return numSteps_; }
  const std::string& path() const { return path_; }
  long long numNodes() const { return numNodes_; }
  const std::vector<std::string>& nodalVariableNames() const { return nodalNames_; }
  const std::vector<std::string>& globalVariableNames() const { return globalNames_; }

  /// Closes the file. Idempotent; afterwards writeStep() throws.
  void close();

private:
  void writeMesh(const mesh::GlobalMesh& mesh, const std::string& title);
  void declareVariables();
  void check(int status, const std::string& what) const;

  std::string path_;
  int fileId_ = -1;
  long long numNodes_ = 0;
  int numSteps_ = 0;
  bool variablesDeclared_ = false;
  std::vector<std::string> nodalNames_;
  std::vector<std::string> globalNames_;
};

}  // namespace coulomb::io
