/// @file ExodusReader.cpp
/// @brief readExodus() on top of the exodusII 6.02 C API.
///
/// All integer data is requested as int64 (EX_ALL_INT64_API) so that files
/// with 32-bit and with 64-bit maps (the shared benchmark meshes store int64
/// connectivity and int32 side sets in one netCDF-4 file) read through one
/// code path; the library converts. ex_opts(EX_DEFAULT) keeps the library from
/// printing or aborting on errors: we turn each failed call into a
/// coulomb::Error that names the file and carries the library's own message.
#include "coulomb/io/ExodusReader.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusError.hpp"
#include "coulomb/io/NetcdfHeaderCheck.hpp"

namespace coulomb::io {
namespace {

/// The longest block, set or variable name a file may declare (NC_MAX_NAME;
/// ExodusWriter writes at most 255 characters).
constexpr int64_t kLongestName = 256;
constexpr const char* kSupportedTypes = "QUAD4, QUAD8, QUAD9, TRI3, TRI6, HEX8, HEX20, HEX27, TET4, TET10";

/// Closes the file however readExodus() leaves.
struct FileGuard {
  int id = -1;
  ~FileGuard() {
    if (id >= 0) ex_close(id);
  }
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string trimmed(const char* raw) {
  std::string s(raw);
  const auto end = s.find_last_not_of(" \t\r\n");
  return end == std::string::npos ? std::string() : s.substr(0, end + 1);
}

class Reader {
public:
  Reader(const std::string& path, const MemoryBudget& budget) : path_(path), budget_(budget) {}

  mesh::GlobalMesh read() {
    {
      std::ifstream probe(path_);
      COULOMB_REQUIRE(probe.good(), "mesh '" << path_ << "': cannot open file (missing or not readable)");
    }
    // netCDF allocates what a classic header declares: damaged counts are
    // caught here, before they become an out-of-memory kill.
    const std::string damaged = classicNetcdfHeaderProblem(path_);
    COULOMB_REQUIRE(damaged.empty(), "mesh '" << path_ << "': " << damaged);
    ex_opts(EX_DEFAULT);  // no printing, no abort: we report errors ourselves
    int cpuWordSize = sizeof(double);
    int ioWordSize = 0;
    float version = 0.0f;
    file_.id = ex_open(path_.c_str(), EX_READ | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize, &version);
    COULOMB_REQUIRE(file_.id >= 0, "mesh '" << path_ << "': not a readable Exodus II file ("
                                            << lastExodusError() << ")");
    ex_set_int64_status(file_.id, EX_ALL_INT64_API);
    // Names may be longer than the default 32 characters (ExodusWriter sizes
    // the name dimension to the longest name).
    const int64_t usedNameLength = ex_inquire_int(file_.id, EX_INQ_DB_MAX_USED_NAME_LENGTH);
    // The length sizes a buffer per block and set: a damaged one (found by
    // fuzz_exodus: 2.7e8, 1.3 GB of buffers for 5 sets) is refused.
    COULOMB_REQUIRE(usedNameLength >= 0 && usedNameLength <= kLongestName,
                    "mesh '" << path_ << "': the header declares names of " << usedNameLength
                             << " characters (at most " << kLongestName << "): the file is damaged");
    if (usedNameLength > 32) ex_set_max_name_length(file_.id, static_cast<int>(usedNameLength));
    nameBufferLength_ = static_cast<std::size_t>(std::max<int64_t>(usedNameLength, 256)) + 1;

    ex_init_params init{};
    check(ex_get_init_ext(file_.id, &init), "reading the file header");
    COULOMB_REQUIRE(init.num_dim == 2 || init.num_dim == 3,
                    "mesh '" << path_ << "': spatial dimension " << init.num_dim << " is not supported (need 2 or 3)");
    mesh_.dimension = static_cast<int>(init.num_dim);
    COULOMB_REQUIRE(init.num_nodes > 0, "mesh '" << path_ << "': has no nodes");
    const std::string tooLarge = meshMemoryProblem(init.num_nodes, init.num_elem, mesh_.dimension, budget_);
    COULOMB_REQUIRE(tooLarge.empty(), "mesh '" << path_ << "': " << tooLarge);
    readCoordinates(init.num_nodes);
    if (init.num_elem_blk > 0) readBlocks(init.num_elem_blk);
    COULOMB_REQUIRE(mesh_.numElements() == init.num_elem,
                    "mesh '" << path_ << "': blocks hold " << mesh_.numElements() << " elements but the header says "
                             << init.num_elem);
    if (init.num_node_sets > 0) readNodeSets(init.num_node_sets);
    if (init.num_side_sets > 0) readSideSets(init.num_side_sets);
    return std::move(mesh_);
  }

private:
  void check(int status, const std::string& what) const {
    COULOMB_REQUIRE(status >= 0, "mesh '" << path_ << "': " << what << " failed (" << lastExodusError() << ")");
  }

  bool hasVariable(const std::string& name) const {
    int varid = 0;
    return nc_inq_varid(file_.id, name.c_str(), &varid) == NC_NOERR;
  }

  /// The exodusII library reads a whole netCDF variable into the buffer it
  /// is given, sized from a dimension it looks up by name; in a damaged file
  /// the variable can be longer than that dimension (a renamed or duplicated
  /// dimension), and the read would write past the buffer (found by
  /// tests/fuzz/fuzz_exodus). So the variable's own length is checked first.
  /// A missing variable is left to the library's own error.
  void requireLength(const std::string& name, std::size_t expected, const std::string& what) const {
    int varid = 0, numDims = 0;
    if (nc_inq_varid(file_.id, name.c_str(), &varid) != NC_NOERR) return;
    auto ok = [&](int status) {
      COULOMB_REQUIRE(status == NC_NOERR, "mesh '" << path_ << "': reading the shape of " << what << " failed ("
                                                   << nc_strerror(status) << ")");
    };
    ok(nc_inq_varndims(file_.id, varid, &numDims));
    std::vector<int> dims(static_cast<std::size_t>(std::max(numDims, 0)));
    if (numDims > 0) ok(nc_inq_vardimid(file_.id, varid, dims.data()));
    std::size_t length = 1;
    for (int dim : dims) {
      std::size_t extent = 0;
      ok(nc_inq_dimlen(file_.id, dim, &extent));
      length *= extent;
    }
    COULOMB_REQUIRE(length == expected, "mesh '" << path_ << "': " << what << " (netCDF variable '" << name
                                                 << "') holds " << length << " values where the header declares "
                                                 << expected << ": the file is damaged");
  }

  std::vector<int64_t> ids(ex_entity_type type, int64_t count, const char* what) {
    std::vector<int64_t> result(static_cast<std::size_t>(count));
    const char* variable = type == EX_ELEM_BLOCK ? "eb_prop1" : type == EX_NODE_SET ? "ns_prop1" : "ss_prop1";
    requireLength(variable, result.size(), std::string("the ") + what + " ids");
    check(ex_get_ids(file_.id, type, result.data()), std::string("reading the ") + what + " ids");
    return result;
  }

  std::vector<std::string> names(ex_entity_type type, int64_t count) {
    std::vector<std::vector<char>> buffers(static_cast<std::size_t>(count), std::vector<char>(nameBufferLength_, '\0'));
    std::vector<char*> pointers;
    for (auto& buffer : buffers) pointers.push_back(buffer.data());
    std::vector<std::string> result(static_cast<std::size_t>(count));
    // A file without names is fine (status > 0 is a warning): names stay "".
    if (ex_get_names(file_.id, type, pointers.data()) < 0) return result;
    for (std::size_t i = 0; i < buffers.size(); ++i) result[i] = trimmed(buffers[i].data());
    return result;
  }

  void readCoordinates(int64_t numNodes) {
    const auto n = static_cast<std::size_t>(numNodes);
    std::vector<double> x(n), y(n), z(mesh_.dimension == 3 ? n : 0);
    if (hasVariable("coord")) {
      requireLength("coord", n * static_cast<std::size_t>(mesh_.dimension), "the coordinates");
    } else {
      for (int c = 0; c < mesh_.dimension; ++c)
        requireLength(std::string("coord") + "xyz"[c], n, "the coordinates");
    }
    check(ex_get_coord(file_.id, x.data(), y.data(), mesh_.dimension == 3 ? z.data() : nullptr),
          "reading the coordinates");
    const int d = mesh_.dimension;
    mesh_.coordinates.resize(n * static_cast<std::size_t>(d));
    for (std::size_t i = 0; i < n; ++i) {
      mesh_.coordinates[d * i] = x[i];
      mesh_.coordinates[d * i + 1] = y[i];
      if (d == 3) mesh_.coordinates[d * i + 2] = z[i];
      for (int c = 0; c < d; ++c)
        COULOMB_REQUIRE(std::isfinite(mesh_.coordinates[d * i + c]),
                        "mesh '" << path_ << "': node " << i + 1 << " has a coordinate that is not a finite number ("
                                 << "xyz"[c] << " = " << mesh_.coordinates[d * i + c] << ")");
    }
  }

  void readBlocks(int64_t count) {
    const auto blockIds = ids(EX_ELEM_BLOCK, count, "element block");
    const auto blockNames = names(EX_ELEM_BLOCK, count);
    const long long numNodes = mesh_.numNodes();
    long long firstElement = 0;
    for (std::size_t b = 0; b < blockIds.size(); ++b) {
      ex_block param{};
      param.id = blockIds[b];
      param.type = EX_ELEM_BLOCK;
      const std::string label = "element block '" + mesh::displayName(blockNames[b], "block", static_cast<int>(blockIds[b])) +
                                "' (id " + std::to_string(blockIds[b]) + ")";
      check(ex_get_block_param(file_.id, &param), "reading " + label);
      mesh::ElementBlock block;
      block.name = blockNames[b];
      block.id = static_cast<int>(blockIds[b]);
      block.firstElement = firstElement;
      const std::string type = trimmed(param.topology);
      COULOMB_REQUIRE(parseExodusElementType(type, static_cast<int>(param.num_nodes_per_entry), block.cellType),
                      "mesh '" << path_ << "': " << label << " has element type " << type << " with "
                               << param.num_nodes_per_entry << " nodes per element; supported: " << kSupportedTypes);
      COULOMB_REQUIRE(mesh::spatialDimension(block.cellType) == mesh_.dimension,
                      "mesh '" << path_ << "': " << label << " has element type " << type << " (a "
                               << mesh::spatialDimension(block.cellType) << "D cell) in a " << mesh_.dimension
                               << "D file; supported: QUAD4, QUAD8, QUAD9, TRI3, TRI6 in 2D files, HEX8, HEX20, HEX27, TET4, "
                                  "TET10 in 3D files");
      block.connectivity.resize(static_cast<std::size_t>(param.num_entry * param.num_nodes_per_entry));
      if (param.num_entry > 0) {
        requireLength("connect" + std::to_string(b + 1), block.connectivity.size(), "the connectivity of " + label);
        check(ex_get_conn(file_.id, EX_ELEM_BLOCK, param.id, block.connectivity.data(), nullptr, nullptr),
              "reading the connectivity of " + label);
      }
      for (long long& node : block.connectivity) {
        checkNodeReference(label, node, numNodes);
        --node;
      }
      firstElement += param.num_entry;
      mesh_.blocks.push_back(std::move(block));
    }
  }

  /// A node number of a block or set. 0 is no node of any Exodus file (they
  /// start at 1): it is what netCDF returns for data beyond the end of a cut
  /// file, so the message says so instead of blaming the numbering.
  void checkNodeReference(const std::string& label, long long node, long long numNodes) const {
    COULOMB_REQUIRE(node != 0, "mesh '" << path_ << "': " << label
                                        << " refers to node 0 (Exodus node numbers start at 1): the file is truncated "
                                           "or damaged (is it complete? it holds "
                                        << fileSize() << " bytes)");
    COULOMB_REQUIRE(node >= 1 && node <= numNodes, "mesh '" << path_ << "': " << label << " refers to node " << node
                                                            << " but the file has " << numNodes << " nodes");
  }
  std::uintmax_t fileSize() const {
    std::error_code ignored;
    const auto size = std::filesystem::file_size(path_, ignored);
    return ignored ? 0 : size;
  }

  void readNodeSets(int64_t count) {
    const auto setIds = ids(EX_NODE_SET, count, "node set");
    const auto setNames = names(EX_NODE_SET, count);
    const long long numNodes = mesh_.numNodes();
    for (std::size_t s = 0; s < setIds.size(); ++s) {
      mesh::NodeSet set;
      set.name = setNames[s];
      set.id = static_cast<int>(setIds[s]);
      const std::string label = "node set '" + mesh::displayName(set.name, "nodeset", set.id) + "' (id " +
                                std::to_string(set.id) + ")";
      int64_t numEntries = 0, numFactors = 0;
      check(ex_get_set_param(file_.id, EX_NODE_SET, setIds[s], &numEntries, &numFactors), "reading " + label);
      set.nodes.resize(static_cast<std::size_t>(numEntries));
      if (numEntries > 0) {
        requireLength("node_ns" + std::to_string(s + 1), set.nodes.size(), label);
        check(ex_get_set(file_.id, EX_NODE_SET, setIds[s], set.nodes.data(), nullptr), "reading " + label);
      }
      for (long long& node : set.nodes) {
        checkNodeReference(label, node, numNodes);
        --node;
      }
      mesh_.nodeSets.push_back(std::move(set));
    }
  }

  void readSideSets(int64_t count) {
    const auto setIds = ids(EX_SIDE_SET, count, "side set");
    const auto setNames = names(EX_SIDE_SET, count);
    const long long numElements = mesh_.numElements();
    for (std::size_t s = 0; s < setIds.size(); ++s) {
      mesh::SideSet set;
      set.name = setNames[s];
      set.id = static_cast<int>(setIds[s]);
      const std::string label = "side set '" + mesh::displayName(set.name, "sideset", set.id) + "' (id " +
                                std::to_string(set.id) + ")";
      int64_t numEntries = 0, numFactors = 0;
      check(ex_get_set_param(file_.id, EX_SIDE_SET, setIds[s], &numEntries, &numFactors), "reading " + label);
      std::vector<int64_t> sides(static_cast<std::size_t>(numEntries));
      set.elements.resize(static_cast<std::size_t>(numEntries));
      if (numEntries > 0) {
        requireLength("elem_ss" + std::to_string(s + 1), sides.size(), label);
        requireLength("side_ss" + std::to_string(s + 1), sides.size(), label);
        check(ex_get_set(file_.id, EX_SIDE_SET, setIds[s], set.elements.data(), sides.data()), "reading " + label);
      }
      set.sides.resize(sides.size());
      for (std::size_t i = 0; i < sides.size(); ++i) {
        const long long element = set.elements[i];
        COULOMB_REQUIRE(element >= 1 && element <= numElements, "mesh '" << path_ << "': " << label << " refers to element "
                                                                         << element << " but the file has " << numElements
                                                                         << " elements");
        set.elements[i] = element - 1;
        const auto& block = blockOf(element - 1);
        const int numFaces = mesh::numFaces(block.cellType);
        COULOMB_REQUIRE(sides[i] >= 1 && sides[i] <= numFaces,
                        "mesh '" << path_ << "': " << label << " gives side " << sides[i] << " of element " << element
                                 << " (" << mesh::toString(block.cellType) << ", sides 1.." << numFaces << ")");
        set.sides[i] = static_cast<int>(sides[i] - 1);
      }
      mesh_.sideSets.push_back(std::move(set));
    }
  }

  const mesh::ElementBlock& blockOf(long long element) const {
    // Blocks are few; a linear scan is cheaper than anything clever.
    for (const auto& block : mesh_.blocks)
      if (element >= block.firstElement && element < block.firstElement + block.numElements()) return block;
    throw Error("mesh '" + path_ + "': element " + std::to_string(element + 1) + " is in no block");
  }

  std::string path_;
  MemoryBudget budget_;
  FileGuard file_;
  std::size_t nameBufferLength_ = 257;
  mesh::GlobalMesh mesh_;
};

}  // namespace

bool parseExodusElementType(const std::string& type, int nodesPerElement, mesh::CellType& cellType) {
  // The name gives the family (QUAD, TRI/TRIANGLE, HEX/HEXAHEDRON, TET/TETRA),
  // the node count the member: "HEX" with 27 nodes is a HEX27. A number in
  // the name ("QUAD9", "TRIANGLE6") must agree with the node count.
  std::string t = upper(type);
  std::size_t digits = t.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(t[digits - 1]))) --digits;
  const std::string family = t.substr(0, digits);
  if (digits < t.size() && (t.size() - digits > 2 || std::stoi(t.substr(digits)) != nodesPerElement)) return false;
  using mesh::CellType;
  struct Member {
    const char* family;
    CellType type;
  };
  static const Member kMembers[] = {
      {"QUAD", CellType::Quad4},    {"QUAD", CellType::Quad8},     {"QUAD", CellType::Quad9},
      {"TRI", CellType::Tri3},      {"TRI", CellType::Tri6},       {"TRIANGLE", CellType::Tri3},
      {"TRIANGLE", CellType::Tri6}, {"HEX", CellType::Hex8},       {"HEX", CellType::Hex20},
      {"HEX", CellType::Hex27},     {"HEXAHEDRON", CellType::Hex8}, {"HEXAHEDRON", CellType::Hex20},
      {"HEXAHEDRON", CellType::Hex27}, {"TET", CellType::Tet4},    {"TET", CellType::Tet10},
      {"TETRA", CellType::Tet4},    {"TETRA", CellType::Tet10}};
  for (const Member& m : kMembers)
    if (family == m.family && nodesPerElement == mesh::numNodes(m.type)) {
      cellType = m.type;
      return true;
    }
  return false;
}

mesh::GlobalMesh readExodus(const std::string& path, const MemoryBudget& budget) { return Reader(path, budget).read(); }

mesh::GlobalMesh readExodus(const std::string& path) {
  MemoryBudget budget;
  budget.availableBytes = availableMemoryBytes();
  return readExodus(path, budget);
}

}  // namespace coulomb::io
