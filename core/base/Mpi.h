#pragma once
// MPI for the libraries that need it (hypre's structured solvers take a
// communicator even in one process). Tephra runs in one process today; MPI is
// initialised lazily, the first time a component asks for a communicator, and
// finalised at exit if Tephra initialised it (an embedding program that called
// MPI_Init itself keeps ownership).
namespace tephra {

// Initialises MPI (MPI_THREAD_FUNNELED) unless MPI_Initialized says it is
// already up; idempotent and cheap after the first call. Registers
// MPI_Finalize with atexit when it did the initialisation.
void ensure_mpi_initialized();

// True after ensure_mpi_initialized() or when the program initialised MPI.
bool mpi_is_initialized();

}  // namespace tephra
