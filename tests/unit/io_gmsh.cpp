// Tests of the gmsh -> Exodus conversion (readGmsh + ExodusWriter, the code
// behind coulomb_gmsh2exo). A hand-written .msh checks node renumbering,
// cell flipping and side matching exactly without needing the gmsh program;
// damaged files must be errors naming the file, with nothing printed; one
// mesh written as msh 2.2, 4.1 and 4.1 binary must convert to the same
// GlobalMesh. The .geo files of exodus_meshes/ are then meshed with gmsh
// (skipped, visibly, when gmsh is not installed), written in gmsh's default
// format (4.1), and checked geometrically: every named set holds
// exactly the nodes on its face, side sets' nodes (through the exodus
// library's own side numbering) equal the node set of the same name, side
// normals point outwards, and all cells have positive measure summing to
// the domain's area/volume.
#include <gtest/gtest.h>

#include <exodusII.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/io/ExodusWriter.hpp"
#include "coulomb/io/GmshReader.hpp"

namespace {

using coulomb::mesh::CellType;
using coulomb::mesh::GlobalMesh;
using Vec = std::array<double, 3>;

std::string outputPath(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(COULOMB_BINARY_DIR) / "test_output" / "io_gmsh";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string writeText(const std::string& name, const std::string& text) {
  const std::string path = outputPath(name);
  std::ofstream(path) << text;
  return path;
}

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

// Two unit squares; the right one is listed clockwise, node 99 is an unused
// geometry point, a point element without physical group must be ignored.
const char* kTwoSquares = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
4
0 7 "corner"
1 2 "bottom"
1 3 "right"
2 1 "body"
$EndPhysicalNames
$Nodes
7
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
5 2 0 0
6 2 1 0
99 5 5 0
$EndNodes
$Elements
7
1 15 2 7 1 1
2 15 2 0 5 99
3 1 2 2 1 1 2
4 1 2 2 1 2 5
5 1 2 3 2 5 6
6 3 2 1 1 1 2 3 4
7 3 2 1 1 2 3 6 5
$EndElements
)";

Vec point(const GlobalMesh& m, long long node) {
  Vec p{0, 0, 0};
  for (int c = 0; c < m.dimension; ++c) p[c] = m.coordinates[m.dimension * node + c];
  return p;
}
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double tetVolume(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  return dot(sub(b, a), cross(sub(c, a), sub(d, a))) / 6.0;
}

/// Signed measure of cell e of block b; a hex is cut into six tetrahedra
/// around its 1-7 diagonal, each of which must be positive on its own.
double cellMeasure(const GlobalMesh& m, const coulomb::mesh::ElementBlock& b, long long e, bool* allPositive) {
  const int nn = coulomb::mesh::numNodes(b.cellType);
  std::vector<Vec> x;
  for (int i = 0; i < nn; ++i) x.push_back(point(m, b.connectivity[e * nn + i]));
  std::vector<double> parts;
  switch (coulomb::mesh::linearType(b.cellType)) {  // quadratic cells: the corners (they come first)
    case CellType::Tri3: parts = {0.5 * cross(sub(x[1], x[0]), sub(x[2], x[0]))[2]}; break;
    case CellType::Quad4:
      parts = {0.5 * cross(sub(x[1], x[0]), sub(x[2], x[0]))[2], 0.5 * cross(sub(x[2], x[0]), sub(x[3], x[0]))[2]};
      break;
    case CellType::Tet4: parts = {tetVolume(x[0], x[1], x[2], x[3])}; break;
    case CellType::Hex8: {
      const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
      for (const auto& k : t) parts.push_back(tetVolume(x[k[0]], x[k[1]], x[k[2]], x[k[3]]));
      break;
    }
    default: break;
  }
  double sum = 0;
  for (double p : parts) {
    sum += p;
    if (!(p > 0)) *allPositive = false;
  }
  return sum;
}

const coulomb::mesh::ElementBlock& blockOf(const GlobalMesh& m, long long element) {
  for (const auto& b : m.blocks)
    if (element >= b.firstElement && element < b.firstElement + b.numElements()) return b;
  throw std::logic_error("element in no block");
}

}  // namespace

TEST(GmshIo, HandWrittenTwoSquares) {
  const std::string path = writeText("two_squares.msh", kTwoSquares);
  const GlobalMesh m = coulomb::io::readGmsh(path);
  EXPECT_EQ(m.dimension, 2);
  // node 99 dropped; the others keep gmsh tag order
  EXPECT_EQ(m.coordinates, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1}));
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "body");
  EXPECT_EQ(m.blocks[0].id, 1);
  EXPECT_EQ(m.blocks[0].cellType, CellType::Quad4);
  // second square flipped to counter-clockwise: gmsh 2 3 6 5 -> 2 5 6 3
  EXPECT_EQ(m.blocks[0].connectivity, (std::vector<long long>{0, 1, 2, 3, 1, 4, 5, 2}));
  ASSERT_EQ(m.sideSets.size(), 2u);
  EXPECT_EQ(m.sideSets[0].name, "bottom");
  EXPECT_EQ(m.sideSets[0].id, 2);
  EXPECT_EQ(m.sideSets[0].elements, (std::vector<long long>{0, 1}));
  EXPECT_EQ(m.sideSets[0].sides, (std::vector<int>{0, 0}));
  EXPECT_EQ(m.sideSets[1].name, "right");
  EXPECT_EQ(m.sideSets[1].elements, (std::vector<long long>{1}));
  EXPECT_EQ(m.sideSets[1].sides, (std::vector<int>{1}));
  ASSERT_EQ(m.nodeSets.size(), 3u);
  EXPECT_EQ(m.nodeSets[0].name, "bottom");
  EXPECT_EQ(m.nodeSets[0].nodes, (std::vector<long long>{0, 1, 4}));
  EXPECT_EQ(m.nodeSets[1].name, "right");
  EXPECT_EQ(m.nodeSets[1].nodes, (std::vector<long long>{4, 5}));
  EXPECT_EQ(m.nodeSets[2].name, "corner");
  EXPECT_EQ(m.nodeSets[2].id, 7);
  EXPECT_EQ(m.nodeSets[2].nodes, (std::vector<long long>{0}));
}

TEST(GmshIo, Errors) {
  expectErrorContaining([] { coulomb::io::readGmsh(outputPath("missing.msh")); }, {outputPath("missing.msh")});

  std::string text = kTwoSquares;  // the diagonal 1-3 as a "boundary" line
  text.replace(text.find("5 1 2 3 2 5 6"), 13, "5 1 2 3 2 1 3");
  const std::string diagonal = writeText("diagonal.msh", text);
  expectErrorContaining([&] { coulomb::io::readGmsh(diagonal); }, {diagonal, "'right'", "not a side"});

  text = kTwoSquares;  // the second square as two triangles: mixed types in "body"
  text.replace(text.find("7\n1 15"), 6, "8\n1 15");
  text.replace(text.find("7 3 2 1 1 2 3 6 5"), 17, "7 2 2 1 1 2 5 6\n8 2 2 1 1 2 6 3");
  const std::string mixed = writeText("mixed.msh", text);
  // gmsh's names of the types
  expectErrorContaining([&] { coulomb::io::readGmsh(mixed); }, {mixed, "'body'", "Quadrilateral 4", "Triangle 3"});

  text = kTwoSquares;  // both squares as third-order quadrangles, which Coulomb has not
  text.replace(text.find("6 3 2 1 1 1 2 3 4"), 17, "6 36 2 1 1 1 2 3 4 1 2 3 4 1 2 3 4 1 2 3 4");
  text.replace(text.find("7 3 2 1 1 2 3 6 5"), 17, "7 36 2 1 1 2 3 6 5 2 3 6 5 2 3 6 5 2 3 6 5");
  const std::string cubic = writeText("cubic.msh", text);
  expectErrorContaining([&] { coulomb::io::readGmsh(cubic); }, {cubic, "'body'", "Quadrilateral 16", "supported"});

  text = kTwoSquares;  // the body in the plane z = 1
  for (const char* line : {"1 0 0 0\n", "2 1 0 0\n", "3 1 1 0\n", "4 0 1 0\n", "5 2 0 0\n", "6 2 1 0\n"}) {
    std::string moved = line;
    moved.replace(moved.size() - 2, 1, "1");
    text.replace(text.find(line), moved.size(), moved);
  }
  const std::string lifted = writeText("lifted.msh", text);
  expectErrorContaining([&] { coulomb::io::readGmsh(lifted); }, {lifted, "z = 0"});
}

// Files that are no mesh, or damaged ones: a coulomb::Error naming the file,
// nothing on stdout (gmsh's messages go to its logger), and the next file
// reads (gmsh 4.8 stays locked after an error unless it is started afresh).
TEST(GmshIo, DamagedFilesAreErrorsNamingTheFile) {
  std::vector<std::pair<std::string, std::string>> files = {  // name, content
      {"garbage.msh", "this is no mesh\n"},
      {"script.msh", "Point(1) = {0, 0, 0};\n"},  // a .geo script: never given to gmsh's parser
      {"empty.msh", ""},
      {"bad_format.msh", "$MeshFormat\nnot a version\n$EndMeshFormat\n"},
      {"truncated22.msh", std::string(kTwoSquares).substr(0, std::string(kTwoSquares).find("3 1 1 0"))},
      {"bad_node_line.msh", std::string(kTwoSquares).replace(std::string(kTwoSquares).find("2 1 0 0"), 7, "2 x y z")}};
  // Meshes of gmsh's own, cut in half: 4.1 ASCII and binary.
  if (std::system("gmsh --version > /dev/null 2>&1") == 0) {
    for (const std::string format : {"", "-bin"}) {
      const std::string whole = outputPath("whole" + format + ".msh");
      const std::string command = "gmsh -2 -v 0 " + format + " -setnumber n 4 -o " + whole + " " +
                                  std::string(COULOMB_SOURCE_DIR) + "/exodus_meshes/block2d.geo > /dev/null 2>&1";
      ASSERT_EQ(std::system(command.c_str()), 0) << command;
      std::ifstream in(whole, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      files.push_back({"half" + format + ".msh", bytes.substr(0, bytes.size() / 2)});
    }
  }
  const std::string good = writeText("good.msh", kTwoSquares);
  for (const auto& [name, content] : files) {
    SCOPED_TRACE(name);
    std::string path = outputPath(name);
    std::ofstream(path, std::ios::binary) << content;
    testing::internal::CaptureStdout();
    expectErrorContaining([&] { coulomb::io::readGmsh(path); }, {path});
    EXPECT_EQ(coulomb::io::readGmsh(good).numElements(), 2);
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  }
}

// Found by tests/fuzz (fuzz_gmsh; input tests/fuzz/regressions/gmsh/):
// a node or element count far beyond what the file holds was reserved
// ahead of reading, ending in std::length_error / bad_alloc instead of a
// message naming the file.
TEST(GmshIo, HugeCountIsAnErrorNotAnAllocation) {
  for (const char* count : {"$Nodes\n123456789012345\n", "$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n98765432109876\n"}) {
    const std::string path = writeText("huge_count.msh", std::string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n") + count);
    expectErrorContaining([&] { coulomb::io::readGmsh(path); }, {path});
  }
}

TEST(GmshIo, ConverterToolReportsErrorsOnOneLine) {
  const std::string tool = std::string(COULOMB_BINARY_DIR) + "/coulomb_gmsh2exo";
  if (!std::filesystem::exists(tool)) GTEST_SKIP() << "coulomb_gmsh2exo not built yet at " << tool;
  const std::string in = writeText("tool_in.msh", kTwoSquares), out = outputPath("tool_out.e");
  const std::string log = outputPath("tool_stderr.txt");
  ASSERT_EQ(std::system((tool + " " + in + " " + out + " > /dev/null 2> " + log).c_str()), 0);
  const GlobalMesh m = coulomb::io::readExodus(out);
  EXPECT_EQ(m.numNodes(), 6);
  EXPECT_EQ(m.numElements(), 2);
  // A missing file, one gmsh cannot read (cut inside $Nodes) and one gmsh
  // crashes on: exit 1, one line on stderr naming the file, nothing on stdout.
  const std::string missing = outputPath("no_such_input.msh");
  const std::string squares = kTwoSquares;
  const std::string cut = writeText("tool_cut.msh", squares.substr(0, squares.find("3 1 1 0")));
  const std::string crash = std::string(COULOMB_SOURCE_DIR) + "/tests/fuzz/gmsh_crashes/physical_name_unterminated.msh";
  for (const std::string& bad : {missing, cut, crash}) {
    std::filesystem::remove(out);
    SCOPED_TRACE(bad);
    const std::string stdoutLog = outputPath("tool_stdout.txt");
    const int status = std::system((tool + " " + bad + " " + out + " > " + stdoutLog + " 2> " + log).c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << "status " << status;
    std::ifstream err(log);
    std::string line, extra;
    ASSERT_TRUE(std::getline(err, line));
    EXPECT_NE(line.find(bad), std::string::npos) << line;
    EXPECT_FALSE(std::getline(err, extra)) << "more than one line on stderr: " << extra;
    EXPECT_EQ(std::filesystem::file_size(stdoutLog), 0u);
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

namespace {

struct GeoCase {
  std::string geo;
  int dim;
  int n;
  CellType type;
  long long nodes, elements;  // -1: not checked (unstructured)
  double measure, measureTolerance;
  /// name -> predicate "node lies on this boundary part"
  std::map<std::string, std::function<bool(const Vec&)>> sets;
  std::string gmshOptions = "";  ///< e.g. "-order 2"
  bool straight = true;          ///< straight-edged: higher-order nodes sit at the mean of their corners
};

bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

void checkGeo(const GeoCase& c) {
  if (std::system("gmsh --version > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "gmsh is not installed: skipping the .geo -> .msh -> Exodus round trip of " << c.geo;
  const std::string stem = std::filesystem::path(c.geo).stem().string() + "_" + coulomb::mesh::toString(c.type);
  const std::string msh = outputPath(stem + ".msh"), exo = outputPath(stem + ".e");
  std::filesystem::remove(msh);
  const std::string command = "gmsh -" + std::to_string(c.dim) + " -v 1 -setnumber n " +
                              std::to_string(c.n) + " " + c.gmshOptions + " -o " + msh + " " + std::string(COULOMB_SOURCE_DIR) +
                              "/exodus_meshes/" + c.geo + " > " + outputPath(stem + ".gmsh.log") + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  {
    coulomb::io::ExodusWriter writer(exo, coulomb::io::readGmsh(msh), {}, {});
  }
  const GlobalMesh m = coulomb::io::readExodus(exo);

  EXPECT_EQ(m.dimension, c.dim);
  if (c.nodes >= 0) {
    EXPECT_EQ(m.numNodes(), c.nodes);
  }
  if (c.elements >= 0) {
    EXPECT_EQ(m.numElements(), c.elements);
  }
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "body");
  EXPECT_EQ(m.blocks[0].cellType, c.type);

  bool allPositive = true;
  double measure = 0;
  for (long long e = 0; e < m.blocks[0].numElements(); ++e) measure += cellMeasure(m, m.blocks[0], e, &allPositive);
  EXPECT_TRUE(allPositive) << "a cell (or sub-tetrahedron of a hex) has non-positive measure";
  EXPECT_NEAR(measure, c.measure, c.measureTolerance);
  // gmsh's higher-order nodes converted to the Exodus order: on a straight-edged
  // mesh each sits at the mean of the corners coulomb::mesh::nodeCorners names.
  const auto& block = m.blocks[0];
  const int perCell = coulomb::mesh::numNodes(block.cellType);
  for (long long e = 0; e < block.numElements() && c.straight; ++e)
    for (int a = coulomb::mesh::numCorners(block.cellType); a < perCell; ++a) {
      const coulomb::mesh::NodeCorners corners = coulomb::mesh::nodeCorners(block.cellType, a);
      Vec mean{0, 0, 0};
      for (int k = 0; k < corners.count; ++k)
        for (int d = 0; d < 3; ++d) mean[d] += point(m, block.connectivity[e * perCell + corners.corners[k]])[d] / corners.count;
      const Vec x = point(m, block.connectivity[e * perCell + a]);
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(x[d], mean[d], 1e-12) << "element " << e + 1 << " node " << a + 1;
    }

  // Side set nodes through the exodus library's own side numbering.
  int cpuWordSize = 8, ioWordSize = 0;
  float version = 0;
  const int exoId = ex_open(exo.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  ASSERT_GE(exoId, 0);

  ASSERT_EQ(m.sideSets.size(), c.sets.size());
  ASSERT_EQ(m.nodeSets.size(), c.sets.size());
  for (std::size_t s = 0; s < m.sideSets.size(); ++s) {
    const auto& side = m.sideSets[s];
    const auto& nodes = m.nodeSets[s];
    SCOPED_TRACE(c.geo + " set '" + side.name + "'");
    ASSERT_EQ(side.name, nodes.name);
    ASSERT_TRUE(c.sets.count(side.name));
    const auto& onPart = c.sets.at(side.name);

    std::set<long long> expected;
    for (long long i = 0; i < m.numNodes(); ++i)
      if (onPart(point(m, i))) expected.insert(i);
    EXPECT_EQ(std::set<long long>(nodes.nodes.begin(), nodes.nodes.end()), expected);
    EXPECT_EQ(nodes.nodes.size(), expected.size()) << "duplicates in the node set";

    std::set<long long> ours;
    for (std::size_t k = 0; k < side.elements.size(); ++k) {
      const auto& b = blockOf(m, side.elements[k]);
      const int nn = coulomb::mesh::numNodes(b.cellType);
      const long long local = side.elements[k] - b.firstElement;
      std::vector<Vec> f;
      for (int l : coulomb::io::exodusSideNodes(b.cellType, side.sides[k])) {
        const long long node = b.connectivity[local * nn + l];
        ours.insert(node);
        f.push_back(point(m, node));
      }
      Vec cellCentre{0, 0, 0}, faceCentre{0, 0, 0};
      for (int i = 0; i < nn; ++i)
        for (int d = 0; d < 3; ++d) cellCentre[d] += point(m, b.connectivity[local * nn + i])[d] / nn;
      for (const auto& p : f)
        for (int d = 0; d < 3; ++d) faceCentre[d] += p[d] / f.size();
      const Vec normal = c.dim == 2 ? Vec{f[1][1] - f[0][1], f[0][0] - f[1][0], 0}
                                    : cross(sub(f[1], f[0]), sub(f[2], f[0]));
      EXPECT_GT(dot(normal, sub(faceCentre, cellCentre)), 0)
          << "normal of side " << side.sides[k] << " of element " << side.elements[k] << " points inwards";
    }
    EXPECT_EQ(ours, expected);

    int64_t count = 0, factors = 0;
    ASSERT_GE(ex_get_set_param(exoId, EX_SIDE_SET, side.id, &count, &factors), 0);
    std::vector<int> perSide(count), sideNodes(count * coulomb::mesh::kMaxFaceNodes);
    ASSERT_GE(ex_get_side_set_node_list(exoId, side.id, perSide.data(), sideNodes.data()), 0);
    std::set<long long> library;
    std::size_t offset = 0;
    for (int k = 0; k < count; ++k) {
      EXPECT_EQ(perSide[k], static_cast<int>(coulomb::io::exodusSideNodes(c.type, 0).size()));
      for (int i = 0; i < perSide[k]; ++i) library.insert(sideNodes[offset + i] - 1);
      offset += perSide[k];
    }
    EXPECT_EQ(library, expected);
  }
  ex_close(exoId);
}

std::map<std::string, std::function<bool(const Vec&)>> rectangleSets(double width, double height) {
  return {{"bottom", [](const Vec& p) { return near(p[1], 0); }},
          {"top", [=](const Vec& p) { return near(p[1], height); }},
          {"left", [](const Vec& p) { return near(p[0], 0); }},
          {"right", [=](const Vec& p) { return near(p[0], width); }}};
}

std::map<std::string, std::function<bool(const Vec&)>> cubeSets() {
  return {{"bottom", [](const Vec& p) { return near(p[2], 0); }}, {"top", [](const Vec& p) { return near(p[2], 1); }},
          {"left", [](const Vec& p) { return near(p[0], 0); }},   {"right", [](const Vec& p) { return near(p[0], 1); }},
          {"front", [](const Vec& p) { return near(p[1], 0); }},  {"back", [](const Vec& p) { return near(p[1], 1); }}};
}

}  // namespace

TEST(GmshIo, Block2dQuad) {
  checkGeo({"block2d.geo", 2, 3, CellType::Quad4, 7 * 4, 6 * 3, 2.0, 1e-12, rectangleSets(2, 1)});
}

TEST(GmshIo, Block2dTri) {
  checkGeo({"block2d_tri.geo", 2, 3, CellType::Tri3, 7 * 4, 2 * 6 * 3, 2.0, 1e-12, rectangleSets(2, 1)});
}

TEST(GmshIo, Block3dHex) {
  checkGeo({"block3d.geo", 3, 3, CellType::Hex8, 4 * 4 * 4, 27, 1.0, 1e-12, cubeSets()});
}

TEST(GmshIo, Block3dTet) { checkGeo({"block3d_tet.geo", 3, 3, CellType::Tet4, -1, -1, 1.0, 1e-12, cubeSets()}); }

// Order-2 meshes of the same scripts (what scripts/make_mesh -order 2 makes):
// complete (QUAD9, TRI6, HEX27, TET10) and, with Mesh.SecondOrderIncomplete,
// serendipity (QUAD8, HEX20).
const std::string kOrder2 = "-order 2";
const std::string kIncomplete = "-order 2 -string Mesh.SecondOrderIncomplete=1\\;";

TEST(GmshIo, Block2dQuad9) {
  checkGeo({"block2d.geo", 2, 3, CellType::Quad9, 13 * 7, 6 * 3, 2.0, 1e-12, rectangleSets(2, 1), kOrder2});
}
TEST(GmshIo, Block2dQuad8) {
  checkGeo({"block2d.geo", 2, 3, CellType::Quad8, 13 * 7 - 18, 6 * 3, 2.0, 1e-12, rectangleSets(2, 1), kIncomplete});
}
TEST(GmshIo, Block2dTri6) {
  checkGeo({"block2d_tri.geo", 2, 3, CellType::Tri6, 13 * 7, 2 * 6 * 3, 2.0, 1e-12, rectangleSets(2, 1), kOrder2});
}
TEST(GmshIo, Block3dHex27) {
  checkGeo({"block3d.geo", 3, 3, CellType::Hex27, 7 * 7 * 7, 27, 1.0, 1e-12, cubeSets(), kOrder2});
}
TEST(GmshIo, Block3dHex20) {
  checkGeo({"block3d.geo", 3, 3, CellType::Hex20, 64 + 3 * 48, 27, 1.0, 1e-12, cubeSets(), kIncomplete});
}
TEST(GmshIo, Block3dTet10) {
  checkGeo({"block3d_tet.geo", 3, 3, CellType::Tet10, -1, -1, 1.0, 1e-12, cubeSets(), kOrder2});
}

TEST(GmshIo, QuarterAnnulus) {
  // The arcs are polygons of 2n = 8 chords: the meshed area is that between
  // two inscribed polygons, 8 * (2^2 - 1^2) * sin(pi/16) / 2, 0.64 % below 3*pi/4.
  const auto radius = [](const Vec& p) { return std::hypot(p[0], p[1]); };
  checkGeo({"quarter_annulus2d.geo", 2, 4, CellType::Quad4, 5 * 9, 4 * 8, 12.0 * std::sin(M_PI / 16.0), 1e-9,
            {{"inner", [=](const Vec& p) { return std::abs(radius(p) - 1) < 1e-9; }},
             {"outer", [=](const Vec& p) { return std::abs(radius(p) - 2) < 1e-9; }},
             {"symmetry_x", [](const Vec& p) { return near(p[0], 0); }},
             {"symmetry_y", [](const Vec& p) { return near(p[1], 0); }}}});
}

TEST(GmshIo, QuarterAnnulusQuad9) {
  // Order 2: the edge nodes on the arcs lie on the circles (so not at their
  // corners' mean: straight = false); the corner polygon is the one above.
  const auto radius = [](const Vec& p) { return std::hypot(p[0], p[1]); };
  checkGeo({"quarter_annulus2d.geo", 2, 4, CellType::Quad9, 9 * 17, 4 * 8, 12.0 * std::sin(M_PI / 16.0), 1e-9,
            {{"inner", [=](const Vec& p) { return std::abs(radius(p) - 1) < 1e-9; }},
             {"outer", [=](const Vec& p) { return std::abs(radius(p) - 2) < 1e-9; }},
             {"symmetry_x", [](const Vec& p) { return near(p[0], 0); }},
             {"symmetry_y", [](const Vec& p) { return near(p[1], 0); }}},
            kOrder2, false});
}

namespace {

// Two bodies side by side, one of triangles and one of quadrangles, an
// interior curve, a physical point (a node set of its own).
const char* kTwoBodies2d = R"(// dim: 2
n = 3;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0}; Point(5) = {1, 1, 0}; Point(6) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Curve{:} = n + 1;
Transfinite Surface{2}; Recombine Surface{2};
Physical Surface("tris", 1) = {1};
Physical Surface("quads", 2) = {2};
Physical Curve("bottom", 3) = {1, 2};
Physical Curve("interface", 4) = {7};
Physical Point("origin", 5) = {1};
)";

// Two unstructured boxes sharing a face; a physical curve and point (node sets).
const char* kTwoBoxes3d = R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Coherence;
Mesh.MeshSizeMax = 0.4;
e = 1e-3;
Physical Volume("left", 1) = {1};
Physical Volume("right", 2) = {2};
Physical Surface("bottom", 3) = Surface In BoundingBox{-e, -e, -e, 2 + e, 1 + e, e};
Physical Curve("edge", 4) = Curve In BoundingBox{-e, -e, -e, e, 1 + e, e};
Physical Point("origin", 5) = Point In BoundingBox{-e, -e, -e, e, e, e};
)";

/// Same mesh: coordinates within @p tolerance (0: bit for bit), the rest exactly.
void expectSameMesh(const char* what, const GlobalMesh& a, const GlobalMesh& b, double tolerance) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.dimension, b.dimension);
  if (tolerance == 0) {
    EXPECT_EQ(a.coordinates, b.coordinates);
  } else {
    ASSERT_EQ(a.coordinates.size(), b.coordinates.size());
    for (std::size_t i = 0; i < a.coordinates.size(); ++i)
      ASSERT_NEAR(a.coordinates[i], b.coordinates[i], tolerance) << "coordinate " << i;
  }
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].name, b.blocks[i].name);
    EXPECT_EQ(a.blocks[i].id, b.blocks[i].id);
    EXPECT_EQ(a.blocks[i].cellType, b.blocks[i].cellType);
    EXPECT_EQ(a.blocks[i].firstElement, b.blocks[i].firstElement);
    EXPECT_EQ(a.blocks[i].connectivity, b.blocks[i].connectivity) << "block " << a.blocks[i].name;
  }
  ASSERT_EQ(a.sideSets.size(), b.sideSets.size());
  for (std::size_t i = 0; i < a.sideSets.size(); ++i) {
    EXPECT_EQ(a.sideSets[i].name, b.sideSets[i].name);
    EXPECT_EQ(a.sideSets[i].id, b.sideSets[i].id);
    EXPECT_EQ(a.sideSets[i].elements, b.sideSets[i].elements) << "side set " << a.sideSets[i].name;
    EXPECT_EQ(a.sideSets[i].sides, b.sideSets[i].sides) << "side set " << a.sideSets[i].name;
  }
  ASSERT_EQ(a.nodeSets.size(), b.nodeSets.size());
  for (std::size_t i = 0; i < a.nodeSets.size(); ++i) {
    EXPECT_EQ(a.nodeSets[i].name, b.nodeSets[i].name);
    EXPECT_EQ(a.nodeSets[i].id, b.nodeSets[i].id);
    EXPECT_EQ(a.nodeSets[i].nodes, b.nodeSets[i].nodes) << "node set " << a.nodeSets[i].name;
  }
}

struct FormatCase {
  std::string label, geo;  // geo: a path
  int dim;
  std::string options;
  std::vector<CellType> types;  // of the blocks, in order
  std::size_t nodeSets;
};

}  // namespace

// One mesh, written by gmsh as msh 2.2, 4.1 and 4.1 binary, converts to the
// same GlobalMesh, linear and quadratic (gmsh meshes a .geo the same way each time).
TEST(GmshIo, FormatsGiveTheSameMesh) {
  if (std::system("gmsh --version > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "gmsh is not installed: skipping the msh 2.2 / 4.1 / binary comparison";
  const std::string twoBodies = writeText("two_bodies2d.geo", kTwoBodies2d);
  const std::string twoBoxes = writeText("two_boxes3d.geo", kTwoBoxes3d);
  const std::string block3d = std::string(COULOMB_SOURCE_DIR) + "/exodus_meshes/block3d.geo";
  const std::vector<FormatCase> cases = {
      {"two_bodies", twoBodies, 2, "", {CellType::Tri3, CellType::Quad4}, 3},
      {"two_bodies_order2", twoBodies, 2, kOrder2, {CellType::Tri6, CellType::Quad9}, 3},
      {"two_bodies_serendipity", twoBodies, 2, kIncomplete, {CellType::Tri6, CellType::Quad8}, 3},
      {"two_boxes", twoBoxes, 3, "", {CellType::Tet4, CellType::Tet4}, 3},
      {"two_boxes_order2", twoBoxes, 3, kOrder2, {CellType::Tet10, CellType::Tet10}, 3},
      {"block3d_hex20", block3d, 3, "-setnumber n 2 " + kIncomplete, {CellType::Hex20}, 6},
      {"block3d_hex27", block3d, 3, "-setnumber n 2 " + kOrder2, {CellType::Hex27}, 6}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.label);
    std::vector<GlobalMesh> meshes;
    for (const std::string format : {"-format msh22", "-format msh41", "-format msh41 -bin"}) {
      const std::string msh = outputPath(c.label + "_" + std::to_string(meshes.size()) + ".msh");
      const std::string command = "gmsh -" + std::to_string(c.dim) + " -v 1 " + format + " " + c.options + " -o " +
                                  msh + " " + c.geo + " > " + msh + ".log 2>&1";
      ASSERT_EQ(std::system(command.c_str()), 0) << command;
      meshes.push_back(coulomb::io::readGmsh(msh));
    }
    const GlobalMesh& m = meshes[0];
    ASSERT_EQ(m.blocks.size(), c.types.size());
    for (std::size_t b = 0; b < c.types.size(); ++b) EXPECT_EQ(m.blocks[b].cellType, c.types[b]);
    EXPECT_EQ(m.nodeSets.size(), c.nodeSets);
    for (const auto& set : m.sideSets) EXPECT_FALSE(set.elements.empty()) << set.name;
    for (const auto& set : m.nodeSets) EXPECT_FALSE(set.nodes.empty()) << set.name;
    expectSameMesh("msh 2.2 against msh 4.1", meshes[0], meshes[1], 0);
    // gmsh's ASCII files hold 16 significant digits, one short of what gives
    // every double back: the binary file's coordinates may differ in the last
    // bit (the domains here are of size 1 to 2).
    expectSameMesh("msh 4.1 against msh 4.1 binary", meshes[1], meshes[2], 1e-15);
  }
}
