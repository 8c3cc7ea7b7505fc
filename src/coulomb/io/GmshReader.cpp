/// @file GmshReader.cpp
/// @brief readGmsh(): gmsh's own library reads the file (any .msh version,
/// ASCII or binary), then its physical groups become blocks and sets (rules
/// in GmshReader.hpp).
///
/// The side sets are what the solver's contact search and Neumann loads use,
/// so every boundary element must match a bulk element side exactly; a
/// mismatch is an error rather than a silently smaller set.
#include "coulomb/io/GmshReader.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "coulomb/core/Error.hpp"
#include "coulomb/io/GmshNodeOrder.hpp"

namespace coulomb::io {
namespace {

using mesh::CellType;

struct GmshElement {
  std::size_t tag = 0;
  int type = 0;
  std::vector<std::size_t> nodes;  // gmsh node tags, in gmsh's node order
};

/// One physical group: the elements of all its entities, in element tag order
/// (the order gmsh numbers and writes them, whatever the file format).
struct GmshGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<GmshElement> elements;
};

/// What the conversion needs of the model gmsh read, copied out of gmsh's
/// global state so that gmsh can be finalised before the conversion starts.
struct GmshFile {
  std::vector<std::size_t> nodeTags;
  std::vector<double> xyz;                 // 3 per node
  std::vector<GmshGroup> groups;           // ascending (dim, tag); only groups with elements
  std::map<int, std::string> typeNames;    // gmsh element type -> gmsh's name ("Triangle 6")
};

/// What gmsh::initialize changes in the process: it appends the executable's
/// folder to PATH and PYTHONPATH (again at every initialisation) and sets the
/// C locale. gmsh 4.8's API cannot be told not to: it exits the process on its
/// own -noenv and -nolocale ("Unknown option"). So they are put back.
class ProcessState {
public:
  ProcessState() : locale_(std::setlocale(LC_ALL, nullptr)) {
    for (const char* name : kVariables) {
      const char* value = std::getenv(name);
      values_.push_back(value ? std::optional<std::string>(value) : std::nullopt);
    }
  }
  void restoreEnvironment() const {
    for (std::size_t i = 0; i < values_.size(); ++i) {
      if (values_[i])
        setenv(kVariables[i], values_[i]->c_str(), 1);
      else
        unsetenv(kVariables[i]);
    }
  }
  void restoreLocale() const { std::setlocale(LC_ALL, locale_.c_str()); }

private:
  static constexpr const char* kVariables[] = {"PATH", "PYTHONPATH"};
  std::string locale_;
  std::vector<std::optional<std::string>> values_;
};

/// gmsh initialised for one file and finalised after it, also when it throws.
/// Not once per process: after an error gmsh 4.8 keeps its file lock, and
/// every later open is then refused with an info message only; a fresh
/// initialisation clears it, and costs about 0.2 ms.
class GmshSession {
public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);  // false: no gmshrc / gmsh-options of the user
    state_.restoreEnvironment();
    // Messages go to gmsh's logger (read below for the error), never to the terminal.
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::logger::start();
  }
  ~GmshSession() {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {  // a destructor must not throw; the file's error is already on its way
    }
    // After gmsh is done: it parses numbers in the C locale.
    state_.restoreLocale();
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

  /// The first error gmsh logged (its root cause: later ones follow from it), "" if none.
  static std::string firstLoggedError() {
    std::vector<std::string> log;
    gmsh::logger::get(log);
    for (const auto& line : log)
      if (line.rfind("Error", 0) == 0) return line.substr(std::min(line.size(), line.find(':') + 1));
    return {};
  }

private:
  ProcessState state_;  // taken before gmsh::initialize
};

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  const auto first = text.find_first_not_of(' ');
  return first == std::string::npos ? std::string() : text.substr(first);
}

/// Refuses what is no .msh file before gmsh sees it: gmsh parses any file it
/// does not recognise as a .geo script, which may run shell commands (System)
/// and read or write other files.
void checkIsMshFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  COULOMB_REQUIRE(in.good(), "gmsh mesh '" << path << "': cannot open file (missing or not readable)");
  std::string first;
  std::getline(in, first);
  COULOMB_REQUIRE(first.rfind("$MeshFormat", 0) == 0 || first.rfind("$NOD", 0) == 0,
                  "gmsh mesh '" << path << "': not a gmsh .msh file (it does not start with $MeshFormat)");
}

/// The nodes and the physical groups of the mesh gmsh read from @p path.
GmshFile loadWithGmsh(const std::string& path) {
  GmshSession session;
  gmsh::open(path);
  if (const std::string error = GmshSession::firstLoggedError(); !error.empty()) throw Error(oneLine(error));

  GmshFile file;
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(file.nodeTags, file.xyz, parametric, -1, -1, false, false);
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  std::sort(groups.begin(), groups.end());
  for (const auto& [dim, tag] : groups) {
    GmshGroup group;
    group.dim = dim;
    group.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, group.name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elementTags, nodeTags;
      gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim, entity);
      for (std::size_t t = 0; t < types.size(); ++t) {
        std::string name;
        int typeDim = 0, order = 0, numNodes = 0, numPrimary = 0;
        std::vector<double> reference;
        gmsh::model::mesh::getElementProperties(types[t], name, typeDim, order, numNodes, reference, numPrimary);
        file.typeNames[types[t]] = name;
        const auto perElement = static_cast<std::size_t>(numNodes);
        COULOMB_CHECK(nodeTags[t].size() == elementTags[t].size() * perElement,
                      "gmsh returned " << nodeTags[t].size() << " node tags for " << elementTags[t].size() << " "
                                       << name << " elements");
        for (std::size_t k = 0; k < elementTags[t].size(); ++k) {
          const auto first = nodeTags[t].begin() + static_cast<std::ptrdiff_t>(k * perElement);
          const auto last = first + static_cast<std::ptrdiff_t>(perElement);
          group.elements.push_back({elementTags[t][k], types[t], {first, last}});
        }
      }
    }
    std::stable_sort(group.elements.begin(), group.elements.end(),
                     [](const GmshElement& a, const GmshElement& b) { return a.tag < b.tag; });
    if (!group.elements.empty()) file.groups.push_back(std::move(group));
  }
  return file;
}

/// loadWithGmsh() with whatever gmsh throws (a std::string in gmsh 4.8, a
/// std::runtime_error in later versions) as a coulomb::Error naming the file.
GmshFile readWithGmsh(const std::string& path) {
  checkIsMshFile(path);
  const std::string prefix = "gmsh mesh '" + path + "': gmsh cannot read it: ";
  try {
    return loadWithGmsh(path);
  } catch (const InternalError&) {
    throw;
  } catch (const Error& e) {
    throw Error(prefix + e.what());
  } catch (const std::string& message) {
    throw Error(prefix + oneLine(message));
  } catch (const std::bad_alloc&) {
    throw Error(prefix + "out of memory (a damaged node or element count?)");
  } catch (const std::exception& e) {
    throw Error(prefix + oneLine(e.what()));
  } catch (...) {
    throw Error(prefix + "gmsh failed without a message");
  }
}

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

/// The cell type of a gmsh element type (MSH type numbers), if Coulomb has it.
std::optional<CellType> cellTypeOf(int gmshType) {
  switch (gmshType) {
    case 2: return CellType::Tri3;
    case 3: return CellType::Quad4;
    case 4: return CellType::Tet4;
    case 5: return CellType::Hex8;
    case 9: return CellType::Tri6;
    case 10: return CellType::Quad9;
    case 11: return CellType::Tet10;
    case 12: return CellType::Hex27;
    case 16: return CellType::Quad8;
    case 17: return CellType::Hex20;
    default: return std::nullopt;
  }
}

/// Boundary elements that can be a cell's side: lines (2D); triangles and
/// quadrangles, linear and quadratic (3D).
bool isSideType(int gmshType, int dim) {
  return dim == 2 ? (gmshType == 1 || gmshType == 8)
                  : (gmshType == 2 || gmshType == 3 || gmshType == 9 || gmshType == 10 || gmshType == 16);
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
  static std::string groupLabel(const GmshGroup& group) {
    static const char* kinds[] = {"point", "curve", "surface", "volume"};
    return "physical " + std::string(kinds[group.dim]) + " " + (group.name.empty() ? "" : "'" + group.name + "' ") +
           "(tag " + std::to_string(group.tag) + ")";
  }
  std::string typeName(int type) const { return file_.typeNames.at(type); }

  void findDimension() {
    dim_ = -1;
    for (const auto& group : file_.groups) dim_ = std::max(dim_, group.dim);
    COULOMB_REQUIRE(dim_ == 2 || dim_ == 3,
                    prefix() << "no physical surface (2D) or volume (3D) found; define e.g. Physical Volume(\"body\") "
                             << "= {...}; so that the bulk elements are written");
    mesh_.dimension = dim_;
  }

  /// Index of a gmsh node tag in file_.nodeTags.
  std::size_t node(std::size_t tag, std::size_t element) const {
    const auto found = nodeIndex_.find(tag);
    COULOMB_REQUIRE(found != nodeIndex_.end(), prefix() << "element " << element << " refers to undefined node " << tag);
    return found->second;
  }
  Point point(std::size_t index) const {
    return {file_.xyz[3 * index], file_.xyz[3 * index + 1], dim_ == 3 ? file_.xyz[3 * index + 2] : 0.0};
  }

  void buildBlocks() {
    // Orient cells on gmsh node indices, then renumber the nodes bulk cells use.
    std::vector<std::vector<std::size_t>> cells;
    std::vector<char> used(file_.nodeTags.size(), 0);
    std::vector<std::size_t> counts;  // cells per block
    for (const auto& group : file_.groups) {
      if (group.dim != dim_) continue;
      const int type = group.elements.front().type;
      const std::optional<CellType> cellType = cellTypeOf(type);
      COULOMB_REQUIRE(cellType, prefix() << groupLabel(group) << " has " << typeName(type)
                                         << " elements; supported: "
                                         << (dim_ == 2 ? "3- and 6-node triangles, 4-, 8- and 9-node quadrangles"
                                                       : "4- and 10-node tetrahedra, 8-, 20- and 27-node hexahedra")
                                         << " (Mesh.ElementOrder 1 or 2)");
      mesh::ElementBlock block;
      block.name = group.name;
      block.id = group.tag;
      block.cellType = *cellType;
      block.firstElement = numCells_;
      const std::vector<int> exodusOrder = gmshToExodus(block.cellType);
      for (const GmshElement& e : group.elements) {
        COULOMB_REQUIRE(e.type == type, prefix() << groupLabel(group) << " mixes " << typeName(type) << " and "
                                                 << typeName(e.type)
                                                 << " elements; an element block holds one cell type: put them in "
                                                 << "separate physical groups");
        std::vector<std::size_t> cell;
        for (int g : exodusOrder) cell.push_back(node(e.nodes[static_cast<std::size_t>(g)], e.tag));
        orient(block.cellType, cell, e.tag, group);
        for (std::size_t n : cell) used[n] = 1;
        cells.push_back(std::move(cell));
        ++numCells_;
      }
      mesh_.blocks.push_back(std::move(block));
      counts.push_back(group.elements.size());
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
    for (std::size_t b = 0; b < mesh_.blocks.size(); ++b)
      for (std::size_t k = 0; k < counts[b]; ++k, ++cellIndex)
        for (std::size_t n : cells[cellIndex]) mesh_.blocks[b].connectivity.push_back(newNumber_[n]);
  }

  void orient(CellType type, std::vector<std::size_t>& cell, std::size_t element, const GmshGroup& group) const {
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
      COULOMB_REQUIRE(v > tolerance, prefix() << "element " << element << " of " << groupLabel(group)
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

  /// 0-based Exodus numbers of an element's nodes; every one must belong to a bulk cell.
  std::vector<long long> exodusNodes(const GmshElement& e, const GmshGroup& group) const {
    std::vector<long long> numbers;
    for (std::size_t n : e.nodes) {
      const long long number = newNumber_[node(n, e.tag)];
      COULOMB_REQUIRE(number >= 0, prefix() << "element " << e.tag << " of " << groupLabel(group) << " uses node "
                                            << n << ", which no bulk element uses: the group "
                                            << "is not on the boundary of the meshed region");
      numbers.push_back(number);
    }
    return numbers;
  }

  void buildSets() {
    // Boundary groups (dimension d-1): one side set + one node set each.
    std::vector<const GmshGroup*> boundary, lower;
    for (const auto& group : file_.groups) {
      if (group.dim == dim_ - 1) {
        for (const GmshElement& e : group.elements)
          COULOMB_REQUIRE(isSideType(e.type, dim_),
                          prefix() << groupLabel(group) << " has " << typeName(e.type)
                                   << " elements; supported boundary elements: "
                                   << (dim_ == 2 ? "2- and 3-node lines"
                                                 : "3- and 6-node triangles, 4-, 8- and 9-node quadrangles"));
        boundary.push_back(&group);
      } else if (group.dim < dim_ - 1) {
        lower.push_back(&group);
      }
    }

    // Match boundary faces against all bulk element sides: key -> (element, side).
    std::map<FaceKey, std::pair<long long, int>> match;
    for (const GmshGroup* group : boundary)
      for (const GmshElement& e : group->elements)
        match.emplace(faceKey(exodusNodes(e, *group)), std::make_pair(-1LL, -1));
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
    for (const GmshGroup* group : boundary) {
      mesh::SideSet sides;
      mesh::NodeSet nodes;
      sides.name = nodes.name = group->name;
      sides.id = nodes.id = group->tag;
      std::set<long long> nodeSet;
      for (const GmshElement& e : group->elements) {
        const std::vector<long long> faceNodes = exodusNodes(e, *group);
        const auto& hit = match.at(faceKey(faceNodes));
        COULOMB_REQUIRE(hit.first >= 0, prefix() << "element " << e.tag << " of " << groupLabel(*group)
                                                 << " is not a side of any bulk element (non-conforming mesh?)");
        sides.elements.push_back(hit.first);
        sides.sides.push_back(hit.second);
        nodeSet.insert(faceNodes.begin(), faceNodes.end());
      }
      nodes.nodes.assign(nodeSet.begin(), nodeSet.end());
      nodeSetIds.insert(group->tag);
      mesh_.sideSets.push_back(std::move(sides));
      mesh_.nodeSets.push_back(std::move(nodes));
    }
    // Lower groups (points, curves in 3D): node sets; ids after the boundary ones'.
    for (const GmshGroup* group : lower) {
      std::set<long long> nodeSet;
      for (const GmshElement& e : group->elements)
        for (std::size_t n : e.nodes) {
          const long long number = newNumber_[node(n, e.tag)];
          COULOMB_REQUIRE(number >= 0, prefix() << groupLabel(*group) << " contains node " << n
                                                << ", which no bulk element uses");
          nodeSet.insert(number);
        }
      mesh::NodeSet nodes;
      nodes.name = group->name;
      nodes.id = group->tag;
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
  std::unordered_map<std::size_t, std::size_t> nodeIndex_;  // gmsh node tag -> index in file_.nodeTags
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
  return Converter(path, readWithGmsh(path)).convert();
}

}  // namespace coulomb::io
