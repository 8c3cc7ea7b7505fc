#pragma once
/// @file TripletAssembly.hpp
/// @brief Sparse contributions given as (row, column, value) triplets by any
/// rank, summed on the owner of the row into a Tpetra matrix or vector.
///
/// Why not an overlap matrix and a Tpetra Export: the contact contributions
/// change their pattern with every search and active-set change, and a
/// Tpetra 13.2 CrsMatrix cannot grow rows past its allocation; so the
/// triplets are shipped to the row owners first (one MPI_Alltoallv), each
/// owner counts its rows exactly and builds a fresh, fill-completed matrix.
#include <vector>

#include <Teuchos_RCP.hpp>

#include <Tpetra_CrsMatrix_decl.hpp>

#include "coulomb/core/TpetraTypes.hpp"

namespace coulomb::linalg {

/// One matrix contribution A(row, column) += value (global indices).
struct MatrixTriplet {
  GlobalOrdinal row = 0;
  GlobalOrdinal column = 0;
  double value = 0.0;
};

/// One vector contribution v(row) += value (global index).
struct VectorEntry {
  GlobalOrdinal row = 0;
  double value = 0.0;
};

/// @brief Collective: the square matrix with row, domain and range map
/// `map` (one-to-one) holding the sum of every rank's `triplets`.
/// Duplicates are added; explicit zeros are kept (the pattern is what was
/// given). Throws coulomb::Error (on every rank) if a row is not in `map`.
Teuchos::RCP<CrsMatrix> matrixFromTriplets(const std::vector<MatrixTriplet>& triplets,
                                           const Teuchos::RCP<const Map>& map);

/// @brief Collective: the matrix K + (sum of every rank's `triplets`), with
/// K's row, domain and range maps; K must be fill-complete and its rows sorted.
/// A triplet of at most 1e-14 of its row's largest entry in K (an exact zero
/// among them) is left out: it would add pattern, not a value.
/// Built directly in compressed-row form (K's column map extended by the new
/// columns, each row K's entries in order then the new ones sorted): a
/// general sparse sum (Tpetra::MatrixMatrix::add) sorts every row and costs
/// several times more on the size of K.
Teuchos::RCP<CrsMatrix> addTriplets(const CrsMatrix& K, const std::vector<MatrixTriplet>& triplets);

/// @brief addTriplets for a Newton loop: when K + S has the pattern of the
/// previous result (same column map, same rows), that matrix gets the new
/// values in place and is returned again; otherwise the new matrix is built
/// in the memory of the previous one when it fits (a fresh allocation of
/// K's size costs mostly first-touch page faults on this machine).
/// The result of a call is overwritten by the next call: callers must not
/// keep it across calls.
class MatrixSum {
public:
  /// Collective, as addTriplets.
  Teuchos::RCP<CrsMatrix> add(const CrsMatrix& K, const std::vector<MatrixTriplet>& triplets);
  /// The last result (null before the first call). K may be this matrix
  /// itself, refilled by the caller (fem::Assembler::acceptsTangent): the sum
  /// is then formed in place, and a new pattern (K's and the triplets'
  /// entries) is merged into the same buffers row by row from the end when
  /// their capacity allows, so that no second matrix of K's size is made.
  Teuchos::RCP<CrsMatrix> last() const { return last_; }
  /// Calls that reused the previous matrix (for tests and diagnostics).
  int reuses() const { return reuses_; }
  /// Calls that merged a grown pattern into K's own buffers (K = last()).
  int inPlaceMerges() const { return inPlaceMerges_; }
  /// Turns the last result back into the K of the last call, on the result's
  /// pattern (the entries K lacks set to zero): the rows that got triplets
  /// take the K values kept from that call, the others are K's already.
  /// For a K that does not change (linear elasticity), this replaces its
  /// assembly; the values are bitwise those of the K given. False before the
  /// first call (nothing done) or if the result lacks an entry of K (values
  /// partly rewritten: the caller must fill the matrix anew). Local.
  bool restoreBase();
  /// Successful restoreBase() calls (for tests and diagnostics).
  int restores() const { return restores_; }
  /// This rank's last result has more than `factor` x (triplets of the last
  /// call that were not negligible) entries beyond those of the last K that
  /// was not the result itself.
  /// In place the pattern only grows (a sliding contact leaves its old
  /// couplings as zeros): the caller then assembles K apart once, to start
  /// from the current couplings again. Local.
  bool grownBeyond(double factor) const;

private:
  using LocalMatrix = CrsMatrix::local_matrix_device_type;
  typename LocalMatrix::row_map_type::non_const_type rowBuffer_;  ///< row pointers being built
  typename LocalMatrix::index_type::non_const_type indexBuffer_;  ///< column indices (capacity >= nnz)
  typename LocalMatrix::values_type::non_const_type valueBuffer_;  ///< values (same capacity)
  std::vector<GlobalOrdinal> columnGids_;
  Teuchos::RCP<CrsMatrix> last_;
  std::vector<GlobalOrdinal> lastColumnGids_;
  Teuchos::RCP<const Map> lastColumnMap_;   ///< the last result's column map ...
  Teuchos::RCP<const Import> lastImporter_;  ///< ... and importer, reused for the same columns
  const Map* lastDomainMap_ = nullptr;       ///< K's domain map then (the importer's source)
  int reuses_ = 0;
  int inPlaceMerges_ = 0;
  int restores_ = 0;
  /// K's entries (local column, value) of the rows the last call added
  /// triplets to, row baseRows_[i] at [baseStart_[i], baseStart_[i + 1]).
  std::vector<LocalOrdinal> baseRows_;
  std::vector<std::size_t> baseStart_;
  std::vector<std::pair<LocalOrdinal, double>> baseRowEntries_;
  std::size_t baseEntryCount_ = 0;  ///< entries of the last K that was not the result itself
  std::size_t lastTriplets_ = 0;  ///< triplets of rows this rank owns in the last call (its own and received; kept ones)
};

/// @brief Collective: adds every rank's `entries` into `owned` (on its map).
void addEntries(const std::vector<VectorEntry>& entries, Vector& owned);

/// @brief Collective: every rank's `triplets` (rows in `map`) moved to the
/// owners of their rows: returns this rank's own ones followed by those the
/// other ranks hold for rows it owns.
std::vector<MatrixTriplet> onRowOwners(const std::vector<MatrixTriplet>& triplets, const Map& map);
/// @brief onRowOwners for vector entries.
std::vector<VectorEntry> onRowOwners(const std::vector<VectorEntry>& entries, const Map& map);

}  // namespace coulomb::linalg
