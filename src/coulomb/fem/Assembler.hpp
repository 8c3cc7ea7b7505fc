#pragma once
/// @file Assembler.hpp
/// @brief Bulk residual and tangent of all blocks, surface and body loads,
/// reactions and nodal stress, assembled into Tpetra objects.
///
/// Each rank integrates its own elements into overlap objects (rows of every
/// local node) and exports them, adding, to the owned objects.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "coulomb/core/TpetraTypes.hpp"
#include "coulomb/fem/DirichletConstraints.hpp"
#include "coulomb/fem/DofMap.hpp"
#include "coulomb/fem/Material.hpp"
#include "coulomb/fem/ModelSettings.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::fem {

/// @brief Outcome of one assembly: an element inverted under the current
/// displacement (det F <= 0) makes the Newton iterate unusable.
struct AssemblyStatus {
  bool invertedElement = false;
  /// The lowest-numbered inverted element on any rank (0-based global
  /// number, -1 if none) and its block's name: the failure names them.
  long long invertedElementNumber = -1;
  std::string invertedBlock;
  /// With linearizeLaggingBoundary: a prescribed DoF lagged behind ū on some
  /// rank (the residual carries its linearised coupling, not its value).
  bool boundaryLags = false;
  /// "element N of block 'B' is inverted (det F <= 0)", or "" if none is.
  std::string invertedMessage() const;
};

class Assembler {
public:
  /// Checks every element's reference Jacobian (a non-positive one is an
  /// input error naming block and element) and builds the sparsity graphs.
  Assembler(const mesh::Mesh& mesh, const DofMap& dofs, const ModelSettings& model);
  ~Assembler();

  /// A matrix on the owned graph, to be filled by assemble().
  Teuchos::RCP<CrsMatrix> createMatrix() const;
  /// True when assemble() can fill `matrix` in place: it has the owned rows,
  /// every entry of the owned graph, and a column map that starts with the
  /// owned graph's (a condensed contact tangent built on K by
  /// linalg::MatrixSum). Its other entries are zeroed by assemble(), which
  /// checks only the rows and columns: a caller passing another matrix than
  /// createMatrix()'s asks this first. Local.
  bool acceptsTangent(const CrsMatrix& matrix) const;
  /// The tangent does not depend on u or t: every block is linear elastic
  /// (small strain), the prescribed DoFs are fixed. Local (the same on every rank).
  bool tangentIsConstant() const;
  const DirichletConstraints& constraints() const { return *constraints_; }

  /// residual = f_int(u) − f_ext(t) with prescribed rows u − ū(t); jacobian
  /// (may be null) its derivative with prescribed rows/columns of the
  /// identity. Collective. `reactions` (may be null) receives f_int − f_ext
  /// on prescribed DoFs and zero elsewhere. `linearizeLaggingBoundary`: where
  /// u lags behind ū(t) on prescribed DoFs, the free rows of the residual
  /// also get the coupling K_fp (ū − u_p) (DirichletConstraints.hpp): the
  /// Newton residual; off for a residual meant as forces at u itself.
  AssemblyStatus assemble(double time, const Vector& u, Vector* residual, CrsMatrix* jacobian,
                          Vector* reactions = nullptr, bool linearizeLaggingBoundary = false);

  /// ||f_ext(t)||: the 2-norm over every DoF (prescribed ones included) of
  /// the loads at `time` (surface loads and body forces; the internal force
  /// at u = 0 is zero for every material here). A scale of the step's forces
  /// for the Newton test. Collective; one residual assembly.
  double externalForceNorm(double time);

  /// Nodal Cauchy stress by lumped L2 projection: owned node map, 7 columns
  /// (xx yy zz xy yz xz, von Mises).
  void nodalStress(const Vector& u, MultiVector& stress) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<DirichletConstraints> constraints_;
};

}  // namespace coulomb::fem
