// The `coulomb` executable: parse arguments, run one deck. All work is in
// the library (coulomb::solver::Simulation); this file only reports errors.
#include <mpi.h>

#include <cstring>
#include <string>
#include <iostream>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#include <Trilinos_version.h>

#include "CoulombVersion.hpp"

#include "coulomb/core/Error.hpp"
#include "coulomb/core/Interrupt.hpp"
#include "coulomb/core/UserMessage.hpp"
#include "coulomb/solver/Deck.hpp"
#include "coulomb/solver/RunReport.hpp"
#include "coulomb/solver/Simulation.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: coulomb DECK.xml [-o RESULT.e] [-m|--mesh MESH.e] [--quiet|--verbose]\n"
         "                                    run an input deck (result: the deck's Output/File, or DECK.e\n"
         "                                    next to the deck; -o overrides it; --mesh replaces Mesh/File)\n"
         "                                    console: --quiet one line per load step; default a header and\n"
         "                                    a result line per step; --verbose also every Newton iteration\n"
         "       coulomb --check DECK.xml [-m MESH.e]\n"
         "                                    read and validate the deck and the mesh, print the problem size;\n"
         "                                    solves nothing, writes no result\n"
         "       coulomb --help-deck         list every deck parameter (type, default, doc)\n"
         "       coulomb --version           Coulomb's and Trilinos' versions\n"
         "       mpirun -np N coulomb DECK.xml\n";
}

/// The command line, parsed: flags in any order, one deck.
struct Arguments {
  std::string deck, output, mesh;
  bool check = false, help = false, helpDeck = false, version = false;
  coulomb::solver::Verbosity verbosity = coulomb::solver::Verbosity::Normal;
  std::string error;  ///< why the line is not understood (usage follows)
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "-o" || option == "-m" || option == "--mesh") {
      if (i + 1 >= argc) {
        a.error = option + " needs a file";
        return a;
      }
      (option == "-o" ? a.output : a.mesh) = argv[++i];
    } else if (option == "--check") a.check = true;
    else if (option == "--quiet" || option == "-q") a.verbosity = coulomb::solver::Verbosity::Quiet;
    else if (option == "--verbose" || option == "-v") a.verbosity = coulomb::solver::Verbosity::Verbose;
    else if (option == "--help" || option == "-h") a.help = true;
    else if (option == "--help-deck") a.helpDeck = true;
    else if (option == "--version") a.version = true;
    else if (!option.empty() && option[0] == '-') {
      a.error = "unknown option '" + option + "'";
      return a;
    } else if (!a.deck.empty()) {
      a.error = "one deck at a time (got '" + a.deck + "' and '" + option + "')";
      return a;
    } else a.deck = option;
  }
  if (a.deck.empty() && !a.help && !a.helpDeck && !a.version) a.error = "no deck given";
  return a;
}

void printVersion(std::ostream& out) {
  out << "coulomb " << COULOMB_VERSION << " (git " << COULOMB_GIT_VERSION << ")\n"
      << "Trilinos " << TRILINOS_VERSION_STRING << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  // SIGINT/SIGTERM stop the run cleanly (converged steps kept, exit 1); a
  // second one ends it at once. First of all: a signal during start-up too.
  coulomb::installInterruptHandlers();
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  const Arguments arguments = parse(argc, argv);
  if (arguments.help) {
    if (root) usage(std::cout);
    return 0;
  }
  if (arguments.version) {
    if (root) printVersion(std::cout);
    return 0;
  }
  if (arguments.helpDeck) {
    if (root) coulomb::solver::printDeckHelp(std::cout);
    return 0;
  }
  if (!arguments.error.empty()) {
    if (root) {
      std::cerr << "coulomb: " << arguments.error << "\n";
      usage(std::cerr);
    }
    return 2;
  }
  try {
    coulomb::solver::Simulation simulation(arguments.deck, comm, &std::cout, arguments.output, arguments.mesh);
    if (arguments.check) {
      // Everything a run reads and checks before its first step has been
      // read and checked by the constructor but the result's folder: run()
      // creates the file, --check only asks whether it could.
      simulation.checkOutputFolder();
      if (root) {
        std::cout << "coulomb: " << arguments.deck << " is valid\n";
        coulomb::solver::printProblemSize(std::cout, simulation.problemSize());
      }
      return 0;
    }
    simulation.setVerbosity(arguments.verbosity);
    simulation.run();
  } catch (const coulomb::Error& e) {
    // Every rank throws the same coulomb::Error (see core/Parallel.hpp); one prints it.
    if (root) std::cerr << "coulomb: error: " << coulomb::userMessage(e.what()) << std::endl;
    return 1;
  } catch (const coulomb::InternalError& e) {
    // A broken invariant: a bug, on this rank alone perhaps, so abort all.
    std::cerr << "coulomb: internal error (a bug in Coulomb, please report it with the deck) on rank "
              << comm->getRank() << ": " << coulomb::userMessage(e.what()) << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 3);
  } catch (const std::exception& e) {
    // Neither an input problem Coulomb detected nor one of its checks (a
    // library's exception, memory): a rank may be alone here, so abort all.
    std::cerr << "coulomb: unexpected error on rank " << comm->getRank() << ": " << coulomb::userMessage(e.what())
              << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  return 0;
}
