// TripletAssembly: contributions from any rank end up, summed, on the row owner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "TestSupport.hpp"
#include "coulomb/linalg/TripletAssembly.hpp"

namespace coulomb::test {

TEST(TripletAssembly, EveryRankAddsToEveryRowAndTheOwnerHoldsTheSum) {
  auto comm = worldComm();
  const int size = comm->getSize(), rank = comm->getRank();
  const GlobalOrdinal n = 7 * size + 3;  // rows spread unevenly
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  // Every rank adds (rank + 1) to A(i, i) and 1 to A(i, (i + 1) % n), and 2 to v(i).
  std::vector<linalg::MatrixTriplet> triplets;
  std::vector<linalg::VectorEntry> entries;
  for (GlobalOrdinal i = 0; i < n; ++i) {
    triplets.push_back({i, i, double(rank + 1)});
    triplets.push_back({i, (i + 1) % n, 1.0});
    entries.push_back({i, 2.0});
  }
  auto matrix = linalg::matrixFromTriplets(triplets, map);
  Vector v(map);
  linalg::addEntries(entries, v);
  const double diagonal = size * (size + 1) / 2.0;
  // A x with x = 1 gives diagonal + size on every row.
  Vector ones(map), product(map);
  ones.putScalar(1.0);
  matrix->apply(ones, product);
  const auto p = product.getData(0);
  const auto values = v.getData(0);
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    EXPECT_DOUBLE_EQ(p[i], diagonal + size);
    EXPECT_DOUBLE_EQ(values[i], 2.0 * size);
  }
  EXPECT_EQ(matrix->getGlobalNumEntries(), static_cast<Tpetra::global_size_t>(2 * n));
}

TEST(TripletAssembly, NoContributionsGiveAnEmptyMatrix) {
  auto comm = worldComm();
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(5), 0, comm));
  auto matrix = linalg::matrixFromTriplets({}, map);
  EXPECT_EQ(matrix->getGlobalNumEntries(), 0u);
}

}  // namespace coulomb::test

namespace coulomb::test {

// Regression: a rank without contributions must not desynchronise the others
// (Tpetra's owner lookup skips a collective set-up for an empty list).
TEST(TripletAssembly, OnlyOneRankContributes) {
  auto comm = worldComm();
  const int size = comm->getSize();
  const GlobalOrdinal n = 4 * size;
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  for (int repeat = 0; repeat < 2; ++repeat) {
    std::vector<linalg::MatrixTriplet> triplets;
    std::vector<linalg::VectorEntry> entries;
    if (comm->getRank() == size - 1)
      for (GlobalOrdinal i = 0; i < n; ++i) {
        triplets.push_back({i, n - 1 - i, 3.0});
        entries.push_back({i, 1.5});
      }
    auto matrix = linalg::matrixFromTriplets(triplets, map);
    Vector v(map);
    linalg::addEntries(entries, v);
    EXPECT_EQ(matrix->getGlobalNumEntries(), static_cast<Tpetra::global_size_t>(n));
    EXPECT_DOUBLE_EQ(v.norm1(), 1.5 * n);
  }
}

}  // namespace coulomb::test

namespace coulomb::test {

// addTriplets: K + S with S adding entries inside and outside K's pattern,
// from one rank only (the column map then changes on some ranks only).
TEST(TripletAssembly, AddTripletsEqualsTheSumAppliedToAVector) {
  auto comm = worldComm();
  const int size = comm->getSize();
  const GlobalOrdinal n = 5 * size + 2;
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  std::vector<linalg::MatrixTriplet> k;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(static_cast<LocalOrdinal>(i));
    k.push_back({g, g, 4.0});
    if (g > 0) k.push_back({g, g - 1, -1.0});
    if (g + 1 < n) k.push_back({g, g + 1, -1.0});
  }
  auto K = linalg::matrixFromTriplets(k, map);
  std::vector<linalg::MatrixTriplet> s;
  if (comm->getRank() == 0)
    for (GlobalOrdinal g = 0; g < n; ++g) {
      s.push_back({g, g, 0.5});                      // inside K's pattern
      s.push_back({g, (g + n / 2) % n, 0.25});       // mostly outside it
      s.push_back({g, (g + n / 2) % n, 0.25});       // duplicate: summed
    }
  auto sum = linalg::addTriplets(*K, s);
  auto S = linalg::matrixFromTriplets(s, map);
  Vector x(map), expected(map), actual(map), part(map);
  auto data = x.getDataNonConst(0);
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    data[i] = std::sin(1.0 + static_cast<double>(map->getGlobalElement(static_cast<LocalOrdinal>(i))));
  K->apply(x, expected);
  S->apply(x, part);
  expected.update(1.0, part, 1.0);
  sum->apply(x, actual);
  actual.update(-1.0, expected, 1.0);
  EXPECT_LT(actual.normInf(), 1e-14);
  // Rows stay sorted by local column (the smoothers' requirement).
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    Teuchos::ArrayView<const LocalOrdinal> indices;
    Teuchos::ArrayView<const double> values;
    sum->getLocalRowView(static_cast<LocalOrdinal>(i), indices, values);
    EXPECT_TRUE(std::is_sorted(indices.begin(), indices.end()));
  }
}

namespace {

/// The owned rows of a lower bidiagonal K: 3 on the diagonal, -1 left of it.
std::vector<linalg::MatrixTriplet> bidiagonal(const Map& map) {
  std::vector<linalg::MatrixTriplet> k;
  for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map.getGlobalElement(static_cast<LocalOrdinal>(i));
    k.push_back({g, g, 3.0});
    if (g > 0) k.push_back({g, g - 1, -1.0});
  }
  return k;
}

/// x(g) = cos(phase + g) on the owned rows.
Vector cosineVector(const Teuchos::RCP<const Map>& map, double phase) {
  Vector x(map);
  auto data = x.getDataNonConst(0);
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
    data[i] = std::cos(phase + static_cast<double>(map->getGlobalElement(static_cast<LocalOrdinal>(i))));
  return x;
}

/// |sum x - (K + S) x|_inf, S the matrix of the triplets `s`.
double sumError(const CrsMatrix& K, const std::vector<linalg::MatrixTriplet>& s, const CrsMatrix& sum, const Vector& x) {
  const auto map = K.getRowMap();
  Vector expected(map), part(map), actual(map);
  K.apply(x, expected);
  linalg::matrixFromTriplets(s, map)->apply(x, part);
  expected.update(1.0, part, 1.0);
  sum.apply(x, actual);
  actual.update(-1.0, expected, 1.0);
  return actual.normInf();
}

/// From the last rank only: (g, (g + shift) mod n, scale (g + 1)) for every row g.
std::vector<linalg::MatrixTriplet> shiftedFromLastRank(const Map& map, double scale, GlobalOrdinal shift) {
  std::vector<linalg::MatrixTriplet> s;
  const auto n = static_cast<GlobalOrdinal>(map.getGlobalNumElements());
  if (map.getComm()->getRank() == map.getComm()->getSize() - 1)
    for (GlobalOrdinal g = 0; g < n; ++g) s.push_back({g, (g + shift) % n, scale * static_cast<double>(g + 1)});
  return s;
}

}  // namespace

// MatrixSum: a second sum with the same pattern reuses the first result's
// matrix with the new values; a different pattern builds a new one. Both
// equal K + S applied to a vector.
TEST(TripletAssembly, MatrixSumReusesTheMatrixWhenThePatternRepeats) {
  auto comm = worldComm();
  const GlobalOrdinal n = 4 * comm->getSize() + 3;
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  auto K = linalg::matrixFromTriplets(bidiagonal(*map), map);
  auto triplets = [&](double scale, GlobalOrdinal shift) { return shiftedFromLastRank(*map, scale, shift); };
  const Vector x = cosineVector(map, 0.3);
  auto expectSum = [&](const Teuchos::RCP<CrsMatrix>& sum, const std::vector<linalg::MatrixTriplet>& s) {
    EXPECT_LT(sumError(*K, s, *sum, x), 1e-13);
  };
  linalg::MatrixSum sum;
  const auto s1 = triplets(1.0, n / 2), s2 = triplets(-2.0, n / 2), s3 = triplets(1.0, 1);
  auto first = sum.add(*K, s1);
  expectSum(first, s1);
  auto second = sum.add(*K, s2);  // same pattern, new values: the same matrix
  EXPECT_EQ(second.get(), first.get());
  EXPECT_EQ(sum.reuses(), 1);
  expectSum(second, s2);
  auto third = sum.add(*K, s3);  // another pattern: a new matrix
  EXPECT_NE(third.get(), first.get());
  EXPECT_EQ(sum.reuses(), 1);
  expectSum(third, s3);
  // Triplets only in K's own columns: K's pattern. Moving them to other
  // columns of K keeps that pattern (reused, rows without triplets now
  // included), and the values follow.
  std::vector<linalg::MatrixTriplet> diagonal, lower;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(static_cast<LocalOrdinal>(i));
    diagonal.push_back({g, g, 0.5 * static_cast<double>(g)});
    if (g > 0 && g % 2 == 0) lower.push_back({g, g - 1, 2.0});
  }
  auto fourth = sum.add(*K, diagonal);
  EXPECT_NE(fourth.get(), third.get());
  expectSum(fourth, diagonal);
  auto fifth = sum.add(*K, lower);
  EXPECT_EQ(fifth.get(), fourth.get());
  EXPECT_EQ(sum.reuses(), 2);
  expectSum(fifth, lower);
  // More entries than the memory held so far (K's pattern + 2 %): it grows.
  std::vector<linalg::MatrixTriplet> dense;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(static_cast<LocalOrdinal>(i));
    for (GlobalOrdinal c = 0; c < n; c += 2) dense.push_back({g, c, 0.1 * static_cast<double>(g + c)});
  }
  auto sixth = sum.add(*K, dense);
  expectSum(sixth, dense);
  auto seventh = sum.add(*K, s1);  // and fits again afterwards
  expectSum(seventh, s1);
  // The same columns as s1 on every rank, more entries per row: a new
  // pattern that keeps the column map and importer of the last result.
  std::vector<linalg::MatrixTriplet> sameColumns;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(static_cast<LocalOrdinal>(i));
    for (std::size_t j = 0; j < map->getNodeNumElements(); ++j) {
      const GlobalOrdinal h = map->getGlobalElement(static_cast<LocalOrdinal>(j));
      sameColumns.push_back({g, (h + n / 2) % n, 0.01 * static_cast<double>(g + 2 * h + 1)});
    }
  }
  auto eighth = sum.add(*K, sameColumns);
  EXPECT_EQ(eighth->getColMap().get(), seventh->getColMap().get());
  expectSum(eighth, sameColumns);
}

// MatrixSum leaves out what cannot change a product with the sum: exact
// zeros and values at most 1e-14 of their row's largest K entry (the
// interface rows of a contact tangent carry many; each one in a new column
// grew the pattern, and at np > 1 the column map). The pattern then repeats
// and the matrix is reused; a small but resolvable value (1e-6 of the row)
// still enters.
TEST(TripletAssembly, MatrixSumLeavesOutNegligibleNewEntries) {
  auto comm = worldComm();
  const GlobalOrdinal n = 4 * comm->getSize() + 3;
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  auto K = linalg::matrixFromTriplets(bidiagonal(*map), map);  // rows' largest entry: 3
  const Vector x = cosineVector(map, 0.7);
  linalg::MatrixSum sum;
  const auto s1 = shiftedFromLastRank(*map, 1.0, n / 2);
  auto first = sum.add(*K, s1);
  const auto entries = first->getGlobalNumEntries();
  // s1's values again, plus zeros and 1e-20 x 3 in yet other columns.
  auto withNegligible = [&](double tiny) {
    std::vector<linalg::MatrixTriplet> s = s1;
    for (const auto& t : shiftedFromLastRank(*map, 0.0, n / 2 + 1)) s.push_back(t);
    for (auto t : shiftedFromLastRank(*map, 1.0, n / 2 + 2)) {
      t.value = tiny * 3.0;
      s.push_back(t);
    }
    return s;
  };
  const auto s2 = withNegligible(1e-20);
  auto second = sum.add(*K, s2);
  EXPECT_EQ(second.get(), first.get());
  EXPECT_EQ(sum.reuses(), 1);
  EXPECT_EQ(second->getGlobalNumEntries(), entries);
  EXPECT_LT(sumError(*K, s2, *second, x), 1e-13);
  // 1e-6 of the row is kept: one new entry per row (the zeros still left out).
  const auto s3 = withNegligible(1e-6);
  auto third = sum.add(*K, s3);
  EXPECT_EQ(sum.reuses(), 1);
  EXPECT_EQ(third->getGlobalNumEntries(), entries + static_cast<Tpetra::global_size_t>(n));
  EXPECT_LT(sumError(*K, s3, *third, x), 1e-13);
  // The bound is each row's own: with K's rows at 3e-6 and 3e6 (even and odd
  // rows), 1e-10 in a new column is kept in the small rows (3e-5 of them)
  // and left out in the large ones (3e-17); a bound relative to the whole
  // matrix (or none) would keep none (all) of them.
  std::vector<linalg::MatrixTriplet> scaled;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(static_cast<LocalOrdinal>(i));
    scaled.push_back({g, g, g % 2 == 0 ? 3e-6 : 3e6});
  }
  const auto scaledK = linalg::matrixFromTriplets(scaled, map);
  auto small = shiftedFromLastRank(*map, 1.0, n / 2);
  for (auto& t : small) t.value = 1e-10;
  linalg::MatrixSum other;
  const auto withSmall = other.add(*scaledK, small);
  EXPECT_EQ(withSmall->getGlobalNumEntries(), static_cast<Tpetra::global_size_t>(n + (n + 1) / 2));
}

// MatrixSum with K = its last result, refilled by the caller (the model
// evaluator assembles the next K into the last J): the same pattern is
// completed in the same matrix; a grown one (new entries, new columns at np >
// 1) is merged in place from the last row backwards; more entries than the
// buffers hold go to new buffers. Every result equals K' + S on a vector.
TEST(TripletAssembly, MatrixSumCompletesTheLastResultInPlace) {
  auto comm = worldComm();
  // 100 rows per rank: the buffers' 2 % room holds a few new entries per rank.
  const GlobalOrdinal n = 100 * comm->getSize() + 3;
  auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), 0, comm));
  const auto k = bidiagonal(*map);
  auto K = linalg::matrixFromTriplets(k, map);
  const Vector x = cosineVector(map, 0.7);
  // J := factor K, every other entry of J zero (what the assembler does).
  auto refill = [&](CrsMatrix& J, double factor) {
    J.resumeFill();
    J.setAllToScalar(0.0);
    for (const auto& t : k) {
      const double value = factor * t.value;
      J.sumIntoGlobalValues(t.row, Teuchos::ArrayView<const GlobalOrdinal>(&t.column, 1),
                            Teuchos::ArrayView<const double>(&value, 1));
    }
    J.fillComplete(K->getDomainMap(), K->getRangeMap());
  };
  auto expectSum = [&](const Teuchos::RCP<CrsMatrix>& sum, double factor, const std::vector<linalg::MatrixTriplet>& s) {
    Vector expected(map), part(map), actual(map);
    K->apply(x, expected);
    expected.scale(factor);
    linalg::matrixFromTriplets(s, map)->apply(x, part);
    expected.update(1.0, part, 1.0);
    sum->apply(x, actual);
    actual.update(-1.0, expected, 1.0);
    EXPECT_LT(actual.normInf(), 1e-14 * 3.0 * static_cast<double>(n));  // round-off: entries up to 3 n, |x| <= 1
  };
  linalg::MatrixSum sum;
  const auto s1 = shiftedFromLastRank(*map, 1.0, n / 2), s2 = shiftedFromLastRank(*map, -3.0, n / 2);
  // Two new entries in each rank's first two rows, at a column 25 left of
  // s1's (from np = 3 a column this rank's J does not have yet: a new column
  // map); they fit in the buffers' 2 % room.
  std::vector<linalg::MatrixTriplet> s3;
  for (LocalOrdinal i = 0; i < 2; ++i) {
    const GlobalOrdinal g = map->getGlobalElement(i);
    s3.push_back({g, (g + n / 2 - 25 + n) % n, 0.5 * static_cast<double>(g + 1)});
  }
  auto J = sum.add(*K, s1);
  expectSum(J, 1.0, s1);
  EXPECT_FALSE(sum.grownBeyond(2.0));  // made from K apart: only s1's entries beyond K's
  refill(*J, 2.0);
  auto same = sum.add(*J, s2);  // the same pattern: completed in the same matrix
  EXPECT_EQ(same.get(), J.get());
  expectSum(same, 2.0, s2);
  // restoreBase: the result turned back into the K given (2 K), then completed again.
  ASSERT_TRUE(sum.restoreBase());
  expectSum(same, 2.0, {});
  EXPECT_EQ(sum.add(*same, s2).get(), same.get());
  expectSum(same, 2.0, s2);
  refill(*same, -1.0);
  const auto entriesBefore = same->getGlobalNumEntries();
  auto grown = sum.add(*same, s3);  // s1's entries stay (zero), s3's are merged in
  EXPECT_EQ(sum.last().get(), grown.get());
  EXPECT_EQ(sum.inPlaceMerges(), 1);
  expectSum(grown, -1.0, s3);
  {  // after an in-place merge; s1's rows (triplets two calls ago) are K's already
    ASSERT_TRUE(sum.restoreBase());
    expectSum(grown, -1.0, {});
    EXPECT_EQ(sum.add(*grown, s3).get(), grown.get());
    expectSum(grown, -1.0, s3);
  }
  // s1's couplings stay as zeros: ~n / p entries beyond K's for 2 triplets.
  EXPECT_TRUE(sum.grownBeyond(2.0));
  EXPECT_EQ(grown->getGlobalNumEntries(), entriesBefore + 2 * static_cast<Tpetra::global_size_t>(comm->getSize()));
  refill(*grown, 4.0);
  std::vector<linalg::MatrixTriplet> dense;  // more than the buffers hold
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GlobalOrdinal g = map->getGlobalElement(static_cast<LocalOrdinal>(i));
    for (GlobalOrdinal c = 0; c < n; c += 2) dense.push_back({g, c, 0.1 * static_cast<double>(g + c)});
  }
  auto fresh = sum.add(*grown, dense);
  expectSum(fresh, 4.0, dense);
  ASSERT_TRUE(sum.restoreBase());  // new buffers and columns: K's local columns still lead
  expectSum(fresh, 4.0, {});
  EXPECT_EQ(sum.restores(), 3);
  fresh = sum.add(*fresh, dense);
  expectSum(fresh, 4.0, dense);
  refill(*fresh, 1.0);
  expectSum(sum.add(*fresh, {}), 1.0, {});  // no triplets: the refilled K itself
}

}  // namespace coulomb::test
