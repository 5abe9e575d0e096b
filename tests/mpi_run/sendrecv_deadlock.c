/* Two ranks whose MPI_Sendrecv wait for a tag the other never sends: the eager send of each is
 * complete (it makes no request), and the deadlock report still names both halves of the call. */
#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, sent = 1, got = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Sendrecv(&sent, 1, MPI_INT, 1 - rank, 3, &got, 1, MPI_INT, 1 - rank, 4, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Finalize();
  return 0;
}
