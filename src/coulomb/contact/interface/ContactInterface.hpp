#pragma once
/// @file ContactInterface.hpp
/// @brief A slave/master pair of side sets: their faces, the slave nodes, and
/// which of them this rank owns.
///
/// Every rank holds the whole GlobalMesh (docs/architecture.md, "Mesh
/// distribution"), so every rank builds the same complete lists of slave and
/// master faces without communication; ownership says which rank does what:
///  - a face (slave or master) belongs to the owner of its element (a pair
///    may integrate its slave faces elsewhere: InterfaceBalance.hpp),
///  - a slave node belongs to Mesh::nodeOwner (the owner of its DoFs).
/// A rank may own a slave node none of whose slave faces it owns (the node's
/// lowest-ranked element need not carry a slave face); every rank can still
/// evaluate anything about it, since all faces and (after InterfaceGather,
/// below) all current interface coordinates are replicated.
///
/// Faces: 2D meshes give Line2 faces (Line3 of quadratic cells), 3D meshes
/// Tri3 (Tet4 sides), Quad4 (Hex8 sides), Tri6 (Tet10), Quad8 (Hex20) or
/// Quad9 (Hex27 sides); face nodes
/// are in the outward order of fem::faceLocalNodes
/// (right-hand rule / (dy, -dx) normal points out of the element).
#include <array>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::contact {

/// @brief One side of one element, as a face of the contact interface.
struct ContactFace {
  long long element = -1;          ///< 0-based global element number
  int side = -1;                   ///< 0-based local side (Exodus side - 1)
  mesh::FaceType type = mesh::FaceType::Line2;
  int numNodes = 0;                ///< 2, 3 or 4 (linear), 3 (Line3), 9 (Quad9)
  /// Global node numbers, outward order (corners first, as Exodus).
  std::array<long long, mesh::kMaxFaceNodes> nodes{-1, -1, -1, -1, -1, -1, -1, -1, -1};
  /// Indices of the nodes in ContactInterface::interfaceNodes() (slave ∪ master).
  std::array<int, mesh::kMaxFaceNodes> interfaceIndex{-1, -1, -1, -1, -1, -1, -1, -1, -1};
  int owner = -1;                  ///< rank owning the element
};

class ContactInterface {
public:
  /// @brief Collects the faces of side sets `slaveSet` and `masterSet`
  /// (Exodus names or sideset_<id> aliases; each one set, or several
  /// separated by commas, which then make one surface: e.g. a master made
  /// of two bodies' tops, "left_top, right_top"). `what` names the deck
  /// entry asking (e.g. "Contact/punch"), for error messages.
  /// @throws coulomb::Error naming the set when it is unknown, empty, when
  /// a set is in both lists but the lists differ, or when a face is in both
  /// surfaces. The same list on both sides is a self-contact surface.
  /// Not collective (every rank detects the same errors).
  /// `axisymmetric` (2D): the faces are rings (x = r), the mortar integrals
  /// take 2 pi r (MortarPass).
  ContactInterface(const mesh::Mesh& mesh, const std::string& slaveSet, const std::string& masterSet,
                   const std::string& what = "contact", bool axisymmetric = false);

  int dimension() const { return dimension_; }
  bool axisymmetric() const { return axisymmetric_; }
  const Teuchos::RCP<const Teuchos::Comm<int>>& comm() const { return comm_; }
  /// The slave side sets' display names, joined by ", ".
  const std::string& slaveSetName() const { return slaveName_; }
  /// The slave and master lists name the same sets: one surface that may
  /// touch itself (masterFaces() == slaveFaces(); SelfContactRoles.hpp).
  bool selfContact() const { return selfContact_; }

  /// All slave / master faces (identical on every rank), in side-set order
  /// with duplicates removed.
  const std::vector<ContactFace>& slaveFaces() const { return slaveFaces_; }
  const std::vector<ContactFace>& masterFaces() const { return masterFaces_; }

  /// Unique global node numbers of the slave faces, increasing.
  const std::vector<long long>& slaveNodes() const { return slaveNodes_; }
  /// Index in slaveNodes() of a global node, or -1 if it is no slave node.
  int slaveNodeIndex(long long globalNode) const;
  /// For slave node i: indices of the slave faces containing it (CSR:
  /// slaveNodeFaces()[offset[i] .. offset[i+1])), and the corner of the node
  /// in each of these faces (same positions).
  const std::vector<int>& slaveNodeFaceOffsets() const { return nodeFaceOffset_; }
  const std::vector<int>& slaveNodeFaces() const { return nodeFaces_; }
  const std::vector<int>& slaveNodeFaceCorners() const { return nodeFaceCorner_; }

  /// Unique global node numbers of all interface faces (slave ∪ master), increasing.
  const std::vector<long long>& interfaceNodes() const { return interfaceNodes_; }
  /// Index in interfaceNodes() of a global node, or -1.
  int interfaceNodeIndex(long long globalNode) const;
  /// Reference coordinates of interfaceNodes(), `dimension()` per node.
  const std::vector<double>& referenceCoordinates() const { return referenceCoordinates_; }

  /// Indices into slaveFaces() of the faces whose element this rank owns (increasing).
  const std::vector<int>& ownedSlaveFaces() const { return ownedSlaveFaces_; }
  /// Indices into slaveNodes() of the slave nodes this rank owns (increasing).
  const std::vector<int>& ownedSlaveNodes() const { return ownedSlaveNodes_; }

private:
  int dimension_ = 3;
  bool axisymmetric_ = false;
  bool selfContact_ = false;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::string slaveName_, masterName_;
  std::vector<ContactFace> slaveFaces_, masterFaces_;
  std::vector<long long> slaveNodes_, interfaceNodes_;
  std::vector<int> nodeFaceOffset_, nodeFaces_, nodeFaceCorner_;
  std::vector<double> referenceCoordinates_;
  std::vector<int> ownedSlaveFaces_, ownedSlaveNodes_;
};

/// @brief Coordinates of the interface nodes (ContactInterface::interfaceNodes(),
/// same order), `dimension` values per node; the current configuration
/// x = X + u once gathered, identical on every rank.
struct InterfaceConfiguration {
  int dimension = 3;
  std::vector<double> x;
  const double* point(int interfaceIndex) const { return &x[static_cast<std::size_t>(interfaceIndex) * dimension]; }
};

/// @brief The reference configuration x = X (no communication).
InterfaceConfiguration referenceConfiguration(const ContactInterface& contact);

/// @brief The corners of a face in configuration x (2D: z = 0; a quadratic
/// face by its corners, the straight face of proximity tests and normals).
std::array<std::array<double, 3>, 4> faceCorners(const ContactFace& face, const InterfaceConfiguration& x);

/// @brief Gathers the displacements of the interface nodes (slave and master)
/// from an owned displacement vector to every rank.
///
/// How: a Tpetra Import from the owned DoF map (fem::DofMap::ownedMap(),
/// GID = dim × node + c) to a replicated map that lists all interface DoFs on
/// every rank. The interface is a surface, small next to the volume, so the
/// replicated copy costs O(interface) memory and one all-to-all-like exchange
/// per gather; the Import plan is built once, here.
class InterfaceGather {
public:
  /// Collective. `ownedDofMap`: the map of the displacement vectors to gather from.
  /// The interface must outlive the gather.
  InterfaceGather(const ContactInterface& contact, const Teuchos::RCP<const Map>& ownedDofMap);
  ~InterfaceGather();
  InterfaceGather(const InterfaceGather&) = delete;
  InterfaceGather& operator=(const InterfaceGather&) = delete;

  /// Collective: x = X + u at every interface node, on every rank.
  /// `ownedDisplacement` must live on the map given to the constructor.
  InterfaceConfiguration gather(const Vector& ownedDisplacement) const;
  /// Collective: the values of any vector on the same map at every interface
  /// node, on every rank (`dimension` per node; e.g. the bulk residual).
  std::vector<double> gatherValues(const Vector& owned) const;

private:
  const ContactInterface& contact_;
  Teuchos::RCP<const Map> replicatedMap_;
  Teuchos::RCP<const Import> import_;
};

}  // namespace coulomb::contact
