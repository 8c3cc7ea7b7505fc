// libFuzzer harness: the gmsh .msh reader that coulomb_gmsh2exo uses to
// convert meshes (gmsh's own library reads the file, any version, ASCII or
// binary; then Coulomb's conversion of its physical groups).
#include <cstddef>
#include <cstdint>

#include "FuzzInput.hpp"
#include "coulomb/io/GmshReader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string path = coulomb::fuzz::writeInputFile(data, size, ".msh");
  return coulomb::fuzz::runExpectingOnlyUserErrors([&] { coulomb::io::readGmsh(path); });
}
