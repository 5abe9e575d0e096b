/* Rank 1 recurses far deeper than its stack allows; gcsim must say that rank 1 overflowed its
 * stack and exit 70, not crash with a bare segmentation fault. */
#include <mpi.h>
#include <stdio.h>
#include <string.h>

static int deep(int n) {
  volatile char frame[1024];
  memset((char*)frame, n, sizeof frame);
  return n == 0 ? frame[0] : deep(n - 1) + frame[n % 1024];
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 1) printf("%d\n", deep(1 << 20));
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  return 0;
}
