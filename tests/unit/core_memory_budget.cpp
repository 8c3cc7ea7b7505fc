// The memory check of a mesh before it is read (core/MemoryBudget.hpp):
// the lower bound grows with the mesh and with the ranks on one machine, a
// mesh that fits passes, one that does not is named with both figures, and
// the Exodus reader refuses a damaged or absurd mesh before allocating it.
#include <gtest/gtest.h>

#include <string>

#include "coulomb/core/Error.hpp"
#include "coulomb/core/MemoryBudget.hpp"
#include "coulomb/io/ExodusReader.hpp"

namespace {

coulomb::MemoryBudget budget(double gigabytes, int ranksOnHost = 1, int ranks = 1) {
  coulomb::MemoryBudget b;
  b.availableBytes = static_cast<std::uint64_t>(gigabytes * 1e9);
  b.ranksOnHost = ranksOnHost;
  b.ranks = ranks;
  return b;
}

TEST(MemoryBudget, ThisMachineReportsAvailableMemory) {
  const std::uint64_t available = coulomb::availableMemoryBytes();
  EXPECT_GT(available, 1e8);   // a machine that runs the tests has over 100 MB free
  EXPECT_LT(available, 1e15);  // and less than a petabyte
}

TEST(MemoryBudget, LowerBoundGrowsWithTheMeshAndTheRanksOnOneMachine) {
  using coulomb::meshMemoryLowerBound;
  // 3D, 1e6 nodes: the matrix share alone is 1e6 * 3 * 27 * 3 * 12 bytes.
  const double matrix = 1e6 * 3 * 27 * 3 * 12;
  const double one = static_cast<double>(meshMemoryLowerBound(1000000, 1000000, 3, budget(1)));
  EXPECT_GT(one, matrix);
  EXPECT_LT(one, 1.2 * matrix);  // a lower bound: the mesh itself is small beside the matrix
  // Doubling the mesh doubles the bound.
  EXPECT_NEAR(static_cast<double>(meshMemoryLowerBound(2000000, 2000000, 3, budget(1))), 2 * one, 1e-9 * one);
  // Four ranks on one machine of a four-rank run: the matrix once, the mesh four times.
  const double four = static_cast<double>(meshMemoryLowerBound(1000000, 1000000, 3, budget(1, 4, 4)));
  EXPECT_NEAR(four - one, 3 * (one - matrix), 1e-9 * one);
  // The same four ranks spread over four machines: a quarter of the matrix each.
  const double spread = static_cast<double>(meshMemoryLowerBound(1000000, 1000000, 3, budget(1, 1, 4)));
  EXPECT_NEAR(spread, one - 0.75 * matrix, 1e-9 * one);
  // 2D costs less per node.
  EXPECT_LT(meshMemoryLowerBound(1000000, 1000000, 2, budget(1)), meshMemoryLowerBound(1000000, 1000000, 3, budget(1)));
}

TEST(MemoryBudget, MeshThatDoesNotFitIsNamedWithBothFigures) {
  // A shipped-size mesh fits in 1 GB; two billion nodes do not fit in 24 GB.
  EXPECT_EQ(coulomb::meshMemoryProblem(20000, 18000, 3, budget(1)), "");
  const std::string problem = coulomb::meshMemoryProblem(2000000000, 2, 3, budget(24, 2, 2));
  EXPECT_NE(problem.find("2000000000 nodes and 2 elements need at least"), std::string::npos) << problem;
  EXPECT_NE(problem.find("but 24 GB are available"), std::string::npos) << problem;
  EXPECT_NE(problem.find("each of its 2 ranks holds the whole mesh"), std::string::npos) << problem;
  // Unknown available memory: no check.
  EXPECT_EQ(coulomb::meshMemoryProblem(2000000000, 2, 3, budget(0)), "");
}

TEST(MemoryBudget, BytesAreFormattedForPeople) {
  EXPECT_EQ(coulomb::formatBytes(512), "512 bytes");
  EXPECT_EQ(coulomb::formatBytes(23.4e9), "23.4 GB");
  EXPECT_EQ(coulomb::formatBytes(1.5e6), "1.5 MB");
}

TEST(MemoryBudget, ExodusReaderRefusesAMeshLargerThanTheBudget) {
  const std::string mesh = std::string(COULOMB_SOURCE_DIR) + "/exodus_meshes/block2d.e";
  // With the machine's memory the shipped mesh reads; with 1 kB it is refused
  // before anything is read, the file named.
  EXPECT_NO_THROW(coulomb::io::readExodus(mesh));
  try {
    coulomb::io::readExodus(mesh, budget(1e-6));
    FAIL() << "a 1 kB budget must refuse the mesh";
  } catch (const coulomb::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("block2d.e': "), std::string::npos) << message;
    EXPECT_NE(message.find("but 1 kB are available"), std::string::npos) << message;
  }
}

}  // namespace
