#include "coulomb/fem/Assembler.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Export.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"
#include "coulomb/fem/ElementKernel.hpp"
#include "coulomb/fem/MeshChecks.hpp"
#include "coulomb/fem/FaceKernel.hpp"
#include "coulomb/fem/FaceTopology.hpp"
#include "coulomb/fem/SparsityPattern.hpp"
#include "coulomb/fem/StressKernel.hpp"

namespace coulomb::fem {

using mesh::CellType;
using mesh::FaceType;

namespace {

/// A face of a local element carrying a surface load.
struct LoadedFace {
  std::size_t condition;
  std::size_t block;
  long long element;
  int side;
};

/// Where an element's tangent rows go: owned rows straight into the owned
/// tangent (columns translated from overlap-local to its column map), ghost
/// rows into the small ghost-rows matrix that is exported afterwards. No
/// overlap-sized copy of the tangent exists (one rank: no ghost rows at all).
struct TangentTarget {
  CrsMatrix* owned = nullptr;
  CrsMatrix* ghost = nullptr;
  const int* ownedColumn = nullptr;  ///< overlap-local DoF -> owned column-map local index
  int numOwnedDofs = 0;
};

}  // namespace

struct Assembler::Impl {
  const mesh::Mesh& mesh;
  const DofMap& dofs;
  ModelSettings model;
  std::vector<MaterialParameters> blockMaterial;
  std::vector<LoadedFace> loadedFaces;
  Teuchos::RCP<const CrsGraph> ownedGraph;
  Teuchos::RCP<CrsMatrix> ghostMatrix;
  Teuchos::RCP<Export> ghostToOwned;
  std::vector<int> ownedColumn;
  Teuchos::RCP<Vector> overlapResidual, overlapU;
  Teuchos::RCP<Vector> ownedPending, overlapPending;  ///< ū − u of lagging prescribed DoFs (assemble)
  Teuchos::RCP<Import> ownedToOverlap;
  Teuchos::RCP<Export> overlapToOwned;

  Impl(const mesh::Mesh& m, const DofMap& d, const ModelSettings& s) : mesh(m), dofs(d), model(s) {}

  const double* coordinates(long long node) const { return &mesh.global().coordinates[node * mesh.dimension()]; }

  std::array<double, 3> bodyForce(std::size_t block, double time) const {
    std::array<double, 3> f{};
    for (const auto& b : model.bodyForces) {
      if (b.block && mesh.blockIndex(*b.block, "Body Forces/" + b.name + "/Block") != block) continue;
      const double scale = b.function(time);
      for (int d = 0; d < 3; ++d) f[d] += b.force[d] * scale;
    }
    return f;
  }

  /// Gathers reference coordinates, displacements and overlap DoF indices of one element.
  template <CellType T>
  void gather(const long long* cell, const double* u, std::array<double, CellTraits<T>::dofs>& X,
              std::array<double, CellTraits<T>::dofs>& ue, std::array<int, CellTraits<T>::dofs>& ldof) const {
    constexpr int dim = CellTraits<T>::dim;
    for (int a = 0; a < CellTraits<T>::nodes; ++a) {
      const int local = mesh.localNode(cell[a]);
      const double* x = coordinates(cell[a]);
      for (int d = 0; d < dim; ++d) {
        ldof[a * dim + d] = dofs.localDof(local, d);
        X[a * dim + d] = x[d];
        ue[a * dim + d] = u ? u[ldof[a * dim + d]] : 0.0;
      }
    }
  }

  /// Element loop of one block; returns its first inverted element (0-based
  /// global number), or -1.
  ///
  /// `pending` (overlap, or null): ū − u on prescribed DoFs whose iterate lags
  /// behind the boundary values (DirichletConstraints.hpp); the elements
  /// touching one add k_fp (ū − u_p) to their free rows.
  template <CellType T>
  long long assembleBlock(std::size_t b, double time, const double* u, double* r, const TangentTarget& K,
                          const double* pending) const {
    using Traits = CellTraits<T>;
    constexpr int n = Traits::nodes, nd = Traits::dofs;
    const auto& block = mesh.global().blocks[b];
    const auto force3 = bodyForce(b, time);
    std::array<double, Traits::dim> force{};
    for (int d = 0; d < Traits::dim; ++d) force[d] = force3[d];
    std::array<double, nd> X{}, ue{}, re{};
    std::array<double, nd * nd> ke{};
    std::array<int, nd> ldof{}, column{};
    long long inverted = -1;
    for (long long element : mesh.localElements(b)) {
      gather<T>(&block.connectivity[(element - block.firstElement) * n], u, X, ue, ldof);
      bool lagging = false;
      for (int i = 0; i < nd && pending; ++i) lagging = lagging || (constraintsFlag(ldof[i]) && pending[ldof[i]] != 0.0);
      const KernelStatus status =
          cellResidualTangent<T>(blockMaterial[b], X, ue, force, re, K.owned || lagging ? &ke : nullptr);
      if (status != KernelStatus::Ok) {
        if (inverted < 0) inverted = element;
        continue;
      }
      for (int i = 0; i < nd; ++i) r[ldof[i]] += re[i];
      if (lagging) {  // the free rows' linear response to the boundary increment still to come
        for (int i = 0; i < nd; ++i) {
          if (constraintsFlag(ldof[i])) continue;
          for (int j = 0; j < nd; ++j)
            if (constraintsFlag(ldof[j])) r[ldof[i]] += ke[i * nd + j] * pending[ldof[j]];
        }
      }
      if (!K.owned) continue;
      // Prescribed DoFs: zero their rows and columns (identity set after export).
      for (int i = 0; i < nd; ++i) {
        if (!constraintsFlag(ldof[i])) continue;
        for (int j = 0; j < nd; ++j) ke[i * nd + j] = ke[j * nd + i] = 0.0;
      }
      for (int j = 0; j < nd; ++j) column[j] = K.ownedColumn[ldof[j]];
      for (int i = 0; i < nd; ++i) {
        const Teuchos::ArrayView<const Scalar> values(&ke[i * nd], nd);
        if (ldof[i] < K.numOwnedDofs)  // owned DoFs lead the overlap map: same local row
          K.owned->sumIntoLocalValues(ldof[i], Teuchos::ArrayView<const LocalOrdinal>(column.data(), nd), values);
        else
          K.ghost->sumIntoLocalValues(ldof[i] - K.numOwnedDofs, Teuchos::ArrayView<const LocalOrdinal>(ldof.data(), nd),
                                      values);
      }
    }
    return inverted;
  }

  template <CellType T>
  std::string checkReferenceBlock(std::size_t b) const {
    using Traits = CellTraits<T>;
    const auto& block = mesh.global().blocks[b];
    std::array<double, Traits::dofs> X{}, ue{}, re{};
    std::array<int, Traits::dofs> ldof{};
    const std::array<double, Traits::dim> noForce{};
    for (long long element : mesh.localElements(b)) {
      gather<T>(&block.connectivity[(element - block.firstElement) * Traits::nodes], nullptr, X, ue, ldof);
      if (cellResidualTangent<T>(blockMaterial[b], X, ue, noForce, re, nullptr) != KernelStatus::InvertedReference)
        continue;
      const std::string which = "mesh: element " + std::to_string(element + 1) + " of block '" +
                                mesh::displayName(block.name, "block", block.id) + "'";
      if (hasZeroVolume(T, X.data()))
        return which + " has zero volume (its nodes lie on one " + (Traits::dim == 3 ? "plane" : "line") +
               " or coincide): remesh or remove the degenerate cell";
      return which + " is inverted or degenerate (non-positive Jacobian); check its node order";
    }
    return "";
  }

  template <CellType T>
  void stressBlock(std::size_t b, const double* u, MultiVector& accumulated) const {
    using Traits = CellTraits<T>;
    const auto& block = mesh.global().blocks[b];
    std::array<double, Traits::dofs> X{}, ue{};
    std::array<int, Traits::dofs> ldof{};
    std::array<double, Traits::nodes * 6> weighted{};
    std::array<double, Traits::nodes> weight{};
    for (long long element : mesh.localElements(b)) {
      const long long* cell = &block.connectivity[(element - block.firstElement) * Traits::nodes];
      gather<T>(cell, u, X, ue, ldof);
      cellNodalStress<T>(blockMaterial[b], X, ue, weighted, weight);
      for (int a = 0; a < Traits::nodes; ++a) {
        const int local = mesh.localNode(cell[a]);
        for (int k = 0; k < 6; ++k) accumulated.sumIntoLocalValue(local, k, weighted[a * 6 + k]);
        accumulated.sumIntoLocalValue(local, 6, weight[a]);
      }
    }
  }

  template <FaceType F>
  void faceForces(const LoadedFace& face, double time, double* r) const {
    using Traits = FaceTraits<F>;
    const auto& block = mesh.global().blocks[face.block];
    const int nodesPerCell = mesh::numNodes(block.cellType);
    const long long* cell = &block.connectivity[(face.element - block.firstElement) * nodesPerCell];
    std::array<int, mesh::kMaxFaceNodes> localNodes{};
    faceLocalNodes(block.cellType, face.side, localNodes);
    std::array<double, Traits::dofs> X{}, force{};
    std::array<int, Traits::dofs> ldof{};
    for (int a = 0; a < Traits::nodes; ++a) {
      const long long node = cell[localNodes[a]];
      for (int d = 0; d < Traits::dim; ++d) {
        X[a * Traits::dim + d] = coordinates(node)[d];
        ldof[a * Traits::dim + d] = dofs.localDof(mesh.localNode(node), d);
      }
    }
    const auto& c = model.neumann[face.condition];
    const double scale = c.function(time);
    const MaterialParameters& material = blockMaterial[face.block];
    const bool axisymmetric = isAxisymmetric(material, Traits::dim);
    if (c.kind == NeumannCondition::Kind::Pressure) {
      facePressureForces<F>(X, c.pressure * scale, material.thickness, force, axisymmetric);
    } else {
      std::array<double, Traits::dim> t{};
      for (int d = 0; d < Traits::dim; ++d) t[d] = c.traction[d] * scale;
      faceTractionForces<F>(X, t, material.thickness, force, axisymmetric);
    }
    for (int i = 0; i < Traits::dofs; ++i) r[ldof[i]] -= force[i];  // residual = internal − external
  }

  std::vector<char> constrainedFlags;
  bool constraintsFlag(int dof) const { return constrainedFlags[dof] != 0; }
};

namespace {

template <typename Visitor>
auto dispatchCell(CellType type, Visitor&& visit) {
  switch (type) {
    case CellType::Quad4: return visit(std::integral_constant<CellType, CellType::Quad4>{});
    case CellType::Tri3: return visit(std::integral_constant<CellType, CellType::Tri3>{});
    case CellType::Hex8: return visit(std::integral_constant<CellType, CellType::Hex8>{});
    case CellType::Tet4: return visit(std::integral_constant<CellType, CellType::Tet4>{});
    case CellType::Quad8: return visit(std::integral_constant<CellType, CellType::Quad8>{});
    case CellType::Quad9: return visit(std::integral_constant<CellType, CellType::Quad9>{});
    case CellType::Tri6: return visit(std::integral_constant<CellType, CellType::Tri6>{});
    case CellType::Hex20: return visit(std::integral_constant<CellType, CellType::Hex20>{});
    case CellType::Hex27: return visit(std::integral_constant<CellType, CellType::Hex27>{});
    case CellType::Tet10: return visit(std::integral_constant<CellType, CellType::Tet10>{});
  }
  throw InternalError("unknown cell type");
}

}  // namespace

Assembler::Assembler(const mesh::Mesh& mesh, const DofMap& dofs, const ModelSettings& model)
    : impl_(std::make_unique<Impl>(mesh, dofs, model)) {
  const auto& global = mesh.global();
  impl_->blockMaterial.resize(global.blocks.size());
  for (std::size_t b = 0; b < global.blocks.size(); ++b) {
    const std::string name = mesh::displayName(global.blocks[b].name, "block", global.blocks[b].id);
    const auto it = model.blockMaterials.find(name);
    COULOMB_REQUIRE(it != model.blockMaterials.end(),
                    "deck: element block '" << name << "' of the mesh has no sublist in 'Element Blocks'");
    impl_->blockMaterial[b] = it->second;
  }
  for (const auto& [name, material] : model.blockMaterials) mesh.blockIndex(name, "Element Blocks/" + name);
  for (const auto& b : model.bodyForces)
    if (b.block) mesh.blockIndex(*b.block, "Body Forces/" + b.name + "/Block");
  for (std::size_t c = 0; c < model.neumann.size(); ++c) {
    const auto& set = global.sideSets[mesh.sideSetIndex(model.neumann[c].sideSet,
                                                         "Neumann Conditions/" + model.neumann[c].name + "/Side Set")];
    for (std::size_t i = 0; i < set.elements.size(); ++i)
      if (mesh.elementOwner(set.elements[i]) == mesh.comm()->getRank())
        impl_->loadedFaces.push_back({c, mesh.blockOfElement(set.elements[i]), set.elements[i], set.sides[i]});
  }
  constraints_ = std::make_unique<DirichletConstraints>(mesh, dofs, model.dirichlet);
  impl_->constrainedFlags.resize(dofs.overlapMap()->getNodeNumElements());
  for (std::size_t i = 0; i < impl_->constrainedFlags.size(); ++i)
    impl_->constrainedFlags[i] = constraints_->isConstrained(static_cast<int>(i));

  std::string failure;
  for (std::size_t b = 0; b < global.blocks.size() && failure.empty(); ++b)
    failure = dispatchCell(global.blocks[b].cellType, [&](auto tag) { return impl_->checkReferenceBlock<decltype(tag)::value>(b); });
  throwIfAnyRankFailed(*mesh.comm(), failure);

  impl_->ownedGraph = buildOwnedGraph(mesh, dofs);
  const auto ghostGraph = buildGhostRowsGraph(mesh, dofs);
  impl_->ghostMatrix = Teuchos::rcp(new CrsMatrix(ghostGraph));
  impl_->ghostToOwned = Teuchos::rcp(new Export(ghostGraph->getRowMap(), dofs.ownedMap()));
  // Every overlap DoF a local element couples to an owned DoF is in the owned
  // graph's column map; the others (ghost-ghost couplings) never reach it.
  const auto& overlapMap = *dofs.overlapMap();
  const auto& columnMap = *impl_->ownedGraph->getColMap();
  impl_->ownedColumn.resize(overlapMap.getNodeNumElements());
  for (std::size_t i = 0; i < impl_->ownedColumn.size(); ++i)
    impl_->ownedColumn[i] = columnMap.getLocalElement(overlapMap.getGlobalElement(static_cast<LocalOrdinal>(i)));
  // sumIntoLocalValues would drop a column -1 silently: check the invariant
  // once (every node of a local element touching an owned node is a column).
  const int numOwnedNodes = mesh.numOwnedNodes(), dim = dofs.dofsPerNode();
  for (std::size_t b = 0; b < global.blocks.size(); ++b) {
    const auto& block = global.blocks[b];
    const int n = mesh::numNodes(block.cellType);
    for (long long element : mesh.localElements(b)) {
      const long long* cell = &block.connectivity[(element - block.firstElement) * n];
      bool touchesOwned = false;
      for (int a = 0; a < n; ++a) touchesOwned |= mesh.localNode(cell[a]) < numOwnedNodes;
      for (int a = 0; a < n && touchesOwned; ++a)
        COULOMB_CHECK(impl_->ownedColumn[dofs.localDof(mesh.localNode(cell[a]), 0)] >= 0 &&
                            impl_->ownedColumn[dofs.localDof(mesh.localNode(cell[a]), dim - 1)] >= 0,
                        "node " << cell[a] + 1 << " of element " << element + 1
                                          << " is missing from the owned tangent's column map");
    }
  }
  impl_->overlapResidual = Teuchos::rcp(new Vector(dofs.overlapMap()));
  impl_->overlapU = Teuchos::rcp(new Vector(dofs.overlapMap()));
  impl_->ownedToOverlap = Teuchos::rcp(new Import(dofs.ownedMap(), dofs.overlapMap()));
  impl_->overlapToOwned = Teuchos::rcp(new Export(dofs.overlapMap(), dofs.ownedMap()));
}

Assembler::~Assembler() = default;

Teuchos::RCP<CrsMatrix> Assembler::createMatrix() const {
  auto matrix = Teuchos::rcp(new CrsMatrix(impl_->ownedGraph));
  matrix->fillComplete();
  return matrix;
}

namespace {

/// `matrix` has the owned rows and a column map that starts with the owned
/// graph's, so that the assembler's local column indices hold in it (O(columns)).
bool extendsOwnedColumns(const CrsGraph& graph, const CrsMatrix& matrix) {
  if (matrix.getRowMap().get() != graph.getRowMap().get() || !matrix.isFillComplete()) return false;
  const auto& own = *graph.getColMap();
  const auto& other = *matrix.getColMap();
  if (&own == &other) return true;
  if (other.getNodeNumElements() < own.getNodeNumElements()) return false;
  const auto a = own.getNodeElementList(), b = other.getNodeElementList();
  return std::equal(a.begin(), a.end(), b.begin());
}

}  // namespace

bool Assembler::tangentIsConstant() const {
  return std::all_of(impl_->blockMaterial.begin(), impl_->blockMaterial.end(),
                     [](const MaterialParameters& m) { return m.model == MaterialModel::LinearElastic; });
}

bool Assembler::acceptsTangent(const CrsMatrix& matrix) const {
  const auto& graph = *impl_->ownedGraph;
  if (!extendsOwnedColumns(graph, matrix)) return false;
  // Every entry of the owned graph in the matrix's rows (both sorted by local column).
  const auto k = graph.getLocalGraphHost();
  const auto j = matrix.getLocalMatrixHost().graph;
  for (std::size_t r = 0; r + 1 < k.row_map.extent(0); ++r) {
    auto at = j.row_map(r);
    const auto end = j.row_map(r + 1);
    for (auto e = k.row_map(r); e < k.row_map(r + 1); ++e) {
      while (at < end && j.entries(at) < k.entries(e)) ++at;
      if (at == end || j.entries(at) != k.entries(e)) return false;
    }
  }
  return true;
}

AssemblyStatus Assembler::assemble(double time, const Vector& u, Vector* residual, CrsMatrix* jacobian,
                                   Vector* reactions, bool linearizeLaggingBoundary) {
  Impl& m = *impl_;
  static const auto timer = Teuchos::TimeMonitor::getNewCounter("Coulomb: bulk assembly");
  Teuchos::TimeMonitor scope(*timer);
  m.overlapU->doImport(u, *m.ownedToOverlap, Tpetra::INSERT);
  m.overlapResidual->putScalar(0.0);
  TangentTarget K;
  if (jacobian) {
    // The entry scan of acceptsTangent (O(nnz)) is the caller's: here only its cheap part.
    COULOMB_CHECK(extendsOwnedColumns(*m.ownedGraph, *jacobian),
                    "the tangent must be made by Assembler::createMatrix or accepted by acceptsTangent");
    jacobian->resumeFill();
    jacobian->setAllToScalar(0.0);
    m.ghostMatrix->resumeFill();
    m.ghostMatrix->setAllToScalar(0.0);
    K = {jacobian, m.ghostMatrix.get(), m.ownedColumn.data(), static_cast<int>(m.dofs.ownedMap()->getNodeNumElements())};
  }
  long long inverted = std::numeric_limits<long long>::max();  // the lowest inverted element here
  // Prescribed DoFs behind their values (DirichletConstraints.hpp): only the
  // Newton residual carries their coupling; collective test, so every rank imports.
  Teuchos::ArrayRCP<const double> pendingData;
  AssemblyStatus status;
  if (linearizeLaggingBoundary && residual) {
    if (m.ownedPending.is_null()) {
      m.ownedPending = Teuchos::rcp(new Vector(m.dofs.ownedMap()));
      m.overlapPending = Teuchos::rcp(new Vector(m.dofs.overlapMap()));
    }
    if (anyRank(*m.mesh.comm(), constraints_->pendingIncrements(time, u, *m.ownedPending))) {
      m.overlapPending->doImport(*m.ownedPending, *m.ownedToOverlap, Tpetra::INSERT);
      pendingData = m.overlapPending->getData(0);
      status.boundaryLags = true;
    }
  }
  {
    auto uData = m.overlapU->getData(0);
    auto rData = m.overlapResidual->getDataNonConst(0);
    for (std::size_t b = 0; b < m.mesh.global().blocks.size(); ++b) {
      const long long first = dispatchCell(m.mesh.global().blocks[b].cellType, [&](auto tag) {
        return m.assembleBlock<decltype(tag)::value>(b, time, uData.get(), rData.get(), K, pendingData.get());
      });
      if (first >= 0) inverted = std::min(inverted, first);
    }
    for (const auto& face : m.loadedFaces) {
      switch (faceType(m.mesh.global().blocks[face.block].cellType, face.side)) {
        case FaceType::Line2: m.faceForces<FaceType::Line2>(face, time, rData.get()); break;
        case FaceType::Tri3: m.faceForces<FaceType::Tri3>(face, time, rData.get()); break;
        case FaceType::Quad4: m.faceForces<FaceType::Quad4>(face, time, rData.get()); break;
        case FaceType::Line3: m.faceForces<FaceType::Line3>(face, time, rData.get()); break;
        case FaceType::Tri6: m.faceForces<FaceType::Tri6>(face, time, rData.get()); break;
        case FaceType::Quad8: m.faceForces<FaceType::Quad8>(face, time, rData.get()); break;
        case FaceType::Quad9: m.faceForces<FaceType::Quad9>(face, time, rData.get()); break;
      }
    }
  }
  long long lowest = inverted;
  Teuchos::reduceAll(*m.mesh.comm(), Teuchos::REDUCE_MIN, inverted, Teuchos::outArg(lowest));
  if (lowest != std::numeric_limits<long long>::max()) {
    status.invertedElement = true;
    status.invertedElementNumber = lowest;
    for (const auto& block : m.mesh.global().blocks)
      if (lowest >= block.firstElement &&
          lowest < block.firstElement + block.numElements())
        status.invertedBlock = mesh::displayName(block.name, "block", block.id);
  }

  const auto prescribed = constraints_->ownedConstrainedDofs();
  if (residual || reactions) {  // a tangent-only call (NOX's computeJacobian) needs no residual export
    Vector ownedResidual(m.dofs.ownedMap());
    ownedResidual.doExport(*m.overlapResidual, *m.overlapToOwned, Tpetra::ADD);
    if (reactions) {
      reactions->putScalar(0.0);
      auto source = ownedResidual.getData(0);
      auto target = reactions->getDataNonConst(0);
      for (int dof : prescribed) target[dof] = source[dof];
    }
    if (residual) {
      constraints_->setResidualRows(time, u, ownedResidual);
      residual->assign(ownedResidual);
    }
  }
  if (jacobian) {
    m.ghostMatrix->fillComplete(m.dofs.ownedMap(), m.dofs.ownedMap());
    // Ghost rows are owned elsewhere: the export only sends (no local
    // same/permute rows), and ADD sums them into the owned rows.
    jacobian->doExport(*m.ghostMatrix, *m.ghostToOwned, Tpetra::ADD);
    const Scalar one = 1.0;
    for (int dof : prescribed)  // owned DoFs lead the column map, so row index == column index
      jacobian->replaceLocalValues(dof, Teuchos::ArrayView<const LocalOrdinal>(&dof, 1),
                                   Teuchos::ArrayView<const Scalar>(&one, 1));
    jacobian->fillComplete(m.dofs.ownedMap(), m.dofs.ownedMap());
  }
  return status;
}

double Assembler::externalForceNorm(double time) {
  Vector zero(impl_->dofs.ownedMap()), residual(impl_->dofs.ownedMap()), reactions(impl_->dofs.ownedMap());
  assemble(time, zero, &residual, nullptr, &reactions);
  // Free rows of the residual hold -f_ext; the prescribed rows hold -u_bar
  // (a length) there, and the reaction vector their load instead.
  auto r = residual.getDataNonConst(0);
  const auto q = reactions.getData(0);
  for (int dof : constraints_->ownedConstrainedDofs()) r[dof] = q[dof];
  return residual.norm2();
}

void Assembler::nodalStress(const Vector& u, MultiVector& stress) const {
  const Impl& m = *impl_;
  Vector overlapU(m.dofs.overlapMap());
  overlapU.doImport(u, *m.ownedToOverlap, Tpetra::INSERT);
  const auto overlapNodes = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                                 Teuchos::ArrayView<const GlobalOrdinal>(
                                                     reinterpret_cast<const GlobalOrdinal*>(m.mesh.localNodes().data()),
                                                     m.mesh.localNodes().size()),
                                                 0, m.mesh.comm()));
  MultiVector accumulated(overlapNodes, 7);
  {
    auto uData = overlapU.getData(0);
    for (std::size_t b = 0; b < m.mesh.global().blocks.size(); ++b)
      dispatchCell(m.mesh.global().blocks[b].cellType,
                   [&](auto tag) { m.stressBlock<decltype(tag)::value>(b, uData.get(), accumulated); });
  }
  MultiVector owned(m.dofs.ownedNodeMap(), 7);
  owned.doExport(accumulated, Export(overlapNodes, m.dofs.ownedNodeMap()), Tpetra::ADD);
  const std::size_t numOwned = m.dofs.ownedNodeMap()->getNodeNumElements();
  auto in = owned.get2dView();
  auto out = stress.get2dViewNonConst();
  for (std::size_t i = 0; i < numOwned; ++i) {
    const double w = in[6][i];
    std::array<double, 6> s{};
    for (int k = 0; k < 6; ++k) s[k] = w > 0 ? in[k][i] / w : 0.0;
    for (int k = 0; k < 6; ++k) out[k][i] = s[k];
    out[6][i] = vonMises(s);
  }
}

std::string AssemblyStatus::invertedMessage() const {
  if (!invertedElement) return "";
  return "element " + std::to_string(invertedElementNumber + 1) + " of block '" + invertedBlock +
         "' is inverted (det F <= 0)";
}

}  // namespace coulomb::fem
