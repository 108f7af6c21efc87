// main() of the MPI test tier: every rank runs every test; only rank 0
// prints (the others' failures still fail the run through the exit code,
// which mpirun propagates). MPI is initialised here, before any test, and
// finalised at exit (core/base/Mpi).
#include <gtest/gtest.h>

#include "core/parallel/Ranks.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const tephra::Ranks r = tephra::world_ranks();
  if (!r.is_root()) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
