/// @file ExodusWriter.cpp
/// @brief ExodusWriter on top of the exodusII 6.02 C API.
///
/// The mesh is checked before anything is written (ids unique, numbers in
/// range) because the exodus library accepts almost anything and ParaView
/// then fails without saying why. Every library call is checked and turned
/// into a coulomb::Error naming the path and carrying the library's message.
#include "coulomb/io/ExodusWriter.hpp"

#include <exodusII.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>
#include <utility>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusError.hpp"

namespace coulomb::io {
namespace {

/// Exodus names are limited by the library's maximum name length (the file's
/// name dimension is sized to the longest name, see writeMesh); longer names
/// than this are refused rather than cut silently.
constexpr std::size_t kMaxNameLength = 255;

void checkIdsUnique(const std::string& path, const char* kind, const std::vector<int>& ids) {
  std::set<int> seen;
  for (int id : ids) {
    COULOMB_REQUIRE(id > 0, "exodus output '" << path << "': " << kind << " id " << id << " must be positive");
    COULOMB_REQUIRE(seen.insert(id).second, "exodus output '" << path << "': two " << kind << "s have id " << id);
  }
}

/// Refuses a mesh the file format (or a later reader) cannot represent.
void validateMesh(const std::string& path, const mesh::GlobalMesh& mesh) {
  COULOMB_REQUIRE(mesh.dimension == 2 || mesh.dimension == 3,
                  "exodus output '" << path << "': mesh dimension " << mesh.dimension << " (need 2 or 3)");
  COULOMB_REQUIRE(mesh.coordinates.size() % static_cast<std::size_t>(mesh.dimension) == 0,
                  "exodus output '" << path << "': coordinate array length " << mesh.coordinates.size()
                                    << " is not a multiple of the dimension " << mesh.dimension);
  const long long numNodes = mesh.numNodes();
  constexpr long long kMaxCount = 2147483647;  // 32-bit storage, see the constructor
  COULOMB_REQUIRE(numNodes <= kMaxCount && mesh.numElements() <= kMaxCount,
                  "exodus output '" << path << "': more than 2^31 - 1 nodes or elements");
  std::vector<int> ids;
  long long firstElement = 0;
  for (const auto& block : mesh.blocks) {
    ids.push_back(block.id);
    const std::string name = mesh::displayName(block.name, "block", block.id);
    COULOMB_REQUIRE(mesh::spatialDimension(block.cellType) == mesh.dimension,
                    "exodus output '" << path << "': block '" << name << "' has " << mesh::toString(block.cellType)
                                      << " cells in a " << mesh.dimension << "D mesh");
    COULOMB_REQUIRE(block.connectivity.size() % static_cast<std::size_t>(mesh::numNodes(block.cellType)) == 0,
                    "exodus output '" << path << "': block '" << name << "' connectivity length "
                                      << block.connectivity.size() << " is not a multiple of "
                                      << mesh::numNodes(block.cellType));
    COULOMB_REQUIRE(block.firstElement == firstElement,
                    "exodus output '" << path << "': block '" << name << "' starts at element " << block.firstElement
                                      << " but the blocks before it hold " << firstElement << " elements");
    for (long long node : block.connectivity)
      COULOMB_REQUIRE(node >= 0 && node < numNodes, "exodus output '" << path << "': block '" << name
                                                                      << "' refers to node " << node << " of "
                                                                      << numNodes);
    firstElement += block.numElements();
  }
  checkIdsUnique(path, "element block", ids);
  ids.clear();
  for (const auto& set : mesh.nodeSets) {
    ids.push_back(set.id);
    for (long long node : set.nodes)
      COULOMB_REQUIRE(node >= 0 && node < numNodes, "exodus output '" << path << "': node set '" << set.name
                                                                      << "' refers to node " << node << " of "
                                                                      << numNodes);
  }
  checkIdsUnique(path, "node set", ids);
  ids.clear();
  for (const auto& set : mesh.sideSets) {
    ids.push_back(set.id);
    COULOMB_REQUIRE(set.elements.size() == set.sides.size(),
                    "exodus output '" << path << "': side set '" << set.name << "' has " << set.elements.size()
                                      << " elements but " << set.sides.size() << " sides");
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      const long long element = set.elements[i];
      COULOMB_REQUIRE(element >= 0 && element < firstElement, "exodus output '" << path << "': side set '" << set.name
                                                                                << "' refers to element " << element
                                                                                << " of " << firstElement);
      const auto block = std::find_if(mesh.blocks.begin(), mesh.blocks.end(), [&](const mesh::ElementBlock& b) {
        return element >= b.firstElement && element < b.firstElement + b.numElements();
      });
      COULOMB_REQUIRE(set.sides[i] >= 0 && set.sides[i] < mesh::numFaces(block->cellType),
                      "exodus output '" << path << "': side set '" << set.name << "' gives side " << set.sides[i]
                                        << " (0-based) of a " << mesh::toString(block->cellType) << " element");
    }
  }
  checkIdsUnique(path, "side set", ids);
}

void checkNames(const std::string& path, const char* kind, const std::vector<std::string>& names) {
  std::set<std::string> seen;
  for (const auto& name : names) {
    COULOMB_REQUIRE(!name.empty(), "exodus output '" << path << "': empty " << kind << " variable name");
    COULOMB_REQUIRE(name.size() <= kMaxNameLength, "exodus output '" << path << "': " << kind << " variable name '"
                                                                     << name << "' is longer than " << kMaxNameLength
                                                                     << " characters");
    COULOMB_REQUIRE(seen.insert(name).second,
                    "exodus output '" << path << "': " << kind << " variable '" << name << "' declared twice");
  }
}

}  // namespace

void checkOutputFolder(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  std::error_code ignored;
  COULOMB_REQUIRE(std::filesystem::is_directory(folder, ignored),
                  "exodus output '" << path << "': the folder '" << folder.string() << "' does not exist");
  COULOMB_REQUIRE(::access(folder.c_str(), W_OK) == 0, "exodus output '" << path << "': the folder '"
                                                                        << folder.string() << "' is not writable ("
                                                                        << std::strerror(errno) << ")");
}

ExodusWriter::ExodusWriter(const std::string& path, const mesh::GlobalMesh& mesh,
                           std::vector<std::string> nodalVariableNames, std::vector<std::string> globalVariableNames,
                           const std::string& title)
    : path_(path),
      numNodes_(mesh.numNodes()),
      nodalNames_(std::move(nodalVariableNames)),
      globalNames_(std::move(globalVariableNames)) {
  validateMesh(path_, mesh);
  checkNames(path_, "nodal", nodalNames_);
  checkNames(path_, "global", globalNames_);

  ex_opts(EX_DEFAULT);  // no printing, no abort: errors become coulomb::Error
  int cpuWordSize = sizeof(double);
  int ioWordSize = sizeof(double);
  // netCDF-3 64-bit offset, integers passed as int64 but stored as 32-bit
  // (see the header): with EX_BULK_INT64_DB the Debian exodusII 6.02 stores
  // node and side set lists as netCDF "ushort" and fails on numbers above
  // 65535 (checked by hand); netCDF-4 files are locked against readers while
  // open for writing. 32-bit storage is exact up to 2^31 - 1 (validateMesh).
  const int mode = EX_CLOBBER | EX_LARGE_MODEL | EX_ALL_INT64_API;
  fileId_ = ex_create(path_.c_str(), mode, &cpuWordSize, &ioWordSize);
  if (fileId_ < 0) {
    // Say why in the user's words: the folder is missing or not writable
    // (netCDF's own message names neither).
    checkOutputFolder(path_);
    throw Error("exodus output '" + path_ + "': cannot create the file (" + lastExodusError() + ")");
  }
  try {
    writeMesh(mesh, title);
    check(ex_update(fileId_), "flushing the mesh");
  } catch (...) {
    ex_close(fileId_);
    fileId_ = -1;
    throw;
  }
}

ExodusWriter::~ExodusWriter() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() errors were already unreportable.
  }
}

ExodusWriter::ExodusWriter(ExodusWriter&& other) noexcept
    : path_(std::move(other.path_)),
      fileId_(std::exchange(other.fileId_, -1)),
      numNodes_(other.numNodes_),
      numSteps_(other.numSteps_),
      variablesDeclared_(other.variablesDeclared_),
      nodalNames_(std::move(other.nodalNames_)),
      globalNames_(std::move(other.globalNames_)) {}

ExodusWriter& ExodusWriter::operator=(ExodusWriter&& other) noexcept {
  if (this != &other) {
    try {
      close();
    } catch (...) {
    }
    path_ = std::move(other.path_);
    fileId_ = std::exchange(other.fileId_, -1);
    numNodes_ = other.numNodes_;
    numSteps_ = other.numSteps_;
    variablesDeclared_ = other.variablesDeclared_;
    nodalNames_ = std::move(other.nodalNames_);
    globalNames_ = std::move(other.globalNames_);
  }
  return *this;
}

void ExodusWriter::check(int status, const std::string& what) const {
  if (status >= 0) return;
  const int error = errno;
  // The library's message does not say why a write failed; a full disk is the common cause.
  std::string cause;
  std::error_code ignored;
  const auto parent = std::filesystem::absolute(path_, ignored).parent_path();
  const auto space = std::filesystem::space(parent, ignored);
  if (error == ENOSPC || (!ignored && space.available < (1u << 20)))
    cause = "; the disk holding it is full (" + std::to_string(space.available / 1024) + " KiB free)";
  throw Error("exodus output '" + path_ + "': " + what + " failed (" + lastExodusError() + ")" + cause);
}

void ExodusWriter::writeMesh(const mesh::GlobalMesh& mesh, const std::string& title) {
  // Names longer than the default 32 characters need a larger name length.
  std::size_t longest = 32;
  for (const auto& b : mesh.blocks) longest = std::max(longest, b.name.size());
  for (const auto& s : mesh.nodeSets) longest = std::max(longest, s.name.size());
  for (const auto& s : mesh.sideSets) longest = std::max(longest, s.name.size());
  for (const auto& n : nodalNames_) longest = std::max(longest, n.size());
  for (const auto& n : globalNames_) longest = std::max(longest, n.size());
  COULOMB_REQUIRE(longest <= kMaxNameLength, "exodus output '" << path_ << "': a block or set name is longer than "
                                                               << kMaxNameLength << " characters");
  if (longest > 32) check(ex_set_max_name_length(fileId_, static_cast<int>(longest)), "setting the name length");

  const int d = mesh.dimension;
  const std::string shortTitle = title.substr(0, MAX_LINE_LENGTH);
  check(ex_put_init(fileId_, shortTitle.c_str(), d, numNodes_, mesh.numElements(),
                    static_cast<int64_t>(mesh.blocks.size()), static_cast<int64_t>(mesh.nodeSets.size()),
                    static_cast<int64_t>(mesh.sideSets.size())),
        "writing the file header");

  const auto n = static_cast<std::size_t>(numNodes_);
  std::vector<double> x(n), y(n), z(d == 3 ? n : 0);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = mesh.coordinates[d * i];
    y[i] = mesh.coordinates[d * i + 1];
    if (d == 3) z[i] = mesh.coordinates[d * i + 2];
  }
  check(ex_put_coord(fileId_, x.data(), y.data(), d == 3 ? z.data() : nullptr), "writing the coordinates");
  char coordNameStorage[3][2] = {"x", "y", "z"};
  char* coordNames[3] = {coordNameStorage[0], coordNameStorage[1], coordNameStorage[2]};
  check(ex_put_coord_names(fileId_, coordNames), "writing the coordinate names");

  std::vector<int64_t> buffer;
  for (const auto& block : mesh.blocks) {
    const std::string label = "block '" + mesh::displayName(block.name, "block", block.id) + "'";
    const std::string type = mesh::toString(block.cellType);
    check(ex_put_block(fileId_, EX_ELEM_BLOCK, block.id, type.c_str(), block.numElements(),
                       mesh::numNodes(block.cellType), 0, 0, 0),
          "writing " + label);
    if (block.numElements() > 0) {
      buffer.assign(block.connectivity.begin(), block.connectivity.end());
      for (auto& node : buffer) ++node;
      check(ex_put_conn(fileId_, EX_ELEM_BLOCK, block.id, buffer.data(), nullptr, nullptr),
            "writing the connectivity of " + label);
    }
    if (!block.name.empty()) check(ex_put_name(fileId_, EX_ELEM_BLOCK, block.id, block.name.c_str()), "naming " + label);
  }

  for (const auto& set : mesh.nodeSets) {
    const std::string label = "node set '" + set.name + "'";
    check(ex_put_set_param(fileId_, EX_NODE_SET, set.id, static_cast<int64_t>(set.nodes.size()), 0),
          "writing " + label);
    if (!set.nodes.empty()) {
      buffer.assign(set.nodes.begin(), set.nodes.end());
      for (auto& node : buffer) ++node;
      check(ex_put_set(fileId_, EX_NODE_SET, set.id, buffer.data(), nullptr), "writing " + label);
    }
    if (!set.name.empty()) check(ex_put_name(fileId_, EX_NODE_SET, set.id, set.name.c_str()), "naming " + label);
  }

  std::vector<int64_t> sides;
  for (const auto& set : mesh.sideSets) {
    const std::string label = "side set '" + set.name + "'";
    check(ex_put_set_param(fileId_, EX_SIDE_SET, set.id, static_cast<int64_t>(set.elements.size()), 0),
          "writing " + label);
    if (!set.elements.empty()) {
      buffer.assign(set.elements.begin(), set.elements.end());
      for (auto& element : buffer) ++element;
      sides.assign(set.sides.begin(), set.sides.end());
      for (auto& side : sides) ++side;
      check(ex_put_set(fileId_, EX_SIDE_SET, set.id, buffer.data(), sides.data()), "writing " + label);
    }
    if (!set.name.empty()) check(ex_put_name(fileId_, EX_SIDE_SET, set.id, set.name.c_str()), "naming " + label);
  }
}

void ExodusWriter::declareVariables() {
  const auto declare = [this](ex_entity_type type, const std::vector<std::string>& names, const char* kind) {
    if (names.empty()) return;
    check(ex_put_variable_param(fileId_, type, static_cast<int>(names.size())),
          std::string("declaring the ") + kind + " variables");
    for (std::size_t v = 0; v < names.size(); ++v)
      check(ex_put_variable_name(fileId_, type, static_cast<int>(v + 1), names[v].c_str()),
            std::string("naming ") + kind + " variable '" + names[v] + "'");
  };
  declare(EX_NODAL, nodalNames_, "nodal");
  declare(EX_GLOBAL, globalNames_, "global");
  variablesDeclared_ = true;
}

void ExodusWriter::writeStep(double time, const std::vector<std::vector<double>>& nodalValues,
                             const std::vector<double>& globalValues) {
  COULOMB_REQUIRE(fileId_ >= 0, "exodus output '" << path_ << "': writeStep() after close()");
  COULOMB_REQUIRE(nodalValues.size() == nodalNames_.size(), "exodus output '" << path_ << "': got "
                                                                            << nodalValues.size()
                                                                            << " nodal variables, declared "
                                                                            << nodalNames_.size());
  for (std::size_t v = 0; v < nodalValues.size(); ++v)
    COULOMB_REQUIRE(static_cast<long long>(nodalValues[v].size()) == numNodes_,
                    "exodus output '" << path_ << "': nodal variable '" << nodalNames_[v] << "' has "
                                      << nodalValues[v].size() << " values for " << numNodes_ << " nodes");
  COULOMB_REQUIRE(globalValues.size() == globalNames_.size(), "exodus output '" << path_ << "': got "
                                                                              << globalValues.size()
                                                                              << " global values, declared "
                                                                              << globalNames_.size());
  // Variables are declared with the first step, not in the constructor:
  // ParaView 5.11's Exodus reader crashes (SIGSEGV) on a file that declares
  // variables but holds no time step, which is what a run that fails before
  // its first step would leave behind. Without steps the file is a plain mesh.
  if (!variablesDeclared_) declareVariables();
  const int step = numSteps_ + 1;
  check(ex_put_time(fileId_, step, &time), "writing the time of step " + std::to_string(step));
  for (std::size_t v = 0; v < nodalValues.size(); ++v)
    check(ex_put_var(fileId_, step, EX_NODAL, static_cast<int>(v + 1), 1, numNodes_, nodalValues[v].data()),
          "writing nodal variable '" + nodalNames_[v] + "' at step " + std::to_string(step));
  if (!globalValues.empty())
    check(ex_put_glob_vars(fileId_, step, static_cast<int>(globalValues.size()), globalValues.data()),
          "writing the global variables at step " + std::to_string(step));
  check(ex_update(fileId_), "flushing step " + std::to_string(step));
  numSteps_ = step;
}

void ExodusWriter::close() {
  if (fileId_ < 0) return;
  const int id = std::exchange(fileId_, -1);
  check(ex_close(id), "closing the file");
}

}  // namespace coulomb::io
