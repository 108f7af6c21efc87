// Benchmark (not a test): MPI latency and bandwidth of this machine, the two
// constants of the communication part of the scaling model (docs/scaling.md).
// Run: mpirun --oversubscribe -np 2 build/bin/bench_mpi_pingpong [repeats=2000]
// Rank 0 sends a message of n doubles to rank 1, which sends it back; the
// one-way time is half the round trip, t(n) = alpha + 8 n / beta. Printed:
// one line per size (bytes, one-way time, bandwidth) and the fit alpha
// (smallest message) and beta (largest message), plus the time of an
// MPI_Allreduce of one double (the reductions of a step: stable dt, sums).
// Also CSV lines "csv,bytes,one_way_s,bytes_per_s".
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2) {
    if (rank == 0) std::printf("bench_mpi_pingpong needs mpirun -np 2 (or more; ranks >= 2 idle)\n");
    MPI_Finalize();
    return 1;
  }
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 2000;
  if (rank == 0) std::printf("%12s %14s %16s\n", "bytes", "one-way [s]", "bandwidth [B/s]");
  double alpha = 0, beta = 0;
  for (int n : {1, 16, 128, 1024, 8192, 65536, 524288}) {
    std::vector<double> buf(static_cast<std::size_t>(n), 1.0);
    const int reps = n >= 65536 ? std::max(20, repeats / 50) : repeats;
    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    for (int r = 0; r < reps; ++r) {
      if (rank == 0) {
        MPI_Send(buf.data(), n, MPI_DOUBLE, 1, 7, MPI_COMM_WORLD);
        MPI_Recv(buf.data(), n, MPI_DOUBLE, 1, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      } else if (rank == 1) {
        MPI_Recv(buf.data(), n, MPI_DOUBLE, 0, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(buf.data(), n, MPI_DOUBLE, 0, 7, MPI_COMM_WORLD);
      }
    }
    const double one_way = (MPI_Wtime() - t0) / (2.0 * reps);
    const double bytes = 8.0 * n;
    if (rank == 0) {
      std::printf("%12.0f %14.3e %16.3e\n", bytes, one_way, bytes / one_way);
      std::printf("csv,%.0f,%.4e,%.4e\n", bytes, one_way, bytes / one_way);
    }
    if (n == 1) alpha = one_way;
    if (n == 524288) beta = bytes / (one_way - alpha);
  }
  // One-double allreduce (every rank takes part).
  double v = rank, sum = 0;
  MPI_Barrier(MPI_COMM_WORLD);
  const double t0 = MPI_Wtime();
  for (int r = 0; r < repeats; ++r) MPI_Allreduce(&v, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  const double allreduce = (MPI_Wtime() - t0) / repeats;
  if (rank == 0)
    std::printf("fit: latency alpha = %.3e s, bandwidth beta = %.3e B/s; MPI_Allreduce(1 double) on %d ranks: %.3e s\n",
                alpha, beta, size, allreduce);
  MPI_Finalize();
  return 0;
}
