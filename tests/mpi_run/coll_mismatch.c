/* An erroneous program: rank 0 broadcasts from root 0, the others from root 1. The calls end
 * (each tree completes on its own), so the mismatch shows only as collective messages never
 * received, which gcsim mpirun reports at MPI_Finalize. */
#include <mpi.h>
#include <stdio.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, x = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Bcast(&x, 1, MPI_INT, rank == 0 ? 0 : 1, MPI_COMM_WORLD);
  printf("rank %d left MPI_Bcast\n", rank);
  MPI_Finalize();
  return 0;
}
