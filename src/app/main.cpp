// The `coulomb` executable: parse arguments, run one deck. All work is in
// the library (coulomb::solver::Simulation); this file only reports errors.
#include <mpi.h>

#include <cstring>
#include <iostream>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/Interrupt.hpp"
#include "coulomb/core/UserMessage.hpp"
#include "coulomb/solver/Deck.hpp"
#include "coulomb/solver/Simulation.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: coulomb DECK.xml [-o RESULT.e] [-m|--mesh MESH.e]\n"
         "                                    run an input deck (result: the deck's Output/File, or DECK.e\n"
         "                                    next to the deck; -o overrides it; --mesh replaces Mesh/File)\n"
         "       coulomb --help-deck         list every deck parameter (type, default, doc)\n"
         "       mpirun -np N coulomb DECK.xml\n";
}

}  // namespace

int main(int argc, char** argv) {
  // SIGINT/SIGTERM stop the run cleanly (converged steps kept, exit 1); a
  // second one ends it at once. First of all: a signal during start-up too.
  coulomb::installInterruptHandlers();
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  if (argc < 2) {
    if (root) usage(std::cerr);
    return 2;
  }
  const std::string argument = argv[1];
  std::string output, mesh;
  for (int i = 2; i < argc; i += 2) {
    const std::string option = argv[i];
    if (i + 1 >= argc || (option != "-o" && option != "--mesh" && option != "-m")) {
      if (root) usage(std::cerr);
      return 2;
    }
    (option == "-o" ? output : mesh) = argv[i + 1];
  }
  if (argument == "--help" || argument == "-h") {
    if (root) usage(std::cout);
    return 0;
  }
  if (argument == "--help-deck") {
    if (root) coulomb::solver::printDeckHelp(std::cout);
    return 0;
  }
  try {
    coulomb::solver::Simulation simulation(argument, comm, &std::cout, output, mesh);
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
