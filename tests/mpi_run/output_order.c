// What each rank prints, by printf, raw write(2) and stderr, is its own and keeps its order:
// gcsim mpirun prints rank 0's text, then rank 1's ..., each as the rank wrote it (stdout fully
// buffered as on a pipe: a printf not flushed comes after a later raw write).
#include <mpi.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static void raw(int fd, int rank, const char* what) {
  char line[64];
  snprintf(line, sizeof line, "rank %d: %s\n", rank, what);
  if (write(fd, line, strlen(line)) != (ssize_t)strlen(line)) MPI_Abort(MPI_COMM_WORLD, 3);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  printf("rank %d: printf flushed\n", rank);
  fflush(stdout);
  raw(1, rank, "write after it");
  printf("rank %d: printf buffered\n", rank);
  raw(1, rank, "write before the buffered printf");
  fprintf(stderr, "rank %d: stderr\n", rank);
  raw(2, rank, "raw stderr");
  MPI_Barrier(MPI_COMM_WORLD);  // another rank runs: what this one wrote is attributed here
  printf("rank %d: after the barrier\n", rank);
  MPI_Finalize();
  return 0;
}
