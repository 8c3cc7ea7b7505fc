// libFuzzer harness: the deck reader and validator, as `coulomb deck.xml`
// runs them before it reads the mesh (solver/Simulation.cpp): read + shape
// check + validation against every component's valid list, then the typed
// settings of the run, the model (2D and 3D) and contact.
#include <cstddef>
#include <cstdint>

#include "FuzzInput.hpp"
#include "coulomb/contact/ContactSettings.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/solver/Deck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string path = coulomb::fuzz::writeInputFile(data, size, ".xml");
  return coulomb::fuzz::runExpectingOnlyUserErrors([&] {
    const auto deck = coulomb::solver::readDeck(path);
    coulomb::solver::parseRunSettings(*deck, path);
    coulomb::fem::parseModelSettings(*deck, 2);
    coulomb::fem::parseModelSettings(*deck, 3);
    coulomb::contact::parseContactSettings(*deck);
  });
}
