// An application that owns MPI and Tpetra and runs Coulomb as a library:
// it gives the simulation its own communicator (here all ranks but the
// last when there are more than two: the rest of an application would use
// the others), runs a deck, and reads the results back as Tpetra objects and
// per-node-set totals instead of from the Exodus file.
//
//   embed_coulomb DECK.xml [NODE_SET [RESULT.e]]
//
// RESULT.e replaces the deck's Output/File. Prints the Newton summary, the reaction total on NODE_SET (default "top")
// and the largest displacement magnitude component (a Tpetra reduction over
// the ranks that ran the simulation).
#include <mpi.h>

#include <exception>
#include <iomanip>
#include <iostream>
#include <string>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/solver/Simulation.hpp"

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto world = Tpetra::getDefaultComm();
  if (argc < 2) {
    if (world->getRank() == 0) std::cerr << "usage: embed_coulomb DECK.xml [NODE_SET [RESULT.e]]\n";
    return 2;
  }
  const std::string deck = argv[1];
  const std::string nodeSet = argc > 2 ? argv[2] : "top";
  const std::string result = argc > 3 ? argv[3] : "";

  // The application's own split: with more than two ranks, the last one
  // stays out of the simulation (color 1).
  const int size = world->getSize();
  const int color = size > 2 && world->getRank() == size - 1 ? 1 : 0;
  auto comm = world->split(color, world->getRank());
  int status = 0;
  if (color == 0) {
    try {
      std::ostream* console = nullptr;  // the application prints what it needs
      coulomb::solver::Simulation simulation(deck, comm, console, result);
      const auto summary = simulation.run();
      const auto reaction = simulation.reactionTotal(nodeSet);
      const double largest = simulation.displacement().normInf();
      if (comm->getRank() == 0) {
        std::cout << "embed_coulomb: " << comm->getSize() << " of " << size << " ranks, " << summary.steps
                  << " steps, " << summary.newtonIterations << " Newton iterations\n";
        std::cout << std::setprecision(6) << "embed_coulomb: reaction on '" << nodeSet << "' =";
        for (double r : reaction) std::cout << ' ' << r;
        std::cout << "\nembed_coulomb: largest displacement component = " << largest << "\n";
      }
    } catch (const coulomb::Error& e) {
      // Every rank of `comm` throws the same error; one reports it.
      if (comm->getRank() == 0) std::cerr << "embed_coulomb: error: " << e.what() << "\n";
      status = 1;
    } catch (const std::exception& e) {
      // Anything else (e.g. from inside Trilinos) may have been thrown on
      // some ranks only: the others would wait in a collective, so abort.
      std::cerr << "embed_coulomb: internal error on rank " << world->getRank() << ": " << e.what() << "\n";
      MPI_Abort(MPI_COMM_WORLD, 3);
    }
  }
  // The application goes on with all its ranks.
  int worst = 0;
  Teuchos::reduceAll(*world, Teuchos::REDUCE_MAX, status, Teuchos::outArg(worst));
  return worst;
}
