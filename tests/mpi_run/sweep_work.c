/* A program whose work divides among the ranks, for gcsim sweep mpi: WORK seconds of annotated
 * computation (gcsim_mpi_compute) shared equally over ITERATIONS steps, each step ending with a
 * ring exchange (MPI_Sendrecv of 1 KiB with both neighbours) and an MPI_Allreduce of the step's sum. */
#include <gcsim/mpi_ext.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const double work = argc > 1 ? atof(argv[1]) : 1.0;
  const int iterations = argc > 2 ? atoi(argv[2]) : 10;
  double halo[128], got[128], total = 0;
  for (int i = 0; i < 128; ++i) halo[i] = rank + i;
  const int right = (rank + 1) % size, left = (rank + size - 1) % size;
  for (int k = 0; k < iterations; ++k) {
    gcsim_mpi_compute(work / iterations / size);
    MPI_Sendrecv(halo, 128, MPI_DOUBLE, right, 0, got, 128, MPI_DOUBLE, left, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    double mine = got[0], sum = 0;
    MPI_Allreduce(&mine, &sum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    total += sum;
  }
  if (rank == 0) printf("sweep_work %d ranks total %.1f\n", size, total);
  MPI_Finalize();
  return 0;
}
