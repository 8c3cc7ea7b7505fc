/// @file ContactInterface.cpp
/// @brief Faces and nodes of a slave/master side-set pair; gather of their
/// current coordinates (see the header).
#include "coulomb/contact/interface/ContactInterface.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include <Teuchos_OrdinalTraits.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/fem/FaceTopology.hpp"
#include "coulomb/fem/MeshChecks.hpp"

namespace coulomb::contact {
namespace {

/// The side-set names of a deck value: one name, or several separated by
/// commas (blanks around a name are dropped).
std::vector<std::string> splitSetList(const std::string& list) {
  std::vector<std::string> names;
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    std::string name = list.substr(begin, end - begin);
    const std::size_t first = name.find_first_not_of(" \t");
    name = first == std::string::npos ? std::string() : name.substr(first, name.find_last_not_of(" \t") - first + 1);
    names.push_back(name);
    begin = end + 1;
  }
  return names;
}

/// The side sets named by a deck value (splitSetList), as mesh indices, and
/// their display names joined by ", ".
struct SetList {
  std::vector<std::size_t> indices;
  std::string shown;
};

SetList resolveSets(const mesh::Mesh& mesh, const std::string& list, const std::string& role, const std::string& what) {
  SetList sets;
  for (const std::string& name : splitSetList(list)) {
    COULOMB_REQUIRE(!name.empty(), what << ": the " << role << " side set list '" << list << "' has an empty name");
    const std::size_t index = mesh.sideSetIndex(name, what + " (" + role + " side set)");
    if (std::find(sets.indices.begin(), sets.indices.end(), index) != sets.indices.end()) continue;
    const mesh::SideSet& set = mesh.global().sideSets[index];
    sets.indices.push_back(index);
    sets.shown += (sets.shown.empty() ? "" : ", ") + mesh::displayName(set.name, "sideset", set.id);
  }
  return sets;
}

/// Faces of the side sets `sets` (one surface), duplicates (same element
/// and side) removed.
std::vector<ContactFace> collectFaces(const mesh::Mesh& mesh, const SetList& sets, const std::string& role,
                                      const std::string& what, const fem::NodeElementAdjacency& adjacency) {
  const mesh::GlobalMesh& global = mesh.global();
  std::vector<ContactFace> faces;
  std::set<std::pair<long long, int>> seen;
  for (std::size_t index : sets.indices) {
    const mesh::SideSet& set = global.sideSets[index];
    const std::string shown = mesh::displayName(set.name, "sideset", set.id);
    COULOMB_REQUIRE(!set.elements.empty(), what << ": " << role << " side set '" << shown << "' is empty");
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      ContactFace face;
      face.element = set.elements[i];
      face.side = set.sides[i];
      COULOMB_REQUIRE(face.element >= 0 && face.element < global.numElements(),
                      what << ": " << role << " side set '" << shown << "' refers to element " << face.element + 1
                           << ", which the mesh does not have (it has " << global.numElements() << ")");
      if (!seen.insert({face.element, face.side}).second) continue;
      const std::size_t b = mesh.blockOfElement(face.element);
      const mesh::ElementBlock& block = global.blocks[b];
      std::array<int, mesh::kMaxFaceNodes> local{};
      try {
        face.type = fem::faceType(block.cellType, face.side);
        face.numNodes = fem::faceLocalNodes(block.cellType, face.side, local);
      } catch (const Error& e) {
        throw Error(what + ": " + role + " side set '" + shown + "', element " + std::to_string(face.element + 1) +
                    ": " + e.what());
      }
      // Quadratic faces: Line3 in 2D and Quad9 in 3D keep their standard
      // quadratic dual bases (D_j > 0); Quad8 and Tri6 take the transformed
      // one (DualBasis.hpp, SlaveTransform.hpp).
      // A face with an element on its other side is inside a body (a merged
      // interface, or a set drawn through a body): it can never touch anything.
      const long long across = fem::elementAcrossFace(global, adjacency, face.element, face.side);
      COULOMB_REQUIRE(across < 0, what << ": " << role << " side set '" << shown << "': side " << face.side + 1
                                       << " of element " << face.element + 1 << " is inside a body (element " << across + 1
                                       << " is on its other side); a contact surface must be on the boundary (are the "
                                          "two bodies' nodes merged?)");
      const int perElement = mesh::numNodes(block.cellType);
      const long long offset = (face.element - block.firstElement) * perElement;
      for (int a = 0; a < face.numNodes; ++a) face.nodes[a] = block.connectivity[offset + local[a]];
      face.owner = mesh.elementOwner(face.element);
      faces.push_back(face);
    }
  }
  COULOMB_REQUIRE(!faces.empty(), what << ": " << role << " side set '" << sets.shown << "' is empty");
  return faces;
}

std::vector<long long> uniqueNodes(const std::vector<ContactFace>& a, const std::vector<ContactFace>* b) {
  std::vector<long long> nodes;
  for (const auto* faces : {&a, b}) {
    if (!faces) continue;
    for (const ContactFace& f : *faces) nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.begin() + f.numNodes);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

int indexIn(const std::vector<long long>& sorted, long long value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return (it != sorted.end() && *it == value) ? static_cast<int>(it - sorted.begin()) : -1;
}

}  // namespace

ContactInterface::ContactInterface(const mesh::Mesh& mesh, const std::string& slaveSet,
                                   const std::string& masterSet, const std::string& what, bool axisymmetric)
    : dimension_(mesh.dimension()), axisymmetric_(axisymmetric && mesh.dimension() == 2), comm_(mesh.comm()) {
  const mesh::GlobalMesh& global = mesh.global();
  const SetList slave = resolveSets(mesh, slaveSet, "slave", what);
  const SetList master = resolveSets(mesh, masterSet, "master", what);
  slaveName_ = slave.shown;
  masterName_ = master.shown;
  // The same sets on both sides: a surface that may touch itself
  // (SelfContactRoles.hpp gives its faces their roles per load step).
  std::vector<std::size_t> slaveSorted = slave.indices, masterSorted = master.indices;
  std::sort(slaveSorted.begin(), slaveSorted.end());
  std::sort(masterSorted.begin(), masterSorted.end());
  selfContact_ = slaveSorted == masterSorted;
  if (!selfContact_)
    for (std::size_t index : slave.indices)
      COULOMB_REQUIRE(std::find(master.indices.begin(), master.indices.end(), index) == master.indices.end(),
                      what << ": the slave and the master side sets name the same set '"
                           << mesh::displayName(global.sideSets[index].name, "sideset", global.sideSets[index].id)
                           << "' but not the same list; contact needs two different surfaces, or for a surface "
                              "touching itself the same list on both sides");

  const auto adjacency = fem::nodeElementAdjacency(global);
  slaveFaces_ = collectFaces(mesh, slave, selfContact_ ? "self-contact" : "slave", what, adjacency);
  if (selfContact_) {
    masterFaces_ = slaveFaces_;
  } else {
    masterFaces_ = collectFaces(mesh, master, "master", what, adjacency);
    std::set<std::pair<long long, int>> slaveSides;
    for (const ContactFace& f : slaveFaces_) slaveSides.insert({f.element, f.side});
    for (const ContactFace& f : masterFaces_)
      COULOMB_REQUIRE(!slaveSides.count({f.element, f.side}),
                      what << ": side " << f.side + 1 << " of element " << f.element + 1 << " is in both the slave side set '"
                           << slaveName_ << "' and the master side set '" << masterName_ << "'");
  }

  slaveNodes_ = uniqueNodes(slaveFaces_, nullptr);
  interfaceNodes_ = uniqueNodes(slaveFaces_, &masterFaces_);
  for (auto* faces : {&slaveFaces_, &masterFaces_})
    for (ContactFace& f : *faces)
      for (int a = 0; a < f.numNodes; ++a) f.interfaceIndex[a] = indexIn(interfaceNodes_, f.nodes[a]);

  referenceCoordinates_.resize(interfaceNodes_.size() * dimension_);
  for (std::size_t i = 0; i < interfaceNodes_.size(); ++i)
    for (int c = 0; c < dimension_; ++c)
      referenceCoordinates_[i * dimension_ + c] = global.coordinates[interfaceNodes_[i] * dimension_ + c];

  // Slave node -> slave faces (CSR), with the node's corner in each face.
  const std::size_t numSlaveNodes = slaveNodes_.size();
  nodeFaceOffset_.assign(numSlaveNodes + 1, 0);
  for (const ContactFace& f : slaveFaces_)
    for (int a = 0; a < f.numNodes; ++a) ++nodeFaceOffset_[indexIn(slaveNodes_, f.nodes[a]) + 1];
  for (std::size_t i = 0; i < numSlaveNodes; ++i) nodeFaceOffset_[i + 1] += nodeFaceOffset_[i];
  nodeFaces_.resize(nodeFaceOffset_.back());
  nodeFaceCorner_.resize(nodeFaceOffset_.back());
  std::vector<int> fill(nodeFaceOffset_.begin(), nodeFaceOffset_.end() - 1);
  for (std::size_t k = 0; k < slaveFaces_.size(); ++k)
    for (int a = 0; a < slaveFaces_[k].numNodes; ++a) {
      const int slot = fill[indexIn(slaveNodes_, slaveFaces_[k].nodes[a])]++;
      nodeFaces_[slot] = static_cast<int>(k);
      nodeFaceCorner_[slot] = a;
    }

  const int rank = comm_->getRank();
  for (std::size_t k = 0; k < slaveFaces_.size(); ++k)
    if (slaveFaces_[k].owner == rank) ownedSlaveFaces_.push_back(static_cast<int>(k));
  for (std::size_t i = 0; i < numSlaveNodes; ++i)
    if (mesh.nodeOwner(slaveNodes_[i]) == rank) ownedSlaveNodes_.push_back(static_cast<int>(i));
}

int ContactInterface::slaveNodeIndex(long long globalNode) const { return indexIn(slaveNodes_, globalNode); }

int ContactInterface::interfaceNodeIndex(long long globalNode) const { return indexIn(interfaceNodes_, globalNode); }

std::array<std::array<double, 3>, 4> faceCorners(const ContactFace& face, const InterfaceConfiguration& x) {
  std::array<std::array<double, 3>, 4> corners{};
  for (int a = 0; a < mesh::numCorners(face.type); ++a)
    for (int c = 0; c < x.dimension; ++c) corners[a][c] = x.point(face.interfaceIndex[a])[c];
  return corners;
}

InterfaceConfiguration referenceConfiguration(const ContactInterface& contact) {
  InterfaceConfiguration config;
  config.dimension = contact.dimension();
  config.x = contact.referenceCoordinates();
  return config;
}

InterfaceGather::InterfaceGather(const ContactInterface& contact, const Teuchos::RCP<const Map>& ownedDofMap)
    : contact_(contact) {
  const int dim = contact.dimension();
  const auto& nodes = contact.interfaceNodes();
  std::vector<GlobalOrdinal> gids(nodes.size() * dim);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int c = 0; c < dim; ++c) gids[i * dim + c] = static_cast<GlobalOrdinal>(nodes[i]) * dim + c;
  // Every rank lists every interface DoF: an overlapping ("replicated") target map.
  replicatedMap_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                        Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), gids.size()),
                                        ownedDofMap->getIndexBase(), ownedDofMap->getComm()));
  import_ = Teuchos::rcp(new Import(ownedDofMap, replicatedMap_));
}

InterfaceGather::~InterfaceGather() = default;

std::vector<double> InterfaceGather::gatherValues(const Vector& owned) const {
  Vector replicated(replicatedMap_);
  replicated.doImport(owned, *import_, Tpetra::INSERT);
  const auto values = replicated.getData(0);
  return std::vector<double>(values.begin(), values.end());
}

InterfaceConfiguration InterfaceGather::gather(const Vector& ownedDisplacement) const {
  Vector replicated(replicatedMap_);
  replicated.doImport(ownedDisplacement, *import_, Tpetra::INSERT);
  InterfaceConfiguration config = referenceConfiguration(contact_);
  const auto u = replicated.getData(0);
  for (std::size_t i = 0; i < config.x.size(); ++i) config.x[i] += u[i];
  return config;
}

}  // namespace coulomb::contact
