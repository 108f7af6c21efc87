// Thread count of the loop helper; omp.h stays out of the header.
#include "core/grid/Loop.h"

#include "core/base/Errors.h"
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace tephra {

void set_thread_count(int n) {
  if (n < 1) throw UsageError("--threads must be >= 1, got " + std::to_string(n));
#ifdef _OPENMP
  omp_set_num_threads(n);
#endif
}

int thread_count() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

}  // namespace tephra
