#include "coulomb/linalg/TripletAssembly.hpp"

#include <algorithm>
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

namespace {

/// Sends record r (`width` doubles each, row GID first) to the owner of its
/// row; returns the records this rank owns (its own included).
std::vector<double> toOwners(const std::vector<double>& records, int width, const Map& map) {
  const auto& comm = *map.getComm();
  const int size = comm.getSize();
  const std::size_t n = records.size() / width;
  if (size == 1) return records;  // one rank owns every row (rows come from the DoF map)
  // The owner of each distinct row, looked up once (Tpetra's directory is
  // given a sorted list without duplicates). One extra, valid index on every
  // rank: Map::getRemoteIndexList returns at once for an empty list, skipping
  // the collective set-up of its directory that the ranks with entries do —
  // a rank without contributions would then desynchronise the others.
  // Rows this rank owns (most of them: contributions are emitted by the
  // owner of the slave node) need no lookup.
  const int rank = comm.getRank();
  auto ownedHere = [&](GlobalOrdinal row) { return map.getLocalElement(row) != Teuchos::OrdinalTraits<LocalOrdinal>::invalid(); };
  std::vector<GlobalOrdinal> distinct;
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<GlobalOrdinal>(records[i * width]);
    if (!ownedHere(row)) distinct.push_back(row);
  }
  distinct.push_back(map.getMinAllGlobalIndex());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<int> distinctOwners(distinct.size(), -1);
  std::vector<LocalOrdinal> locals(distinct.size());
  map.getRemoteIndexList(Teuchos::ArrayView<const GlobalOrdinal>(distinct.data(), distinct.size()),
                         Teuchos::ArrayView<int>(distinctOwners.data(), distinct.size()),
                         Teuchos::ArrayView<LocalOrdinal>(locals.data(), distinct.size()));
  std::vector<int> owners(n);
  std::string failure;
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<GlobalOrdinal>(records[i * width]);
    if (ownedHere(row)) {
      owners[i] = rank;
      continue;
    }
    owners[i] = distinctOwners[std::lower_bound(distinct.begin(), distinct.end(), row) - distinct.begin()];
    if ((owners[i] < 0 || owners[i] >= size) && failure.empty())
      failure = "internal: contribution to row " + std::to_string(row) + " outside the DoF map";
  }
  throwIfAnyRankFailed(comm, failure);

  std::vector<std::vector<double>> send(static_cast<std::size_t>(size));
  for (std::size_t i = 0; i < n; ++i)
    send[owners[i]].insert(send[owners[i]].end(), records.begin() + i * width, records.begin() + (i + 1) * width);
  return exchangeByRank(comm, std::move(send));
}

/// The triplets of every rank whose row this rank owns, as (row, column,
/// value) records of doubles (global indices are exact below 2^53).
std::vector<double> tripletsToOwners(const std::vector<MatrixTriplet>& triplets, const Map& map) {
  std::vector<double> records;
  records.reserve(triplets.size() * 3);
  for (const auto& t : triplets) {
    records.push_back(static_cast<double>(t.row));
    records.push_back(static_cast<double>(t.column));
    records.push_back(t.value);
  }
  return toOwners(records, 3, map);
}

}  // namespace

Teuchos::RCP<CrsMatrix> matrixFromTriplets(const std::vector<MatrixTriplet>& triplets,
                                           const Teuchos::RCP<const Map>& map) {
  const auto mine = tripletsToOwners(triplets, *map);
  std::map<GlobalOrdinal, std::map<GlobalOrdinal, double>> rows;
  for (std::size_t i = 0; i < mine.size(); i += 3)
    rows[static_cast<GlobalOrdinal>(mine[i])][static_cast<GlobalOrdinal>(mine[i + 1])] += mine[i + 2];

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

void addEntries(const std::vector<VectorEntry>& entries, Vector& owned) {
  std::vector<double> records;
  records.reserve(entries.size() * 2);
  for (const auto& e : entries) {
    records.push_back(static_cast<double>(e.row));
    records.push_back(e.value);
  }
  const auto mine = toOwners(records, 2, *owned.getMap());
  const auto& map = *owned.getMap();
  auto data = owned.getDataNonConst(0);
  for (std::size_t i = 0; i < mine.size(); i += 2)
    data[map.getLocalElement(static_cast<GlobalOrdinal>(mine[i]))] += mine[i + 1];
}

Teuchos::RCP<CrsMatrix> addTriplets(const CrsMatrix& K, const std::vector<MatrixTriplet>& triplets) {
  MatrixSum sum;
  return sum.add(K, triplets);
}

Teuchos::RCP<CrsMatrix> MatrixSum::add(const CrsMatrix& K, const std::vector<MatrixTriplet>& triplets) {
  const auto rowMap = K.getRowMap();
  const auto mine = tripletsToOwners(triplets, *rowMap);
  lastTriplets_ = mine.size() / 3;
  if (last_.get() != &K) baseEntries_ = K.getNodeNumEntries();

  // Column map: K's, then the columns only the triplets have (in order of appearance).
  const auto kColumns = K.getColMap();
  columnGids_.assign(kColumns->getNodeElementList().begin(), kColumns->getNodeElementList().end());
  const std::size_t kColumnCount = columnGids_.size();
  std::unordered_map<GlobalOrdinal, LocalOrdinal> extra;
  const std::size_t n = mine.size() / 3;
  std::vector<LocalOrdinal> localRow(n), localColumn(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<GlobalOrdinal>(mine[3 * i]);
    const auto column = static_cast<GlobalOrdinal>(mine[3 * i + 1]);
    localRow[i] = rowMap->getLocalElement(row);
    LocalOrdinal c = kColumns->getLocalElement(column);
    if (c == Teuchos::OrdinalTraits<LocalOrdinal>::invalid()) {
      const auto it = extra.find(column);
      if (it != extra.end()) {
        c = it->second;
      } else {
        c = static_cast<LocalOrdinal>(columnGids_.size());
        columnGids_.push_back(column);
        extra.emplace(column, c);
      }
    }
    localColumn[i] = c;
  }
  // Triplets grouped by local row (counting sort).
  const std::size_t numRows = rowMap->getNodeNumElements();
  std::vector<std::size_t> start(numRows + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++start[localRow[i] + 1];
  for (std::size_t r = 0; r < numRows; ++r) start[r + 1] += start[r];
  std::vector<std::size_t> order(n), cursor(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order[cursor[localRow[i]]++] = i;

  // K's compressed rows, read directly (Serial node: the device view is host memory).
  const auto localK = K.getLocalMatrixDevice();
  const auto kRows = localK.graph.row_map;
  const auto kEntries = localK.graph.entries;
  const auto kValues = localK.values;
  // Row r of K + S: K's entries with the triplets of the row added (a binary
  // search finds an existing column; new ones, duplicates summed, are merged
  // in), sorted by local column as K's rows are.
  std::vector<std::pair<LocalOrdinal, double>> added, merged;
  auto mergeRow = [&](std::size_t r) {
    merged.clear();
    for (auto k = kRows(r); k < kRows(r + 1); ++k) merged.push_back({kEntries(k), kValues(k)});
    const std::size_t kCount = merged.size();
    added.clear();
    for (std::size_t k = start[r]; k < start[r + 1]; ++k) added.push_back({localColumn[order[k]], mine[3 * order[k] + 2]});
    std::sort(added.begin(), added.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < added.size();) {
      const LocalOrdinal c = added[k].first;
      double v = 0;
      for (; k < added.size() && added[k].first == c; ++k) v += added[k].second;
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

bool MatrixSum::grownBeyond(double factor) const {
  return !last_.is_null() &&
         static_cast<double>(last_->getNodeNumEntries()) > static_cast<double>(baseEntries_) + factor * static_cast<double>(lastTriplets_);
}

}  // namespace coulomb::linalg
