// Tests of readExodus() and ExodusWriter: a write/read round trip of meshes
// built in code (the result must equal the input exactly), the time steps
// read back through the raw exodusII API (so the writer is not only checked
// against our own reader), and the errors a user sees for missing files and
// unsupported element blocks. No file outside the repository is needed.
#include <gtest/gtest.h>

#include <exodusII.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"

namespace {

using coulomb::mesh::CellType;
using coulomb::mesh::GlobalMesh;

std::string outputPath(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(COULOMB_BINARY_DIR) / "test_output" / "io_exodus";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

/// Two unit hexes side by side along x (12 nodes), one per block.
GlobalMesh twoHexMesh() {
  GlobalMesh m;
  m.dimension = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) m.coordinates.insert(m.coordinates.end(), {1.0 * i, 0.5 * j, 0.25 * k});
  const auto n = [](int i, int j, int k) { return static_cast<long long>(i + 3 * (j + 2 * k)); };
  for (int e = 0; e < 2; ++e) {
    coulomb::mesh::ElementBlock b;
    b.name = e == 0 ? "left_part" : "right_part";
    b.id = 10 * (e + 1);
    b.cellType = CellType::Hex8;
    b.firstElement = e;
    b.connectivity = {n(e, 0, 0), n(e + 1, 0, 0), n(e + 1, 1, 0), n(e, 1, 0),
                      n(e, 0, 1), n(e + 1, 0, 1), n(e + 1, 1, 1), n(e, 1, 1)};
    m.blocks.push_back(b);
  }
  m.nodeSets.push_back({"xmin", 1, {n(0, 0, 0), n(0, 1, 0), n(0, 0, 1), n(0, 1, 1)}});
  m.nodeSets.push_back({"a_node_set_whose_name_is_longer_than_32_characters", 7, {n(2, 1, 1)}});
  m.nodeSets.push_back({"", 8, {}});  // unnamed and empty: both must survive
  m.sideSets.push_back({"xmin", 1, {0}, {3}});
  m.sideSets.push_back({"top", 5, {0, 1}, {5, 5}});
  return m;
}

/// A QUAD4 block and a TRI3 block sharing an edge (2D).
GlobalMesh quadTriMesh() {
  GlobalMesh m;
  m.dimension = 2;
  m.coordinates = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0.5};
  coulomb::mesh::ElementBlock quad{"quad", 1, CellType::Quad4, {0, 1, 2, 3}, 0};
  coulomb::mesh::ElementBlock tri{"tri", 2, CellType::Tri3, {1, 4, 2}, 1};
  m.blocks = {quad, tri};
  m.nodeSets.push_back({"right", 3, {4}});
  m.sideSets.push_back({"outside", 4, {0, 1, 1}, {0, 0, 1}});
  return m;
}

void expectSameMesh(const GlobalMesh& a, const GlobalMesh& b) {
  EXPECT_EQ(a.dimension, b.dimension);
  EXPECT_EQ(a.coordinates, b.coordinates);
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    SCOPED_TRACE("block " + std::to_string(i));
    EXPECT_EQ(a.blocks[i].name, b.blocks[i].name);
    EXPECT_EQ(a.blocks[i].id, b.blocks[i].id);
    EXPECT_EQ(a.blocks[i].cellType, b.blocks[i].cellType);
    EXPECT_EQ(a.blocks[i].connectivity, b.blocks[i].connectivity);
    EXPECT_EQ(a.blocks[i].firstElement, b.blocks[i].firstElement);
  }
  ASSERT_EQ(a.nodeSets.size(), b.nodeSets.size());
  for (std::size_t i = 0; i < a.nodeSets.size(); ++i) {
    EXPECT_EQ(a.nodeSets[i].name, b.nodeSets[i].name);
    EXPECT_EQ(a.nodeSets[i].id, b.nodeSets[i].id);
    EXPECT_EQ(a.nodeSets[i].nodes, b.nodeSets[i].nodes);
  }
  ASSERT_EQ(a.sideSets.size(), b.sideSets.size());
  for (std::size_t i = 0; i < a.sideSets.size(); ++i) {
    EXPECT_EQ(a.sideSets[i].name, b.sideSets[i].name);
    EXPECT_EQ(a.sideSets[i].id, b.sideSets[i].id);
    EXPECT_EQ(a.sideSets[i].elements, b.sideSets[i].elements);
    EXPECT_EQ(a.sideSets[i].sides, b.sideSets[i].sides);
  }
}

/// Expects `f` to throw coulomb::Error whose message contains every string in `parts`.
template <class F>
void expectErrorContaining(F&& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "expected coulomb::Error";
  } catch (const coulomb::Error& e) {
    const std::string message = e.what();
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << "message: " << message;
  }
}

/// Writes a one-block file through the raw exodusII API (what another
/// Exodus writer would produce), to test what our reader refuses or accepts.
void writeRawOneBlockFile(const std::string& path, int dimension, const char* type, int nodesPerElement,
                          const char* blockName, int blockId, int extraMode = 0) {
  int cpuWordSize = 8, ioWordSize = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER | extraMode, &cpuWordSize, &ioWordSize);
  ASSERT_GE(id, 0);
  ASSERT_GE(ex_put_init(id, "raw", dimension, nodesPerElement, 1, 1, 0, 0), 0);
  std::vector<double> x(nodesPerElement), y(nodesPerElement), z(nodesPerElement);
  for (int i = 0; i < nodesPerElement; ++i) {
    x[i] = i;
    y[i] = i % 3;
    z[i] = i % 5;
  }
  ASSERT_GE(ex_put_coord(id, x.data(), y.data(), dimension == 3 ? z.data() : nullptr), 0);
  ASSERT_GE(ex_put_block(id, EX_ELEM_BLOCK, blockId, type, 1, nodesPerElement, 0, 0, 0), 0);
  if (extraMode & EX_BULK_INT64_API) {
    std::vector<int64_t> conn(nodesPerElement);
    for (int i = 0; i < nodesPerElement; ++i) conn[i] = nodesPerElement - i;  // reversed: 1-based N..1
    ASSERT_GE(ex_put_conn(id, EX_ELEM_BLOCK, blockId, conn.data(), nullptr, nullptr), 0);
  } else {
    std::vector<int> conn(nodesPerElement);
    for (int i = 0; i < nodesPerElement; ++i) conn[i] = nodesPerElement - i;
    ASSERT_GE(ex_put_conn(id, EX_ELEM_BLOCK, blockId, conn.data(), nullptr, nullptr), 0);
  }
  ASSERT_GE(ex_put_name(id, EX_ELEM_BLOCK, blockId, blockName), 0);
  ASSERT_GE(ex_close(id), 0);
}

}  // namespace

TEST(ExodusIo, RoundTrip3DWithVariables) {
  const std::string path = outputPath("two_hex.e");
  const GlobalMesh mesh = twoHexMesh();
  const long long nn = mesh.numNodes();
  std::vector<std::vector<double>> step1(2, std::vector<double>(nn)), step2 = step1;
  for (long long i = 0; i < nn; ++i) {
    step1[0][i] = 0.5 * i;
    step1[1][i] = -1.0 * i;
    step2[0][i] = 100.0 + i;
    step2[1][i] = 1e-3 * i * i;
  }
  {
    coulomb::io::ExodusWriter writer(path, mesh, {"displacement_x", "displacement_y"}, {"load_factor"}, "round trip");
    EXPECT_EQ(writer.numStepsWritten(), 0);
    writer.writeStep(0.25, step1, {0.5});
    writer.writeStep(1.0, step2, {1.0});
    EXPECT_EQ(writer.numStepsWritten(), 2);
    writer.close();
    writer.close();  // idempotent
    expectErrorContaining([&] { writer.writeStep(2.0, step2, {2.0}); }, {path, "close"});
  }

  expectSameMesh(mesh, coulomb::io::readExodus(path));

  // The results, through the exodusII API itself.
  int cpuWordSize = 8, ioWordSize = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  ASSERT_GE(id, 0);
  char title[MAX_LINE_LENGTH + 1] = {};
  int unusedInt = 0;
  float unusedFloat = 0;
  ASSERT_GE(ex_inquire(id, EX_INQ_TITLE, &unusedInt, &unusedFloat, title), 0);
  EXPECT_STREQ(title, "round trip");
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 2);
  int numNodal = 0, numGlobal = 0;
  ASSERT_GE(ex_get_variable_param(id, EX_NODAL, &numNodal), 0);
  ASSERT_GE(ex_get_variable_param(id, EX_GLOBAL, &numGlobal), 0);
  ASSERT_EQ(numNodal, 2);
  ASSERT_EQ(numGlobal, 1);
  char name[MAX_STR_LENGTH + 1] = {};
  ASSERT_GE(ex_get_variable_name(id, EX_NODAL, 2, name), 0);
  EXPECT_STREQ(name, "displacement_y");
  ASSERT_GE(ex_get_variable_name(id, EX_GLOBAL, 1, name), 0);
  EXPECT_STREQ(name, "load_factor");
  const std::vector<std::vector<double>>* steps[2] = {&step1, &step2};
  const double times[2] = {0.25, 1.0}, globals[2] = {0.5, 1.0};
  for (int s = 1; s <= 2; ++s) {
    double t = -1;
    ASSERT_GE(ex_get_time(id, s, &t), 0);
    EXPECT_EQ(t, times[s - 1]);
    for (int v = 1; v <= 2; ++v) {
      std::vector<double> values(nn, -7.0);
      ASSERT_GE(ex_get_var(id, s, EX_NODAL, v, 1, nn, values.data()), 0);
      EXPECT_EQ(values, (*steps[s - 1])[v - 1]) << "step " << s << " variable " << v;
    }
    double g = -1;
    ASSERT_GE(ex_get_glob_vars(id, s, 1, &g), 0);
    EXPECT_EQ(g, globals[s - 1]);
  }
  ex_close(id);
}

TEST(ExodusIo, RoundTrip2DQuadAndTri) {
  const std::string path = outputPath("quad_tri.e");
  const GlobalMesh mesh = quadTriMesh();
  { coulomb::io::ExodusWriter writer(path, mesh, {}, {}); }  // destructor closes
  const GlobalMesh back = coulomb::io::readExodus(path);
  expectSameMesh(mesh, back);
  EXPECT_EQ(back.numNodes(), 5);
  EXPECT_EQ(back.numElements(), 2);
}

/// One block per given cell type, one cell each with nodes of its own (numbered
/// backwards, so that a reader reordering nodes would be seen), a side set with
/// side 2 of every cell and a node set with every cell's last node.
GlobalMesh quadraticMesh(int dimension, const std::vector<CellType>& types) {
  GlobalMesh m;
  m.dimension = dimension;
  long long firstNode = 0;
  coulomb::mesh::SideSet sides{"second_sides", 4, {}, {}};
  coulomb::mesh::NodeSet last{"last_nodes", 6, {}};
  for (std::size_t b = 0; b < types.size(); ++b) {
    coulomb::mesh::ElementBlock block;
    block.name = coulomb::mesh::toString(types[b]);
    block.id = static_cast<int>(b + 1);
    block.cellType = types[b];
    block.firstElement = static_cast<long long>(b);
    const int n = coulomb::mesh::numNodes(types[b]);
    for (int a = 0; a < n; ++a) {
      block.connectivity.push_back(firstNode + n - 1 - a);
      for (int c = 0; c < dimension; ++c) m.coordinates.push_back(0.5 * a + 0.25 * c + 10.0 * b);
    }
    last.nodes.push_back(block.connectivity.back());
    sides.elements.push_back(static_cast<long long>(b));
    sides.sides.push_back(1);
    firstNode += n;
    m.blocks.push_back(std::move(block));
  }
  m.sideSets.push_back(sides);
  m.nodeSets.push_back(last);
  return m;
}

TEST(ExodusIo, RoundTripQuadraticCells) {
  const struct {
    const char* file;
    int dimension;
    std::vector<CellType> types;
    std::vector<std::string> written;  // the type names in the file, as ParaView reads them
  } cases[] = {{"quadratic2d.e", 2, {CellType::Quad8, CellType::Quad9, CellType::Tri6}, {"QUAD8", "QUAD9", "TRI6"}},
               {"quadratic3d.e", 3, {CellType::Hex20, CellType::Hex27, CellType::Tet10}, {"HEX20", "HEX27", "TET10"}}};
  for (const auto& c : cases) {
    const std::string path = outputPath(c.file);
    const GlobalMesh mesh = quadraticMesh(c.dimension, c.types);
    { coulomb::io::ExodusWriter writer(path, mesh, {}, {}); }
    const GlobalMesh back = coulomb::io::readExodus(path);
    expectSameMesh(mesh, back);
    ASSERT_EQ(back.blocks.size(), c.types.size());
    for (std::size_t b = 0; b < c.types.size(); ++b) {
      EXPECT_EQ(back.blocks[b].cellType, c.types[b]);
      EXPECT_EQ(back.blocks[b].connectivity, mesh.blocks[b].connectivity) << c.file << " block " << b;
    }
    // The element type string and node count in the file itself.
    int cpu = sizeof(double), io = 0;
    float version = 0;
    const int id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
    ASSERT_GE(id, 0);
    for (std::size_t b = 0; b < c.types.size(); ++b) {
      ex_block param{};
      param.id = static_cast<ex_entity_id>(b + 1);
      param.type = EX_ELEM_BLOCK;
      ASSERT_GE(ex_get_block_param(id, &param), 0);
      EXPECT_EQ(std::string(param.topology), c.written[b]);
      EXPECT_EQ(param.num_nodes_per_entry, coulomb::mesh::numNodes(c.types[b]));
    }
    ex_close(id);
  }
}

TEST(ExodusIo, FileWithoutStepsIsAPlainMesh) {
  // Variables are declared with the first step (ParaView crashes on declared
  // variables without steps); a run that stops before it leaves a mesh.
  const std::string path = outputPath("no_steps.e");
  const GlobalMesh mesh = quadTriMesh();
  { coulomb::io::ExodusWriter writer(path, mesh, {"u_x", "u_y"}, {"energy"}); }
  expectSameMesh(mesh, coulomb::io::readExodus(path));
  int cpuWordSize = 8, ioWordSize = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 0);
  int numNodal = -1;
  ex_get_variable_param(id, EX_NODAL, &numNodal);
  EXPECT_EQ(numNodal, 0);
  ex_close(id);
}

TEST(ExodusIo, WriteStepChecksSizes) {
  const std::string path = outputPath("sizes.e");
  const GlobalMesh mesh = quadTriMesh();
  coulomb::io::ExodusWriter writer(path, mesh, {"u_x", "u_y"}, {"energy"});
  const std::vector<double> good(5, 1.0), bad(4, 1.0);
  expectErrorContaining([&] { writer.writeStep(1.0, {good, bad}, {0.0}); }, {path, "u_y", "4 values"});
  expectErrorContaining([&] { writer.writeStep(1.0, {good}, {0.0}); }, {path, "nodal"});
  expectErrorContaining([&] { writer.writeStep(1.0, {good, good}, {}); }, {path, "global"});
  EXPECT_EQ(writer.numStepsWritten(), 0);
  writer.writeStep(1.0, {good, good}, {3.0});
  EXPECT_EQ(writer.numStepsWritten(), 1);
}

TEST(ExodusIo, WriterRejectsInconsistentMesh) {
  const std::string path = outputPath("inconsistent.e");
  GlobalMesh mesh = twoHexMesh();
  mesh.blocks[1].id = mesh.blocks[0].id;
  expectErrorContaining([&] { coulomb::io::ExodusWriter(path, mesh, {}, {}); }, {path, "id 10"});
  mesh = twoHexMesh();
  mesh.sideSets[0].sides[0] = 6;
  expectErrorContaining([&] { coulomb::io::ExodusWriter(path, mesh, {}, {}); }, {path, "xmin"});
  mesh = twoHexMesh();
  expectErrorContaining([&] { coulomb::io::ExodusWriter(path, mesh, {"u", "u"}, {}); }, {path, "'u'"});
}

TEST(ExodusIo, MissingFileNamesThePath) {
  const std::string path = outputPath("does_not_exist.e");
  std::filesystem::remove(path);
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path});
}

TEST(ExodusIo, NonExodusFileNamesThePath) {
  const std::string path = outputPath("not_exodus.e");
  { std::ofstream(path) << "this is not a netCDF file\n"; }
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "Exodus"});
}

// A mesh file cut short (a copy interrupted, a full disk): netCDF reads the
// missing data as zeros, so the first block refers to node 0; the message
// says the file is truncated, not that the numbering is wrong.
TEST(ExodusIo, TruncatedFileIsNamedAsSuch) {
  const std::string source = std::string(COULOMB_SOURCE_DIR) + "/exodus_meshes/block3d.e";
  const std::string path = outputPath("truncated.e");
  std::string bytes;
  {
    std::ifstream in(source, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 1000u);
  { std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() / 2); }
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "refers to node 0", "truncated"});
  EXPECT_EQ(coulomb::io::readExodus(source).numNodes(), 729);  // the whole file reads
}

// A node at NaN or infinity (a broken mesh export) is named, not carried
// into the assembly.
TEST(ExodusIo, NonFiniteCoordinateNamesTheNode) {
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const std::string path = outputPath("non_finite.e");
    GlobalMesh mesh = twoHexMesh();
    mesh.coordinates[3 * 4 + 1] = bad;  // node 5, y
    { coulomb::io::ExodusWriter writer(path, mesh, {}, {}); }
    expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "node 5", "not a finite number", "y = "});
  }
}

TEST(ExodusIo, UnsupportedElementTypeNamesTheBlock) {
  const std::string path = outputPath("wedge15.e");
  writeRawOneBlockFile(path, 3, "WEDGE15", 15, "foo", 3);
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "'foo'", "id 3", "WEDGE15", "HEX8", "HEX27"});
}

TEST(ExodusIo, BeamBlockIsRefused) {
  const std::string path = outputPath("beam.e");
  writeRawOneBlockFile(path, 3, "BEAM2", 2, "rods", 4);
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "'rods'", "id 4", "BEAM2"});
}

TEST(ExodusIo, TwoDimensionalCellInThreeDimensionalFileIsRefused) {
  const std::string path = outputPath("tri_in_3d.e");
  writeRawOneBlockFile(path, 3, "TRI3", 3, "skin", 2);
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "'skin'", "TRI3", "3D"});
}

TEST(ExodusIo, ReadsInt64ConnectivityAndWriterSpellings) {
  // 64-bit integer storage (as in netCDF-4 files of other writers), type
  // spelled "hex" in lower case: accepted; numbers become 0-based.
  const std::string path = outputPath("int64_hex.e");
  writeRawOneBlockFile(path, 3, "hex", 8, "cube", 9, EX_NETCDF4 | EX_NOCLASSIC | EX_ALL_INT64_DB | EX_ALL_INT64_API);
  const GlobalMesh mesh = coulomb::io::readExodus(path);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].cellType, CellType::Hex8);
  EXPECT_EQ(mesh.blocks[0].name, "cube");
  EXPECT_EQ(mesh.blocks[0].id, 9);
  EXPECT_EQ(mesh.blocks[0].connectivity, (std::vector<long long>{7, 6, 5, 4, 3, 2, 1, 0}));
  EXPECT_EQ(mesh.numNodes(), 8);
  EXPECT_EQ(mesh.coordinates[3 * 7 + 2], 2.0);  // z of node 8 = 7 % 5
}

TEST(ExodusIo, ElementTypeNames) {
  CellType t = CellType::Hex8;
  EXPECT_TRUE(coulomb::io::parseExodusElementType("quad", 4, t));
  EXPECT_EQ(t, CellType::Quad4);
  EXPECT_TRUE(coulomb::io::parseExodusElementType("TRI3", 3, t));
  EXPECT_EQ(t, CellType::Tri3);
  EXPECT_TRUE(coulomb::io::parseExodusElementType("TETRA", 4, t));
  EXPECT_EQ(t, CellType::Tet4);
  EXPECT_TRUE(coulomb::io::parseExodusElementType("Hex8", 8, t));
  EXPECT_EQ(t, CellType::Hex8);
  // quadratic cells: the family from the name, the member from the node count
  const struct {
    const char* name;
    int nodes;
    CellType type;
  } quadratic[] = {{"HEX", 27, CellType::Hex27},     {"HEX27", 27, CellType::Hex27},   {"hex20", 20, CellType::Hex20},
                   {"HEXAHEDRON", 20, CellType::Hex20}, {"TETRA", 10, CellType::Tet10},  {"TETRA10", 10, CellType::Tet10},
                   {"TET10", 10, CellType::Tet10},   {"QUAD", 9, CellType::Quad9},     {"QUAD9", 9, CellType::Quad9},
                   {"QUAD8", 8, CellType::Quad8},    {"TRI6", 6, CellType::Tri6},      {"TRIANGLE6", 6, CellType::Tri6},
                   {"TRIANGLE", 6, CellType::Tri6}};
  for (const auto& q : quadratic) {
    EXPECT_TRUE(coulomb::io::parseExodusElementType(q.name, q.nodes, t)) << q.name;
    EXPECT_EQ(t, q.type) << q.name;
  }
  // a number in the name that disagrees with the node count, or a count no member has
  EXPECT_FALSE(coulomb::io::parseExodusElementType("HEX27", 20, t));
  EXPECT_FALSE(coulomb::io::parseExodusElementType("QUAD8", 9, t));
  EXPECT_FALSE(coulomb::io::parseExodusElementType("TETRA", 11, t));
  EXPECT_FALSE(coulomb::io::parseExodusElementType("TRI", 7, t));
  EXPECT_FALSE(coulomb::io::parseExodusElementType("SHELL4", 4, t));
  EXPECT_FALSE(coulomb::io::parseExodusElementType("WEDGE", 6, t));
}

// A damaged file whose side-set variable is longer than the dimension the
// exodusII library sizes its buffer from (a dimension renamed to a duplicate
// name, found by tests/fuzz/fuzz_exodus: a heap overflow inside the library
// and a double free) is refused before the library reads the variable.
// A damaged maximum name length (found by fuzz_exodus: 2.7e8 characters in
// a 6 kB file) is refused before it sizes a name buffer per block and set
// (1.3 GB for 5 sets, an out-of-memory).
TEST(ExodusIo, AbsurdNameLengthIsRefusedBeforeAllocating) {
  const std::string path = std::string(COULOMB_SOURCE_DIR) + "/tests/fuzz/regressions/exodus/name_length_huge.e";
  expectErrorContaining([&] { coulomb::io::readExodus(path); },
                        {path, "the header declares names of", "characters (at most 256)", "the file is damaged"});
}

TEST(ExodusIo, VariableLongerThanItsDimensionIsRefusedBeforeReading) {
  const std::string path = std::string(COULOMB_SOURCE_DIR) + "/tests/fuzz/regressions/exodus/side_set_dimension_renamed.e";
  expectErrorContaining([&] { coulomb::io::readExodus(path); }, {path, "netCDF variable", "the file is damaged"});
}
