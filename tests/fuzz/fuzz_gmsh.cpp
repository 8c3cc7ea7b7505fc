// libFuzzer harness: the gmsh .msh (format 2.2) reader that
// coulomb_gmsh2exo uses to convert meshes.
#include <cstddef>
#include <cstdint>

#include "FuzzInput.hpp"
#include "coulomb/io/GmshReader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string path = coulomb::fuzz::writeInputFile(data, size, ".msh");
  return coulomb::fuzz::runExpectingOnlyUserErrors([&] { coulomb::io::readGmsh(path); });
}
