/* Two ranks that both send first: unsafe by the standard. A message above the eager limit
 * ([mpi] eager_limit_bytes, 16 KiB by default) waits for its matching receive, which neither rank
 * reaches: gcsim reports the deadlock, naming each rank's MPI_Send and its arguments, and exits 5.
 * Below the limit both sends are buffered and the exchange completes.
 *   gcsim-mpicc -o deadlock deadlock.c && gcsim mpirun -np 2 ./deadlock 100000 */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const int count = argc > 1 ? atoi(argv[1]) : 100000;
  char* out = calloc((size_t)count, 1);
  char* in = calloc((size_t)count, 1);
  const int other = 1 - rank;
  MPI_Send(out, count, MPI_CHAR, other, 7, MPI_COMM_WORLD);
  MPI_Recv(in, count, MPI_CHAR, other, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  printf("rank %d exchanged %d bytes\n", rank, count);
  free(out);
  free(in);
  MPI_Finalize();
  return 0;
}
