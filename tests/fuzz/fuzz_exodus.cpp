// libFuzzer harness: the Exodus II mesh reader (io/ExodusReader.cpp).
//
// Two kinds of input, so that both the file format and the mesh's meaning
// are explored:
// - bytes that start like a netCDF or HDF5 file (the seed corpus: shipped
//   meshes) are the mesh file itself, corrupted byte by byte;
// - anything else is decoded (FuzzedDataProvider) into a mesh description —
//   dimension, counts, element types, connectivity, node and side sets,
//   names, coordinates, each drawn mostly in range and sometimes not — that
//   is written with the exodusII library and then read. Corrupted
//   dimensions, ids, connectivity and side sets reach the reader's checks
//   this way instead of being stopped by netCDF's header check.
#include <exodusII.h>
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "FuzzInput.hpp"
#include "coulomb/io/ExodusReader.hpp"

namespace {

bool looksLikeAFile(const uint8_t* data, std::size_t size) {
  return (size >= 3 && std::memcmp(data, "CDF", 3) == 0) || (size >= 4 && std::memcmp(data, "\x89HDF", 4) == 0);
}

// Element types as files spell them, with their node counts; the last ones
// are types Coulomb refuses.
struct TypeChoice {
  const char* name;
  int nodes;
};
constexpr TypeChoice kTypes[] = {{"QUAD4", 4}, {"quad", 4},  {"TRI3", 3},  {"HEX8", 8},  {"hex", 8},
                                 {"TETRA", 4}, {"TET4", 4},  {"HEX20", 20}, {"BEAM", 2}, {"SHELL4", 4}};

long long drawIndex(FuzzedDataProvider& in, long long count) {
  // Mostly a valid 1-based index; sometimes 0, negative or past the end.
  return in.ConsumeBool() ? in.ConsumeIntegralInRange<long long>(1, count > 0 ? count : 1)
                          : in.ConsumeIntegralInRange<long long>(-3, count + 3);
}

std::string drawName(FuzzedDataProvider& in) { return in.ConsumeRandomLengthString(40); }

// Writes the described mesh; false when the exodusII library itself refuses
// it (not a finding: the reader never sees such a file).
bool writeDescribedMesh(FuzzedDataProvider& in, const std::string& path) {
  const int dim = in.ConsumeIntegralInRange(1, 4);  // 1 and 4: dimensions Coulomb refuses
  const int64_t numNodes = in.ConsumeIntegralInRange<int64_t>(0, 64);
  const int numBlocks = in.ConsumeIntegralInRange(0, 3);
  const int numNodeSets = in.ConsumeIntegralInRange(0, 2);
  const int numSideSets = in.ConsumeIntegralInRange(0, 2);
  struct Block {
    int id;
    TypeChoice type;
    int64_t elements;
    std::string name;
  };
  std::vector<Block> blocks;
  int64_t numElements = 0;
  for (int b = 0; b < numBlocks; ++b) {
    Block block{in.ConsumeIntegralInRange(-1, 5), kTypes[in.ConsumeIntegralInRange<std::size_t>(0, 9)],
                in.ConsumeIntegralInRange<int64_t>(0, 12), drawName(in)};
    if (in.ConsumeIntegralInRange(0, 7) == 0) block.type.nodes = in.ConsumeIntegralInRange(1, 9);
    numElements += block.elements;
    blocks.push_back(block);
  }
  const int64_t declaredElements = in.ConsumeIntegralInRange(0, 15) == 0 ? numElements + 1 : numElements;

  int cpuWordSize = 8, ioWordSize = 8;
  ex_opts(EX_DEFAULT);
  const int exo = ex_create(path.c_str(), EX_CLOBBER | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize);
  if (exo < 0) return false;
  bool ok = ex_put_init(exo, "fuzz", dim, numNodes, declaredElements, numBlocks, numNodeSets, numSideSets) >= 0;
  std::vector<double> x(numNodes), y(numNodes), z(numNodes);
  for (int64_t i = 0; i < numNodes; ++i) {
    x[i] = in.ConsumeFloatingPointInRange<double>(-2, 2);
    y[i] = in.ConsumeBool() ? in.ConsumeFloatingPoint<double>() : in.ConsumeFloatingPointInRange<double>(-2, 2);
    z[i] = in.ConsumeFloatingPointInRange<double>(-2, 2);
  }
  if (ok && numNodes > 0) ok = ex_put_coord(exo, x.data(), y.data(), z.data()) >= 0;
  std::vector<std::string> names;
  for (const auto& block : blocks) {
    if (!ok) break;
    ok = ex_put_block(exo, EX_ELEM_BLOCK, block.id, block.type.name, block.elements, block.type.nodes, 0, 0, 0) >= 0;
    std::vector<int64_t> conn(static_cast<std::size_t>(block.elements * block.type.nodes));
    for (auto& node : conn) node = drawIndex(in, numNodes);
    if (ok && !conn.empty()) ok = ex_put_conn(exo, EX_ELEM_BLOCK, block.id, conn.data(), nullptr, nullptr) >= 0;
    names.push_back(block.name);
  }
  for (int s = 0; ok && s < numNodeSets; ++s) {
    const int id = in.ConsumeIntegralInRange(0, 4);
    std::vector<int64_t> nodes(in.ConsumeIntegralInRange<std::size_t>(0, 10));
    for (auto& node : nodes) node = drawIndex(in, numNodes);
    ok = ex_put_set_param(exo, EX_NODE_SET, id, nodes.size(), 0) >= 0 &&
         (nodes.empty() || ex_put_set(exo, EX_NODE_SET, id, nodes.data(), nullptr) >= 0);
  }
  for (int s = 0; ok && s < numSideSets; ++s) {
    const int id = in.ConsumeIntegralInRange(0, 4);
    const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(0, 10);
    std::vector<int64_t> elements(n), sides(n);
    for (std::size_t i = 0; i < n; ++i) {
      elements[i] = drawIndex(in, numElements);
      sides[i] = in.ConsumeIntegralInRange<int64_t>(-1, 8);
    }
    ok = ex_put_set_param(exo, EX_SIDE_SET, id, n, 0) >= 0 &&
         (n == 0 || ex_put_set(exo, EX_SIDE_SET, id, elements.data(), sides.data()) >= 0);
  }
  if (ok && numBlocks > 0 && in.ConsumeBool()) {
    std::vector<char*> pointers;
    for (auto& name : names) pointers.push_back(name.data());
    ex_put_names(exo, EX_ELEM_BLOCK, pointers.data());
  }
  ex_close(exo);
  return ok;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string path;
  if (looksLikeAFile(data, size)) {
    path = coulomb::fuzz::writeInputFile(data, size, ".e");
  } else {
    path = coulomb::fuzz::writeInputFile(nullptr, 0, ".e");
    FuzzedDataProvider in(data, size);
    if (!writeDescribedMesh(in, path)) return 0;
  }
  return coulomb::fuzz::runExpectingOnlyUserErrors([&] { coulomb::io::readExodus(path); });
}
