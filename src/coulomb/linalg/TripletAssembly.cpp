#include "coulomb/linalg/TripletAssembly.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <unordered_map>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/Parallel.hpp"

namespace coulomb::linalg {

/// A triplet is left out when it is at most this fraction of its row's
/// largest entry in K (some fifty units of round-off of that entry): the
/// tangent it would refine is solved to 1e-3 .. 1e-10 relative, so no
/// Newton iterate can tell. Exact zeros are left out whatever the row; a
/// NaN is kept (the solve must see it). The entries this leaves out in
/// practice are 1e-20 to 1e-45 of their rows (MatrixSum::add). The scale is
/// K's row, not the sum's: a contact row whose K part cancels (T - I = -1
/// on an active slave row) keeps entries of the penalty's size, which a
/// penalty 1e14 times below E/h would fall under.
constexpr double kNegligibleEntry = 1e-14;

namespace {

/// Local index of `row` in `map`, or invalid. Contributions come in runs of
/// one row (a node's rows, a combination row), so the last answer is kept:
/// on a non-contiguous map (np > 1) each lookup is a hash probe.
class RowLookup {
public:
  explicit RowLookup(const Map& map) : map_(map) {}
  LocalOrdinal operator()(GlobalOrdinal row) {
    if (row != lastRow_) {
      lastRow_ = row;
      lastLocal_ = map_.getLocalElement(row);
    }
    return lastLocal_;
  }
  static LocalOrdinal invalid() { return Teuchos::OrdinalTraits<LocalOrdinal>::invalid(); }

private:
  const Map& map_;
  GlobalOrdinal lastRow_ = -1;
  LocalOrdinal lastLocal_ = invalid();
};

/// Sends record r (`width` doubles each, row GID first) whose row this rank
/// does not own to the owner of that row; returns the records of other ranks
/// for rows this rank owns. The caller keeps its own records where they are.
std::vector<double> toOwners(const std::vector<double>& records, int width, const Map& map) {
  const auto& comm = *map.getComm();
  const int size = comm.getSize();
  const std::size_t n = records.size() / width;
  if (size == 1) {  // one rank owns every row of the DoF map: a record here is outside it
    COULOMB_CHECK(records.empty(), "contribution to row " << static_cast<GlobalOrdinal>(records[0])
                                                                      << " outside the DoF map");
    return {};
  }
  // The owner of each distinct row, looked up once (Tpetra's directory is
  // given a sorted list without duplicates). One extra, valid index on every
  // rank: Map::getRemoteIndexList returns at once for an empty list, skipping
  // the collective set-up of its directory that the ranks with entries do —
  // a rank without contributions would then desynchronise the others.
  std::vector<GlobalOrdinal> distinct;
  for (std::size_t i = 0; i < n; ++i) distinct.push_back(static_cast<GlobalOrdinal>(records[i * width]));
  distinct.push_back(map.getMinAllGlobalIndex());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<int> distinctOwners(distinct.size(), -1);
  std::vector<LocalOrdinal> locals(distinct.size());
  map.getRemoteIndexList(Teuchos::ArrayView<const GlobalOrdinal>(distinct.data(), distinct.size()),
                         Teuchos::ArrayView<int>(distinctOwners.data(), distinct.size()),
                         Teuchos::ArrayView<LocalOrdinal>(locals.data(), distinct.size()));
  std::vector<std::vector<double>> send(static_cast<std::size_t>(size));
  std::string failure;
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<GlobalOrdinal>(records[i * width]);
    const int owner = distinctOwners[std::lower_bound(distinct.begin(), distinct.end(), row) - distinct.begin()];
    if ((owner < 0 || owner >= size) && failure.empty())
      failure = "internal: contribution to row " + std::to_string(row) + " outside the DoF map";
    if (failure.empty())
      send[owner].insert(send[owner].end(), records.begin() + i * width, records.begin() + (i + 1) * width);
  }
  throwIfAnyRankFailed(comm, failure);
  return exchangeByRank(comm, std::move(send));
}

/// Matrix triplets routed to the owners of their rows: this rank's own
/// triplets stay in the caller's vector (most of them: contributions are
/// emitted by the owner of the slave node), only the others travel.
struct RoutedTriplets {
  std::vector<LocalOrdinal> localRow;  ///< per input triplet: its local row here, or invalid (sent away)
  std::vector<MatrixTriplet> received;  ///< other ranks' triplets for rows owned here
  std::vector<LocalOrdinal> receivedRow;  ///< their local rows
};

/// Collective.
RoutedTriplets routeToOwners(const std::vector<MatrixTriplet>& triplets, const Map& map) {
  RoutedTriplets routed;
  RowLookup local(map);
  routed.localRow.resize(triplets.size());
  std::vector<double> away;  // (row, column, value) records of rows owned elsewhere
  for (std::size_t i = 0; i < triplets.size(); ++i) {
    routed.localRow[i] = local(triplets[i].row);
    if (routed.localRow[i] == RowLookup::invalid())
      away.insert(away.end(), {static_cast<double>(triplets[i].row), static_cast<double>(triplets[i].column),
                               triplets[i].value});
  }
  const auto records = toOwners(away, 3, map);
  for (std::size_t i = 0; i < records.size(); i += 3) {
    const auto row = static_cast<GlobalOrdinal>(records[i]);
    routed.received.push_back({row, static_cast<GlobalOrdinal>(records[i + 1]), records[i + 2]});
    routed.receivedRow.push_back(local(row));
  }
  return routed;
}

}  // namespace

Teuchos::RCP<CrsMatrix> matrixFromTriplets(const std::vector<MatrixTriplet>& triplets,
                                           const Teuchos::RCP<const Map>& map) {
  const auto routed = routeToOwners(triplets, *map);
  std::map<GlobalOrdinal, std::map<GlobalOrdinal, double>> rows;
  for (std::size_t i = 0; i < triplets.size(); ++i)
    if (routed.localRow[i] != RowLookup::invalid()) rows[triplets[i].row][triplets[i].column] += triplets[i].value;
  for (const auto& t : routed.received) rows[t.row][t.column] += t.value;

  const std::size_t numLocal = map->getNodeNumElements();
  Teuchos::Array<std::size_t> counts(numLocal, 0);
  for (const auto& [row, columns] : rows) counts[map->getLocalElement(row)] = columns.size();
  auto matrix = Teuchos::rcp(new CrsMatrix(map, counts()));
  std::vector<GlobalOrdinal> cols;
  std::vector<double> values;
  for (const auto& [row, columns] : rows) {
    cols.clear();
    values.clear();
    for (const auto& [column, value] : columns) {
      cols.push_back(column);
      values.push_back(value);
    }
    matrix->insertGlobalValues(row, Teuchos::ArrayView<const GlobalOrdinal>(cols.data(), cols.size()),
                               Teuchos::ArrayView<const double>(values.data(), values.size()));
  }
  matrix->fillComplete(map, map);
  return matrix;
}

std::vector<MatrixTriplet> onRowOwners(const std::vector<MatrixTriplet>& triplets, const Map& map) {
  RoutedTriplets routed = routeToOwners(triplets, map);
  std::vector<MatrixTriplet> here;
  for (std::size_t i = 0; i < triplets.size(); ++i)
    if (routed.localRow[i] != RowLookup::invalid()) here.push_back(triplets[i]);
  here.insert(here.end(), routed.received.begin(), routed.received.end());
  return here;
}

std::vector<VectorEntry> onRowOwners(const std::vector<VectorEntry>& entries, const Map& map) {
  RowLookup local(map);
  std::vector<VectorEntry> here;
  std::vector<double> away;
  for (const auto& e : entries)
    if (local(e.row) != RowLookup::invalid()) here.push_back(e);
    else away.insert(away.end(), {static_cast<double>(e.row), e.value});
  const auto records = toOwners(away, 2, map);
  for (std::size_t i = 0; i < records.size(); i += 2) here.push_back({static_cast<GlobalOrdinal>(records[i]), records[i + 1]});
  return here;
}

void addEntries(const std::vector<VectorEntry>& entries, Vector& owned) {
  const auto& map = *owned.getMap();
  RowLookup local(map);
  std::vector<double> away;  // (row, value) records of rows owned elsewhere
  std::vector<std::pair<LocalOrdinal, double>> here;
  for (const auto& e : entries) {
    const LocalOrdinal i = local(e.row);
    if (i != RowLookup::invalid()) here.push_back({i, e.value});
    else away.insert(away.end(), {static_cast<double>(e.row), e.value});
  }
  const auto mine = toOwners(away, 2, map);  // checks the rows (collectively) before anything is added
  auto data = owned.getDataNonConst(0);
  for (const auto& [i, value] : here) data[i] += value;
  for (std::size_t i = 0; i < mine.size(); i += 2) data[local(static_cast<GlobalOrdinal>(mine[i]))] += mine[i + 1];
}

Teuchos::RCP<CrsMatrix> addTriplets(const CrsMatrix& K, const std::vector<MatrixTriplet>& triplets) {
  MatrixSum sum;
  return sum.add(K, triplets);
}

Teuchos::RCP<CrsMatrix> MatrixSum::add(const CrsMatrix& K, const std::vector<MatrixTriplet>& triplets) {
  const auto rowMap = K.getRowMap();
  const auto routed = routeToOwners(triplets, *rowMap);
  if (last_.get() != &K) baseEntryCount_ = K.getNodeNumEntries();

  // Column map: K's, then the columns only the triplets have (in order of appearance).
  const auto kColumns = K.getColMap();
  columnGids_.assign(kColumns->getNodeElementList().begin(), kColumns->getNodeElementList().end());
  const std::size_t kColumnCount = columnGids_.size();
  std::unordered_map<GlobalOrdinal, LocalOrdinal> extra;
  auto localColumnOf = [&](GlobalOrdinal column) {
    LocalOrdinal c = kColumns->getLocalElement(column);
    if (c != Teuchos::OrdinalTraits<LocalOrdinal>::invalid()) return c;
    const auto it = extra.find(column);
    if (it != extra.end()) return it->second;
    c = static_cast<LocalOrdinal>(columnGids_.size());
    columnGids_.push_back(column);
    extra.emplace(column, c);
    return c;
  };
  // K's compressed rows, read directly (Serial node: the device view is host memory).
  const auto localK = K.getLocalMatrixDevice();
  const auto kRows = localK.graph.row_map;
  const auto kEntries = localK.graph.entries;
  const auto kValues = localK.values;
  // This rank's triplets (its own, then those received) grouped by local
  // row (counting sort) as (local column, value), each row sorted by column.
  // Negligible ones are left out (kNegligibleEntry), before they can add a
  // column: the interface rows (T - I) K are formed over K's whole pattern,
  // whose dead couplings are explicit zeros (the pattern only grows in
  // place), and the contact derivatives hold values of 1e-20 to 1e-45 of
  // their row; each of them in a new column grew the pattern at every
  // iterate, by one more ring of nodes (HEX20 hertz3d --ref 1: 300 to 77000
  // new entries per iterate with the set unchanged), and each growth was a
  // K-sized rewrite and a new preconditioner.
  const std::size_t numRows = rowMap->getNodeNumElements();
  std::vector<double> negligible(numRows, -1.0);  // per row, once it is needed
  auto kept = [&](LocalOrdinal row, double value) {
    double& bound = negligible[static_cast<std::size_t>(row)];
    if (bound < 0.0) {
      double scale = 0.0;  // the row's largest entry in K
      for (auto k = kRows(row); k < kRows(row + 1); ++k) scale = std::max(scale, std::abs(kValues(k)));
      bound = kNegligibleEntry * scale;
    }
    return !(std::abs(value) <= bound);  // a NaN is kept
  };
  std::vector<char> keep(triplets.size() + routed.received.size(), 0);
  std::vector<std::size_t> start(numRows + 1, 0);
  for (std::size_t i = 0; i < triplets.size(); ++i)
    if (routed.localRow[i] != RowLookup::invalid() && (keep[i] = kept(routed.localRow[i], triplets[i].value)))
      ++start[routed.localRow[i] + 1];
  for (std::size_t i = 0; i < routed.received.size(); ++i)
    if ((keep[triplets.size() + i] = kept(routed.receivedRow[i], routed.received[i].value)))
      ++start[routed.receivedRow[i] + 1];
  for (std::size_t r = 0; r < numRows; ++r) start[r + 1] += start[r];
  const std::size_t n = start[numRows];
  lastTriplets_ = n;
  std::vector<std::pair<LocalOrdinal, double>> grouped(n);
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < triplets.size(); ++i)
      if (keep[i]) grouped[cursor[routed.localRow[i]]++] = {localColumnOf(triplets[i].column), triplets[i].value};
    for (std::size_t i = 0; i < routed.received.size(); ++i)
      if (keep[triplets.size() + i])
        grouped[cursor[routed.receivedRow[i]]++] = {localColumnOf(routed.received[i].column), routed.received[i].value};
  }
  for (std::size_t r = 0; r < numRows; ++r)
    if (start[r + 1] - start[r] > 1)
      std::stable_sort(grouped.begin() + static_cast<std::ptrdiff_t>(start[r]), grouped.begin() + static_cast<std::ptrdiff_t>(start[r + 1]),
                [](const auto& a, const auto& b) { return a.first < b.first; });

  // K's rows that get triplets, kept for restoreBase() before anything is
  // written (in place, K is the buffers about to be overwritten). K's local
  // columns are the result's too: its column map starts with K's.
  baseRows_.clear();
  baseStart_.assign(1, 0);
  baseRowEntries_.clear();
  for (std::size_t r = 0; r < numRows; ++r) {
    if (start[r] == start[r + 1]) continue;
    baseRows_.push_back(static_cast<LocalOrdinal>(r));
    for (auto k = kRows(r); k < kRows(r + 1); ++k) baseRowEntries_.push_back({kEntries(k), kValues(k)});
    baseStart_.push_back(baseRowEntries_.size());
  }
  // Row r of K + S: K's entries with the triplets of the row added (a binary
  // search finds an existing column; new ones, duplicates summed, are merged
  // in), sorted by local column as K's rows are.
  std::vector<std::pair<LocalOrdinal, double>> merged;
  auto mergeRow = [&](std::size_t r) {
    merged.clear();
    for (auto k = kRows(r); k < kRows(r + 1); ++k) merged.push_back({kEntries(k), kValues(k)});
    const std::size_t kCount = merged.size();
    for (std::size_t k = start[r]; k < start[r + 1];) {
      const LocalOrdinal c = grouped[k].first;
      double v = 0;
      for (; k < start[r + 1] && grouped[k].first == c; ++k) v += grouped[k].second;
      const auto end = merged.begin() + static_cast<std::ptrdiff_t>(kCount);
      const auto it = std::lower_bound(merged.begin(), end, c, [](const auto& e, LocalOrdinal x) { return e.first < x; });
      if (it != end && it->first == c) it->second += v;
      else merged.push_back({c, v});
    }
    std::inplace_merge(merged.begin(), merged.begin() + static_cast<std::ptrdiff_t>(kCount), merged.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
  };

  // The pattern of the last result again (same columns, every row as
  // before): only the values are written, straight into that matrix — one
  // pass over K, no buffer of its size. Every rank must agree (collective).
  // K = the last result (refilled): its rows without triplets are the
  // result's own, so only the interface rows are checked.
  const bool inPlace = last_.get() == &K;
  bool samePattern = !last_.is_null() && columnGids_ == lastColumnGids_;
  if (samePattern) {
    const auto graph = last_->getLocalMatrixDevice().graph;
    samePattern = graph.row_map.extent(0) == numRows + 1;
    for (std::size_t r = 0; samePattern && r < numRows; ++r) {
      const auto first = graph.row_map(r), count = graph.row_map(r + 1) - first;
      if (start[r] == start[r + 1]) {
        if (inPlace) continue;
        samePattern = count == kRows(r + 1) - kRows(r) &&
                      std::equal(kEntries.data() + kRows(r), kEntries.data() + kRows(r + 1), graph.entries.data() + first);
      } else {
        mergeRow(r);
        samePattern = count == merged.size();
        for (std::size_t k = 0; samePattern && k < merged.size(); ++k)
          samePattern = graph.entries(first + k) == merged[k].first;
      }
    }
  }
  if (!anyRank(*rowMap->getComm(), !samePattern)) {
    const auto local = last_->getLocalMatrixDevice();
    for (std::size_t r = 0; r < numRows; ++r) {
      const auto first = local.graph.row_map(r);
      if (start[r] == start[r + 1]) {
        if (!inPlace)
          std::copy(kValues.data() + kRows(r), kValues.data() + kRows(r + 1), local.values.data() + first);
      } else {
        mergeRow(r);
        for (std::size_t k = 0; k < merged.size(); ++k) local.values(first + k) = merged[k].second;
      }
    }
    ++reuses_;
    return last_;
  }

  // A new matrix, written straight into compressed-row views. Their memory is
  // that of the previous result when it is large enough (the previous result
  // is dead by the contract of add()): a fresh allocation of K's size costs
  // mostly first-touch page faults on this machine (~0.3 s per call at 67k
  // DoFs), and no second copy of K's size is alive at any time.
  const bool newColumns = columnGids_.size() > kColumnCount;
  const bool anyNewColumns = anyRank(*rowMap->getComm(), newColumns);
  // Row pointers of K + S, apart: K's may be rowBuffer_ itself (inPlace).
  std::vector<std::size_t> rows(numRows + 1, 0);
  for (std::size_t r = 0; r < numRows; ++r) {
    std::size_t count = kRows(r + 1) - kRows(r);
    if (start[r] != start[r + 1]) {
      mergeRow(r);
      count = merged.size();
    }
    rows[r + 1] = rows[r] + count;
  }
  const std::size_t nnz = rows[numRows];
  // Row r of K + S written at rows[r] of the buffers. copy_backward: in
  // place the destination is the source shifted right (or the same).
  auto writeRow = [&](std::size_t r) {
    std::size_t at = rows[r];
    if (start[r] == start[r + 1]) {
      const auto from = kRows(r), count = kRows(r + 1) - kRows(r);
      if (kEntries.data() + from == indexBuffer_.data() + at && kValues.data() + from == valueBuffer_.data() + at)
        return;  // in place and not moved
      std::copy_backward(kEntries.data() + from, kEntries.data() + from + count, indexBuffer_.data() + at + count);
      std::copy_backward(kValues.data() + from, kValues.data() + from + count, valueBuffer_.data() + at + count);
      return;
    }
    mergeRow(r);
    for (const auto& [column, value] : merged) {
      indexBuffer_(at) = column;
      valueBuffer_(at) = value;
      ++at;
    }
  };
  if (inPlace && indexBuffer_.extent(0) >= nnz) {
    // K is the last result, refilled: its rows only grow (all of K's entries
    // stay), so row r moves to an offset >= its old one. From the last row
    // backwards, each row is read (mergeRow copies it) before anything is
    // written over it; no second matrix of K's size is made.
    for (std::size_t r = numRows; r-- > 0;) writeRow(r);
    std::copy(rows.begin(), rows.end(), rowBuffer_.data());
    ++inPlaceMerges_;
  } else {
    if (inPlace) {
      // No room left in K's buffers: new ones (K keeps the old alive until its caller drops it).
      rowBuffer_ = decltype(rowBuffer_)();
      indexBuffer_ = decltype(indexBuffer_)();
      valueBuffer_ = decltype(valueBuffer_)();
    }
    last_ = Teuchos::null;
    if (rowBuffer_.extent(0) != numRows + 1)
      rowBuffer_ = decltype(rowBuffer_)(Kokkos::ViewAllocateWithoutInitializing("rows"), numRows + 1);
    std::copy(rows.begin(), rows.end(), rowBuffer_.data());
    if (indexBuffer_.extent(0) < nnz) {
      // A little room for the patterns of the next iterations (contact grows).
      const std::size_t capacity = nnz + nnz / 50;
      indexBuffer_ = decltype(indexBuffer_)();
      valueBuffer_ = decltype(valueBuffer_)();
      indexBuffer_ = decltype(indexBuffer_)(Kokkos::ViewAllocateWithoutInitializing("columns"), capacity);
      valueBuffer_ = decltype(valueBuffer_)(Kokkos::ViewAllocateWithoutInitializing("values"), capacity);
    }
    for (std::size_t r = 0; r < numRows; ++r) writeRow(r);
  }
  const auto range = std::make_pair(std::size_t(0), nnz);
  const auto indexView = Kokkos::subview(indexBuffer_, range);
  const auto valueView = Kokkos::subview(valueBuffer_, range);
  const auto& pointerView = rowBuffer_;
  // The column map and importer: K's when no rank has new columns (always
  // in serial); the last result's when every rank has the same columns as
  // then (a new pattern in the same columns: the set changed, the
  // neighbourhood did not); else new ones (collective, costly at np > 1).
  Teuchos::RCP<const Map> columnMap = kColumns;
  Teuchos::RCP<const Import> importer = K.getGraph()->getImporter();
  if (anyNewColumns) {
    const bool sameColumns = !lastColumnMap_.is_null() && lastDomainMap_ == K.getDomainMap().get() &&
                             columnGids_ == lastColumnGids_;
    if (!anyRank(*rowMap->getComm(), !sameColumns)) {
      columnMap = lastColumnMap_;
      importer = lastImporter_;
    } else {
      columnMap = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                       Teuchos::ArrayView<const GlobalOrdinal>(columnGids_), rowMap->getIndexBase(),
                                       rowMap->getComm()));
      importer = Teuchos::rcp(new Import(K.getDomainMap(), columnMap));
    }
  }
  // A static graph, as the assembler's K: its ghost-row export (ADD) then sums
  // into existing entries when the next K is assembled into this matrix.
  const typename CrsGraph::local_graph_device_type localGraph(indexView, pointerView);
  const auto graph = Teuchos::rcp(new CrsGraph(localGraph, rowMap, columnMap, K.getDomainMap(), K.getRangeMap(),
                                               importer, Teuchos::null));
  last_ = Teuchos::rcp(new CrsMatrix(graph, valueView));
  if (!last_->isFillComplete()) last_->fillComplete(K.getDomainMap(), K.getRangeMap());
  lastColumnGids_ = columnGids_;
  lastColumnMap_ = columnMap;
  lastImporter_ = importer;
  lastDomainMap_ = K.getDomainMap().get();
  return last_;
}

bool MatrixSum::restoreBase() {
  if (last_.is_null()) return false;
  const auto local = last_->getLocalMatrixDevice();
  for (std::size_t i = 0; i < baseRows_.size(); ++i) {
    const auto first = local.graph.row_map(baseRows_[i]), end = local.graph.row_map(baseRows_[i] + 1);
    std::fill(local.values.data() + first, local.values.data() + end, 0.0);
    const LocalOrdinal* columns = local.graph.entries.data();
    for (std::size_t k = baseStart_[i]; k < baseStart_[i + 1]; ++k) {
      const auto [column, value] = baseRowEntries_[k];
      const LocalOrdinal* at = std::lower_bound(columns + first, columns + end, column);
      if (at == columns + end || *at != column) return false;  // not a K + triplets of add(): the caller assembles
      local.values(static_cast<std::size_t>(at - columns)) = value;
    }
  }
  ++restores_;
  return true;
}

bool MatrixSum::grownBeyond(double factor) const {
  return !last_.is_null() &&
         static_cast<double>(last_->getNodeNumEntries()) > static_cast<double>(baseEntryCount_) + factor * static_cast<double>(lastTriplets_);
}

}  // namespace coulomb::linalg
