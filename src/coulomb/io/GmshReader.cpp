/// @file GmshReader.cpp
/// @brief readGmsh(): parse gmsh 2.2 ASCII, then build blocks and sets (rules
/// in GmshReader.hpp).
///
/// The side sets are what the solver's contact search and Neumann loads use,
/// so every boundary element must match a bulk element side exactly; a
/// mismatch is an error rather than a silently smaller set.
#include "coulomb/io/GmshReader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/GmshNodeOrder.hpp"

namespace coulomb::io {
namespace {

// Largest number of nodes or elements reserved ahead of reading them.
constexpr long long kMaxReserve = 1 << 20;

using mesh::CellType;

struct GmshElement {
  long long tag = 0;
  int type = 0;
  int physical = 0;  // 0: in no physical group
  std::vector<long long> nodes;  // gmsh node tags
};

struct GmshFile {
  std::map<std::pair<int, int>, std::string> physicalNames;  // (dim, tag) -> name
  std::vector<long long> nodeTags;
  std::vector<double> xyz;  // 3 per node
  std::vector<GmshElement> elements;
};

/// Dimension of a gmsh element type, -1 if unknown.
int gmshDimension(int type) {
  switch (type) {
    case 15: return 0;
    case 1: case 8: case 26: case 27: case 28: return 1;
    case 2: case 3: case 9: case 10: case 16: case 20: case 21: case 22: case 23: case 24: case 25: return 2;
    case 4: case 5: case 6: case 7: case 11: case 12: case 13: case 14: case 17: case 18: case 19: case 29:
    case 92: case 93: return 3;
    default: return -1;
  }
}

/// Number of nodes of the types we convert (first and second order), 0 for the others.
int gmshSupportedNodes(int type) {
  switch (type) {
    case 15: return 1;
    case 1: return 2;
    case 2: return 3;
    case 3: return 4;
    case 4: return 4;
    case 5: return 8;
    case 8: return 3;
    case 9: return 6;
    case 10: return 9;
    case 11: return 10;
    case 12: return 27;
    case 16: return 8;
    case 17: return 20;
    default: return 0;
  }
}

std::string gmshTypeName(int type) {
  switch (type) {
    case 1: return "2-node line";
    case 2: return "3-node triangle";
    case 3: return "4-node quadrangle";
    case 4: return "4-node tetrahedron";
    case 5: return "8-node hexahedron";
    case 6: return "6-node prism";
    case 7: return "5-node pyramid";
    case 8: return "3-node line";
    case 9: return "6-node triangle";
    case 10: return "9-node quadrangle";
    case 11: return "10-node tetrahedron";
    case 12: return "27-node hexahedron";
    case 15: return "point";
    case 16: return "8-node quadrangle";
    case 17: return "20-node hexahedron";
    default: return "type " + std::to_string(type);
  }
}

class Parser {
public:
  explicit Parser(const std::string& path) : path_(path), in_(path) {
    COULOMB_REQUIRE(in_.good(), "gmsh mesh '" << path_ << "': cannot open file (missing or not readable)");
  }

  GmshFile parse() {
    std::string line;
    bool sawFormat = false, sawNodes = false, sawElements = false;
    while (next(line)) {
      if (line.empty()) continue;
      COULOMB_REQUIRE(line[0] == '$', where() << "expected a section start like $Nodes, got '" << line << "'");
      const std::string section = line.substr(1);
      if (section == "MeshFormat") {
        readFormat();
        sawFormat = true;
      } else if (section == "PhysicalNames") {
        readPhysicalNames();
      } else if (section == "Nodes") {
        COULOMB_REQUIRE(sawFormat, where() << "$Nodes before $MeshFormat");
        readNodes();
        sawNodes = true;
      } else if (section == "Elements") {
        readElements();
        sawElements = true;
      } else {
        skipSection(section);  // $Periodic, $NodeData, ... are not needed
      }
    }
    COULOMB_REQUIRE(sawFormat && sawNodes && sawElements,
                    "gmsh mesh '" << path_ << "': missing $MeshFormat, $Nodes or $Elements section");
    return std::move(file_);
  }

private:
  bool next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++lineNumber_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    line = first == std::string::npos ? std::string() : line.substr(first);
    return true;
  }
  std::string where() const { return "gmsh mesh '" + path_ + "' line " + std::to_string(lineNumber_) + ": "; }

  std::string require(const char* what) {
    std::string line;
    COULOMB_REQUIRE(next(line), "gmsh mesh '" << path_ << "': file ends inside " << what);
    return line;
  }
  void expectEnd(const std::string& section) {
    const std::string line = require(section.c_str());
    COULOMB_REQUIRE(line.rfind("$End" + section, 0) == 0, where() << "expected $End" << section << ", got '" << line << "'");
  }
  long long readCount(const char* what) {
    std::istringstream s(require(what));
    long long n = -1;
    COULOMB_REQUIRE((s >> n) && n >= 0, where() << "expected the number of " << what);
    return n;
  }

  void readFormat() {
    std::istringstream s(require("$MeshFormat"));
    std::string version;
    int fileType = -1, dataSize = 0;
    s >> version >> fileType >> dataSize;
    COULOMB_REQUIRE(version.rfind("2.", 0) == 0,
                    where() << "msh format " << version << " is not supported; write format 2.2 ASCII "
                            << "(gmsh -format msh22, or Mesh.MshFileVersion = 2.2;)");
    COULOMB_REQUIRE(fileType == 0, where() << "binary .msh files are not supported; write ASCII (Mesh.Binary = 0;)");
    expectEnd("MeshFormat");
  }

  void readPhysicalNames() {
    const long long n = readCount("physical names");
    for (long long i = 0; i < n; ++i) {
      const std::string line = require("$PhysicalNames");
      std::istringstream s(line);
      int dim = -1, tag = 0;
      COULOMB_REQUIRE(s >> dim >> tag, where() << "bad physical name line '" << line << "'");
      const auto open = line.find('"'), close = line.rfind('"');
      COULOMB_REQUIRE(open != std::string::npos && close > open, where() << "physical name without quotes");
      file_.physicalNames[{dim, tag}] = line.substr(open + 1, close - open - 1);
    }
    expectEnd("PhysicalNames");
  }

  void readNodes() {
    const long long n = readCount("nodes");
    // The count is the file's word: reserve at most what a plausible file
    // holds (a corrupted count then ends at a bad line, not in a huge allocation).
    const auto expected = static_cast<std::size_t>(std::min(n, kMaxReserve));
    file_.nodeTags.reserve(expected);
    file_.xyz.reserve(3 * expected);
    for (long long i = 0; i < n; ++i) {
      std::istringstream s(require("$Nodes"));
      long long tag = 0;
      double x = 0, y = 0, z = 0;
      COULOMB_REQUIRE(s >> tag >> x >> y >> z, where() << "bad node line");
      file_.nodeTags.push_back(tag);
      file_.xyz.insert(file_.xyz.end(), {x, y, z});
    }
    expectEnd("Nodes");
  }

  void readElements() {
    const long long n = readCount("elements");
    file_.elements.reserve(static_cast<std::size_t>(std::min(n, kMaxReserve)));
    for (long long i = 0; i < n; ++i) {
      std::istringstream s(require("$Elements"));
      GmshElement e;
      int numTags = 0;
      COULOMB_REQUIRE(s >> e.tag >> e.type >> numTags && numTags >= 0, where() << "bad element line");
      for (int t = 0; t < numTags; ++t) {
        int value = 0;
        COULOMB_REQUIRE(s >> value, where() << "element " << e.tag << ": missing tag");
        if (t == 0) e.physical = value;
      }
      long long node = 0;
      while (s >> node) e.nodes.push_back(node);
      const int expected = gmshSupportedNodes(e.type);
      COULOMB_REQUIRE(expected == 0 || static_cast<int>(e.nodes.size()) == expected,
                      where() << "element " << e.tag << " (" << gmshTypeName(e.type) << ") has " << e.nodes.size()
                              << " nodes, expected " << expected);
      file_.elements.push_back(std::move(e));
    }
    expectEnd("Elements");
  }

  void skipSection(const std::string& section) {
    std::string line;
    while (next(line))
      if (line.rfind("$End" + section, 0) == 0) return;
    throw Error("gmsh mesh '" + path_ + "': section $" + section + " has no $End" + section);
  }

  std::string path_;
  std::ifstream in_;
  long long lineNumber_ = 0;
  GmshFile file_;
};

// ---------------------------------------------------------------------------
// Geometry of cells: orientation and validity

using Point = std::array<double, 3>;

double cross2(const Point& a, const Point& b, const Point& c) {  // (b-a) x (c-a), z component
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}
double det3(const Point& o, const Point& a, const Point& b, const Point& c) {  // (a-o).((b-o)x(c-o))
  const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
  const double v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
  const double w[3] = {c[0] - o[0], c[1] - o[1], c[2] - o[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Corner "Jacobians" of a cell: all positive iff the cell is valid and
/// positively oriented (for simplices there is one, the signed measure).
std::vector<double> cornerJacobians(CellType type, const std::vector<Point>& x) {
  // A quadratic cell by its corners (they lead its node list): a cell whose
  // straight-sided corner cell is inverted is flipped like that cell.
  if (mesh::isQuadratic(type)) return cornerJacobians(mesh::linearType(type), x);
  switch (type) {
    case CellType::Tri3: return {cross2(x[0], x[1], x[2])};
    case CellType::Quad4: {
      std::vector<double> j(4);
      for (int i = 0; i < 4; ++i) j[i] = cross2(x[i], x[(i + 1) % 4], x[(i + 3) % 4]);
      return j;
    }
    case CellType::Tet4: return {det3(x[0], x[1], x[2], x[3])};
    case CellType::Hex8: {
      // For corner i: its neighbours along the local xi, eta, zeta directions.
      static const int corner[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                       {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
      std::vector<double> j(8);
      for (int i = 0; i < 8; ++i) j[i] = det3(x[i], x[corner[i][0]], x[corner[i][1]], x[corner[i][2]]);
      return j;
    }
    default: break;
  }
  return {};
}


CellType cellTypeOf(int gmshType) {
  switch (gmshType) {
    case 2: return CellType::Tri3;
    case 3: return CellType::Quad4;
    case 4: return CellType::Tet4;
    case 9: return CellType::Tri6;
    case 10: return CellType::Quad9;
    case 11: return CellType::Tet10;
    case 12: return CellType::Hex27;
    case 16: return CellType::Quad8;
    case 17: return CellType::Hex20;
    default: return CellType::Hex8;
  }
}


using FaceKey = std::array<long long, mesh::kMaxFaceNodes>;  // sorted node numbers, padded with -1

FaceKey faceKey(std::vector<long long> nodes) {
  std::sort(nodes.begin(), nodes.end());
  FaceKey key;
  key.fill(-1);
  std::copy(nodes.begin(), nodes.end(), key.begin());
  return key;
}

class Converter {
public:
  Converter(const std::string& path, GmshFile file) : path_(path), file_(std::move(file)) {}

  mesh::GlobalMesh convert() {
    findDimension();
    for (std::size_t i = 0; i < file_.nodeTags.size(); ++i) {
      COULOMB_REQUIRE(nodeIndex_.emplace(file_.nodeTags[i], i).second,
                      prefix() << "node " << file_.nodeTags[i] << " is defined twice");
    }
    buildBlocks();
    buildSets();
    return std::move(mesh_);
  }

private:
  std::string prefix() const { return "gmsh mesh '" + path_ + "': "; }
  std::string groupLabel(int dim, int tag) const {
    static const char* kinds[] = {"point", "curve", "surface", "volume"};
    const auto found = file_.physicalNames.find({dim, tag});
    return "physical " + std::string(kinds[dim]) + " " +
           (found == file_.physicalNames.end() ? std::string() : "'" + found->second + "' ") + "(tag " +
           std::to_string(tag) + ")";
  }
  std::string nameOf(int dim, int tag) const {
    const auto found = file_.physicalNames.find({dim, tag});
    return found == file_.physicalNames.end() ? std::string() : found->second;
  }

  void findDimension() {
    dim_ = -1;
    for (const auto& e : file_.elements) {
      if (e.physical == 0) continue;
      const int d = gmshDimension(e.type);
      COULOMB_REQUIRE(d >= 0, prefix() << "element " << e.tag << " has unknown gmsh element type " << e.type);
      dim_ = std::max(dim_, d);
    }
    COULOMB_REQUIRE(dim_ == 2 || dim_ == 3,
                    prefix() << "no physical surface (2D) or volume (3D) found; define e.g. Physical Volume(\"body\") "
                             << "= {...}; so that the bulk elements are written");
    mesh_.dimension = dim_;
  }

  /// Index of a gmsh node tag in file_.nodeTags.
  std::size_t node(long long tag, long long element) const {
    const auto found = nodeIndex_.find(tag);
    COULOMB_REQUIRE(found != nodeIndex_.end(), prefix() << "element " << element << " refers to undefined node " << tag);
    return found->second;
  }
  Point point(std::size_t index) const {
    return {file_.xyz[3 * index], file_.xyz[3 * index + 1], dim_ == 3 ? file_.xyz[3 * index + 2] : 0.0};
  }

  void buildBlocks() {
    std::map<int, std::vector<const GmshElement*>> groups;  // physical tag -> bulk elements
    for (const auto& e : file_.elements)
      if (e.physical != 0 && gmshDimension(e.type) == dim_) groups[e.physical].push_back(&e);

    // Orient cells on gmsh node indices, then renumber the nodes bulk cells use.
    std::vector<std::vector<std::size_t>> cells;
    std::vector<char> used(file_.nodeTags.size(), 0);
    for (const auto& [tag, elements] : groups) {
      const int type = elements.front()->type;
      COULOMB_REQUIRE(gmshSupportedNodes(type) > 0 && gmshDimension(type) >= 2,
                      prefix() << groupLabel(dim_, tag) << " has " << gmshTypeName(type)
                               << " elements; supported: "
                               << (dim_ == 2 ? "3- and 6-node triangles, 4-, 8- and 9-node quadrangles"
                                             : "4- and 10-node tetrahedra, 8-, 20- and 27-node hexahedra")
                               << " (Mesh.ElementOrder 1 or 2)");
      mesh::ElementBlock block;
      block.name = nameOf(dim_, tag);
      block.id = tag;
      block.cellType = cellTypeOf(type);
      block.firstElement = numCells_;
      const std::vector<int> exodusOrder = gmshToExodus(block.cellType);
      for (const GmshElement* e : elements) {
        COULOMB_REQUIRE(e->type == type, prefix() << groupLabel(dim_, tag) << " mixes " << gmshTypeName(type)
                                                  << " and " << gmshTypeName(e->type)
                                                  << " elements; an element block holds one cell type: put them in "
                                                  << "separate physical groups");
        std::vector<std::size_t> cell;
        for (int g : exodusOrder) cell.push_back(node(e->nodes[static_cast<std::size_t>(g)], e->tag));
        orient(block.cellType, cell, e->tag, tag);
        for (std::size_t n : cell) used[n] = 1;
        cells.push_back(std::move(cell));
        ++numCells_;
      }
      mesh_.blocks.push_back(std::move(block));
    }
    if (dim_ == 2) checkPlanar(used);

    // Compact renumbering in gmsh tag order.
    std::vector<std::size_t> order(file_.nodeTags.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return file_.nodeTags[a] < file_.nodeTags[b]; });
    newNumber_.assign(file_.nodeTags.size(), -1);
    long long next = 0;
    for (std::size_t i : order) {
      if (!used[i]) continue;
      newNumber_[i] = next++;
      for (int c = 0; c < dim_; ++c) mesh_.coordinates.push_back(file_.xyz[3 * i + c]);
    }
    std::size_t cellIndex = 0;
    for (auto& block : mesh_.blocks) {
      const auto count = static_cast<std::size_t>(groups[block.id].size());
      for (std::size_t k = 0; k < count; ++k, ++cellIndex)
        for (std::size_t n : cells[cellIndex]) block.connectivity.push_back(newNumber_[n]);
    }
  }

  void orient(CellType type, std::vector<std::size_t>& cell, long long element, int tag) const {
    std::vector<Point> x;
    for (std::size_t n : cell) x.push_back(point(n));
    double size = 0;  // longest distance from the first node, for a relative tolerance
    for (const auto& p : x)
      size = std::max(size, std::hypot(p[0] - x[0][0], p[1] - x[0][1], p[2] - x[0][2]));
    const double tolerance = 1e-12 * std::pow(size, dim_);
    auto j = cornerJacobians(type, x);
    double sum = 0;
    for (double v : j) sum += v;
    if (sum < 0) {
      const auto& p = flipPermutation(type);
      std::vector<std::size_t> flipped(cell.size());
      for (std::size_t i = 0; i < cell.size(); ++i) flipped[i] = cell[static_cast<std::size_t>(p[i])];
      cell = std::move(flipped);
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = point(cell[i]);
      j = cornerJacobians(type, x);
    }
    for (double v : j)
      COULOMB_REQUIRE(v > tolerance, prefix() << "element " << element << " of " << groupLabel(dim_, tag)
                                              << " is degenerate or not convex (corner Jacobian " << v << ")");
  }

  void checkPlanar(const std::vector<char>& used) const {
    double extent = 0, maxZ = 0;
    for (std::size_t i = 0; i < used.size(); ++i) {
      if (!used[i]) continue;
      for (int c = 0; c < 3; ++c) extent = std::max(extent, std::abs(file_.xyz[3 * i + c]));
      maxZ = std::max(maxZ, std::abs(file_.xyz[3 * i + 2]));
    }
    COULOMB_REQUIRE(maxZ <= 1e-10 * extent,
                    prefix() << "a 2D mesh must lie in the plane z = 0, but a node has |z| = " << maxZ);
  }

  void buildSets() {
    // Boundary groups (dimension d-1): one side set + one node set each.
    std::map<int, std::vector<const GmshElement*>> boundary;
    std::map<std::pair<int, int>, std::set<long long>> pointSets;  // (dim, tag) -> nodes, dim < d-1
    for (const auto& e : file_.elements) {
      if (e.physical == 0) continue;
      const int d = gmshDimension(e.type);
      if (d == dim_ - 1) {
        const bool ok = dim_ == 2 ? (e.type == 1 || e.type == 8)
                                  : (e.type == 2 || e.type == 3 || e.type == 9 || e.type == 10 || e.type == 16);
        COULOMB_REQUIRE(ok, prefix() << groupLabel(d, e.physical) << " has " << gmshTypeName(e.type)
                                     << " elements; supported boundary elements: "
                                     << (dim_ == 2 ? "2- and 3-node lines"
                                                   : "3- and 6-node triangles, 4-, 8- and 9-node quadrangles"));
        boundary[e.physical].push_back(&e);
      } else if (d < dim_ - 1) {
        COULOMB_REQUIRE(gmshSupportedNodes(e.type) > 0, prefix() << groupLabel(d, e.physical) << " has "
                                                                 << gmshTypeName(e.type) << " elements");
        auto& set = pointSets[{d, e.physical}];
        for (long long n : e.nodes) {
          const long long number = newNumber_[node(n, e.tag)];
          COULOMB_REQUIRE(number >= 0, prefix() << groupLabel(d, e.physical) << " contains node " << n
                                                << ", which no bulk element uses");
          set.insert(number);
        }
      }
    }

    // Match boundary faces against all bulk element sides: key -> (element, side).
    std::map<FaceKey, std::pair<long long, int>> match;
    for (const auto& [tag, elements] : boundary)
      for (const GmshElement* e : elements) {
        std::vector<long long> nodes;
        for (long long n : e->nodes) nodes.push_back(newNumber_[node(n, e->tag)]);
        match.emplace(faceKey(nodes), std::make_pair(-1LL, -1));
      }
    for (const auto& block : mesh_.blocks) {
      const int nn = mesh::numNodes(block.cellType);
      for (long long k = 0; k < block.numElements(); ++k)
        for (int s = 0; s < mesh::numFaces(block.cellType); ++s) {
          std::vector<long long> nodes;
          for (int local : exodusSideNodes(block.cellType, s)) nodes.push_back(block.connectivity[k * nn + local]);
          const auto found = match.find(faceKey(nodes));
          if (found != match.end() && found->second.first < 0) found->second = {block.firstElement + k, s};
        }
    }

    std::set<int> nodeSetIds;
    for (const auto& [tag, elements] : boundary) {
      mesh::SideSet sides;
      mesh::NodeSet nodes;
      sides.name = nodes.name = nameOf(dim_ - 1, tag);
      sides.id = nodes.id = tag;
      std::set<long long> nodeSet;
      for (const GmshElement* e : elements) {
        std::vector<long long> faceNodes;
        for (long long n : e->nodes) {
          const long long number = newNumber_[node(n, e->tag)];
          COULOMB_REQUIRE(number >= 0, prefix() << "element " << e->tag << " of " << groupLabel(dim_ - 1, tag)
                                                << " uses node " << n << ", which no bulk element uses: the group "
                                                << "is not on the boundary of the meshed region");
          faceNodes.push_back(number);
        }
        const auto& hit = match.at(faceKey(faceNodes));
        COULOMB_REQUIRE(hit.first >= 0, prefix() << "element " << e->tag << " of " << groupLabel(dim_ - 1, tag)
                                                 << " is not a side of any bulk element (non-conforming mesh?)");
        sides.elements.push_back(hit.first);
        sides.sides.push_back(hit.second);
        nodeSet.insert(faceNodes.begin(), faceNodes.end());
      }
      nodes.nodes.assign(nodeSet.begin(), nodeSet.end());
      nodeSetIds.insert(tag);
      mesh_.sideSets.push_back(std::move(sides));
      mesh_.nodeSets.push_back(std::move(nodes));
    }
    for (const auto& [key, nodeSet] : pointSets) {
      mesh::NodeSet nodes;
      nodes.name = nameOf(key.first, key.second);
      nodes.id = key.second;
      while (nodeSetIds.count(nodes.id)) ++nodes.id;
      nodeSetIds.insert(nodes.id);
      nodes.nodes.assign(nodeSet.begin(), nodeSet.end());
      mesh_.nodeSets.push_back(std::move(nodes));
    }
    checkUniqueNames();
  }

  /// Decks address blocks and sets by name: two of one kind with the same
  /// name (e.g. a physical curve and a physical point "top") would be ambiguous.
  void checkUniqueNames() const {
    const auto check = [this](const char* kind, std::vector<std::string> names) {
      std::set<std::string> seen;
      for (const auto& name : names)
        COULOMB_REQUIRE(name.empty() || seen.insert(name).second,
                        prefix() << "two " << kind << "s are named '" << name
                                 << "' (physical groups of different dimension?); rename one");
    };
    std::vector<std::string> names;
    for (const auto& b : mesh_.blocks) names.push_back(b.name);
    check("element block", names);
    names.clear();
    for (const auto& s : mesh_.nodeSets) names.push_back(s.name);
    check("node set", names);
  }

  std::string path_;
  GmshFile file_;
  int dim_ = 3;
  long long numCells_ = 0;
  std::unordered_map<long long, std::size_t> nodeIndex_;
  std::vector<long long> newNumber_;  // gmsh node index -> 0-based Exodus node, -1 if unused
  mesh::GlobalMesh mesh_;
};

}  // namespace

using SideTable = std::vector<std::vector<int>>;

const std::vector<int>& exodusSideNodes(CellType type, int side) {
  static const SideTable quad{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const SideTable tri{{0, 1}, {1, 2}, {2, 0}};
  static const SideTable hex{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const SideTable tet{{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
  static const SideTable quad8 = quadraticSides(CellType::Quad8, quad), quad9 = quadraticSides(CellType::Quad9, quad),
                         tri6 = quadraticSides(CellType::Tri6, tri), hex20 = quadraticSides(CellType::Hex20, hex),
                         hex27 = quadraticSides(CellType::Hex27, hex), tet10 = quadraticSides(CellType::Tet10, tet);
  const SideTable* table = &tet;
  switch (type) {
    case CellType::Quad4: table = &quad; break;
    case CellType::Tri3: table = &tri; break;
    case CellType::Hex8: table = &hex; break;
    case CellType::Tet4: table = &tet; break;
    case CellType::Quad8: table = &quad8; break;
    case CellType::Quad9: table = &quad9; break;
    case CellType::Tri6: table = &tri6; break;
    case CellType::Hex20: table = &hex20; break;
    case CellType::Hex27: table = &hex27; break;
    case CellType::Tet10: table = &tet10; break;
  }
  COULOMB_REQUIRE(side >= 0 && side < static_cast<int>(table->size()),
                  "side " << side << " of a " << mesh::toString(type) << " cell does not exist");
  return (*table)[static_cast<std::size_t>(side)];
}

mesh::GlobalMesh readGmsh(const std::string& path) {
  GmshFile file = Parser(path).parse();
  return Converter(path, std::move(file)).convert();
}

}  // namespace coulomb::io
