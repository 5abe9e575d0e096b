/* pi as the integral of 4 / (1 + x^2) over [0, 1] by the midpoint rule: each rank sums every
 * size-th interval, MPI_Reduce adds the parts at rank 0, which prints pi and its error.
 *   gcsim-mpicc -o pi pi.c && gcsim mpirun -np 8 ./pi 1000000 */
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const long intervals = argc > 1 ? atol(argv[1]) : 1000000;
  const double h = 1.0 / (double)intervals;
  double part = 0.0;
  for (long i = rank; i < intervals; i += size) {
    const double x = h * ((double)i + 0.5);
    part += 4.0 / (1.0 + x * x);
  }
  part *= h;
  double pi = 0.0;
  MPI_Reduce(&part, &pi, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  if (rank == 0) printf("pi %.12f error %.3e with %ld intervals on %d ranks\n", pi, fabs(pi - 3.14159265358979323846), intervals, size);
  MPI_Finalize();
  return 0;
}
