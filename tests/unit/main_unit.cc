// GoogleTest main: MPI and Kokkos are initialised (and finalised after every
// Tpetra object is gone) by Tpetra's ScopeGuard; gtest output only on rank 0.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

int main(int argc, char** argv) {
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (Tpetra::getDefaultComm()->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
