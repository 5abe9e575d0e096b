/* A program that leaves work behind at MPI_Finalize: rank 0 sends a message (tag 5) that rank 1
 * never receives, and rank 1 posts a receive (tag 9) that nothing matches. Both are legal to
 * start, so the run ends normally; gcsim mpirun warns of each with its origin. */
#include <mpi.h>
#include <stdio.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, x = 42, y = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Request r;
  if (rank == 0) MPI_Send(&x, 1, MPI_INT, 1, 5, MPI_COMM_WORLD);
  if (rank == 1) MPI_Irecv(&y, 1, MPI_INT, 0, 9, MPI_COMM_WORLD, &r);
  printf("rank %d done\n", rank);
  MPI_Finalize();
  return 0;
}
