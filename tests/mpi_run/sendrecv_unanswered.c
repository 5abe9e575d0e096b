/* Rank 0's MPI_Sendrecv waits for a letter rank 1 never sends (rank 1 waits in MPI_Recv for a tag
 * rank 0 never sends): the deadlock report names both halves of rank 0's call, the eager send
 * complete and without a request, and rank 1's receive. */
#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, sent = 1, got = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) MPI_Sendrecv(&sent, 1, MPI_INT, 1, 3, &got, 1, MPI_INT, 1, 4, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  else MPI_Recv(&got, 1, MPI_INT, 0, 5, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Finalize();
  return 0;
}
