// Interface Distribution = Balanced (InterfaceBalance.hpp): the slave faces
// a rank integrates are a weighted partition of the whole slave surface.
// Checked on the shipped Hertz 3D mesh (a sphere on a block; the faces near
// the contact zone have candidates, the rest of the cap none) at
// np = 1, 2, 3: every slave face lands on exactly one rank, and the ranks'
// work (one per face plus one per candidate master face) is within the
// partitioner's tolerance of the mean. The pair-level check, that the same
// deck gives the same answer whichever rank integrates a face, is in
// contact_self_mpi.cpp (a self-contact surface redistributed).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <numeric>

#include <Teuchos_CommHelpers.hpp>

#include "TestSupport.hpp"
#include "coulomb/contact/interface/ContactInterface.hpp"
#include "coulomb/contact/interface/ContactSearch.hpp"
#include "coulomb/contact/interface/InterfaceBalance.hpp"
#include "coulomb/io/ExodusReader.hpp"
#include "coulomb/mesh/Mesh.hpp"

namespace coulomb::test {
namespace {

using contact::ContactInterface;

/// Sum over the ranks of `value`, and its largest share.
std::pair<double, double> sumAndMax(const Teuchos::Comm<int>& comm, double value) {
  double sum = 0, max = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, value, Teuchos::outArg(sum));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, value, Teuchos::outArg(max));
  return {sum, max};
}

TEST(InterfaceBalance, EveryFaceOnOneRankAndTheWorkEvenlySpread) {
  auto global = std::make_shared<const mesh::GlobalMesh>(io::readExodus(shippedMesh("hertz3d.e")));
  const mesh::Mesh mesh(global, worldComm());
  const ContactInterface contact(mesh, "slave", "master");
  const auto& comm = *contact.comm();
  // The sphere pressed 0.05 into the block: faces near the pole have
  // candidates, the rest of the cap none.
  contact::InterfaceConfiguration x = contact::referenceConfiguration(contact);
  const auto& slaveNodes = contact.slaveNodes();
  for (long long node : slaveNodes) x.x[contact.interfaceNodeIndex(node) * 3 + 2] -= 0.05;
  const double radius = contact::defaultSearchRadius(contact, x, 1.0);
  const auto& owned = contact.ownedSlaveFaces();
  const auto byElements = contact::searchContactPairs(contact, x, radius, owned);
  const std::vector<int> balanced = contact::balancedSlaveFaces(contact, owned, byElements);
  const auto searched = contact::searchContactPairs(contact, x, radius, balanced);

  // Every face exactly once over the ranks.
  const int numFaces = static_cast<int>(contact.slaveFaces().size());
  std::vector<int> local(numFaces, 0), count(numFaces, 0);
  for (int k : balanced) ++local[k];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, numFaces, local.data(), count.data());
  for (int k = 0; k < numFaces; ++k) ASSERT_EQ(count[k], 1) << "slave face " << k;
  EXPECT_TRUE(std::is_sorted(balanced.begin(), balanced.end()));

  auto work = [](const contact::SearchResult& s) {
    double w = 0;
    for (const auto& c : s.candidates) w += 1.0 + static_cast<double>(c.size());
    return w;
  };
  const auto [total, maxBalanced] = sumAndMax(comm, work(searched));
  const auto [totalByElements, maxByElements] = sumAndMax(comm, work(byElements));
  EXPECT_EQ(total, totalByElements) << "the same pairs, wherever they are searched";
  const double mean = total / comm.getSize();
  // Zoltan2's imbalance tolerance is 1.05; a face's weight (at most a few
  // candidates in a total of thousands) adds little to it.
  EXPECT_LE(maxBalanced, 1.08 * mean);
  if (comm.getRank() == 0)
    std::cout << "slave faces " << numFaces << ", work " << total << ", largest share over the mean: by elements "
              << maxByElements / mean << ", balanced " << maxBalanced / mean << "\n";
}

}  // namespace
}  // namespace coulomb::test
