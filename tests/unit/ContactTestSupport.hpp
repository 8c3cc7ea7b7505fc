#pragma once
// Helpers of the contact deck tests (MPI): shipped decks edited as text,
// runs with their Exodus results on rank 0.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "TestSupport.hpp"
#include "coulomb/io/ExodusResults.hpp"
#include "coulomb/solver/Simulation.hpp"

namespace coulomb::test {

/// Path of a shipped deck xml/<name>.xml.
std::string deckPath(const std::string& name);

/// The text of a shipped deck with its mesh path made absolute, to be edited.
struct ShippedDeck {
  std::string text;
  ShippedDeck(const std::string& name, const std::string& mesh);
  /// Replaces the first occurrence of `from` (which must be there: a failed
  /// test assertion otherwise).
  void replace(const std::string& from, const std::string& to);
  /// Adds a "Newton" list with "Linear Tolerance" = Fixed (every linear
  /// system solved to NOX's 1e-10): for tests of Newton's rate, which
  /// measure the tangent, not the adaptive Krylov tolerance. The deck must not
  /// have a "Newton" list already.
  void fixLinearTolerance();
  /// Adds a "Newton" list for a check to round-off: 'Relative Tolerance' =
  /// 1e-12 of the force scale, 'Linear Tolerance' = Fixed. The deck must not
  /// have a "Newton" list already.
  void solveToRoundOff();
  /// Adds 'Newton/<name>' = `value` (bool). The deck must not have a "Newton" list already.
  void setNewtonFlag(const std::string& name, bool value);
};

struct ContactRun {
  std::unique_ptr<solver::Simulation> simulation;
  solver::RunSummary summary;
  io::ExodusResults results;  ///< rank 0 only
};

/// Runs a shipped deck (results in a scratch folder).
ContactRun runDeck(const std::string& name);
/// Runs the deck text `text` written to <scratch name>/deck.xml.
ContactRun runDeckText(const std::string& name, const std::string& text);

/// Writes (rank 0) the shipped 3D contact patch mesh contact_patch3d.e with
/// the punch's nodes on its face x = 0 as node set `punch_left` to `path`
/// (the bodies' meshes are separate: the base's nodes at the same points are
/// not in it); all ranks wait for it. Returns (rank 0) how many of those
/// nodes lie on the interface z = 0.5.
int writePatch3dWithPunchLeft(const std::string& path);

/// Writes (rank 0) the shipped 2D contact patch mesh contact_patch2d.e with
/// the punch's nodes moved by `punchShift` and then every node by
/// `allShift` to `path`; all ranks wait for it.
void writeMovedPatch2d(const std::string& path, const std::array<double, 2>& punchShift,
                       const std::array<double, 2>& allShift, const std::string& title);

/// Writes (rank 0) contact_patch2d.e with the punch's x mapped to x²
/// (its 7 faces along the interface graded from 1/49 to 13/49 long); all
/// ranks wait for it.
void writeGradedPatch2d(const std::string& path);

/// A contact pair of assemblyDeck; `options`: more parameters of its sublist (XML).
struct AssemblyPair {
  std::string name, slave, master, options = "";
};
/// A steel deck (E = 210000, nu = 0.3, plane strain in 2D) on the shipped
/// mesh `mesh`: `blocks` all steel, u = 0 along `axis` on `bottom`, u =
/// -delta along it on `top` in 2 steps, u = 0 on each (node set, component)
/// of `fixed` (also the condition's name), and the pairs (the many-bodies
/// tests, contact_many_bodies_mpi.cpp).
std::string assemblyDeck(const std::string& mesh, const std::vector<std::string>& blocks,
                         const std::vector<std::pair<std::string, std::string>>& fixed, double delta,
                         const std::vector<AssemblyPair>& pairs, const std::string& axis = "y");

/// The patch tests' contact checks (rank 0, pair `punch`, load on `top`):
/// `active` nodes in contact, each at the pressure `current` (to 1e-8 of
/// it), and the contact force and the reaction along `axis` equal to `force`.
void expectUniformPressure(const ContactRun& run, double current, int active, const std::string& axis, double force);

double lastGlobal(const io::ExodusResults& r, const std::string& name);
const std::vector<double>& lastNodal(const io::ExodusResults& r, const std::string& name);
/// max |a - b| of nodal `field` over every step, relative to max |a| (a
/// failed assertion if the step counts differ).
double nodalDifference(const io::ExodusResults& a, const io::ExodusResults& b, const std::string& field);
/// The same relative to the largest |a| of any of `scaleFields` (e.g. a
/// displacement component against every component).
double nodalDifference(const io::ExodusResults& a, const io::ExodusResults& b, const std::string& field,
                       const std::vector<std::string>& scaleFields);

}  // namespace coulomb::test
