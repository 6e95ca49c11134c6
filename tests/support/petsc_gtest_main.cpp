// GoogleTest main for tests that run under mpiexec: PETSc is initialised once,
// only rank 0 prints, and a test fails when it fails on any rank.
#include <gtest/gtest.h>
#include <slepcsys.h>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, nullptr));
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS();
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  PetscCall(SlepcFinalize());
  return any;
}
