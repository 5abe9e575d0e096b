/* Annotated computation: each rank computes rank * 0.25 s (gcsim_mpi_compute), then a barrier; the
 * simulated clock after it is at least the slowest rank's time under --compute annotated, and
 * under --compute none the annotation costs nothing. */
#include <gcsim/mpi_ext.h>
#include <mpi.h>
#include <stdio.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  gcsim_mpi_compute(0.25 * rank);
  MPI_Barrier(MPI_COMM_WORLD);
  const double t = MPI_Wtime();
  if (rank == 0) printf("after the barrier: %s %.2f s\n", t >= 0.25 * (size - 1) ? "at least" : "less than", 0.25 * (size - 1));
  MPI_Finalize();
  return 0;
}
