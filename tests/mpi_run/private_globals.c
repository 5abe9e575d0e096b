/* Privatization: every rank has its own copy of the program's globals (data and bss), as if it
 * were its own process. Each rank writes its rank into both and increments a counter rank + 1
 * times; after a barrier (every other rank has written its own by then) each must still read its
 * own values, and the counters' sum over the ranks is n (n + 1) / 2. Exits 1 otherwise. */
#include <mpi.h>
#include <stdio.h>

static int initialized = -1; /* data */
static int zeroed;           /* bss */
static int counter;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int fresh = initialized == -1 && zeroed == 0 && counter == 0;
  initialized = rank;
  zeroed = 1000 + rank;
  for (int i = 0; i <= rank; ++i) ++counter;
  MPI_Barrier(MPI_COMM_WORLD);
  int own = fresh && initialized == rank && zeroed == 1000 + rank && counter == rank + 1, all_own = 0, sum = 0;
  MPI_Allreduce(&own, &all_own, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
  MPI_Allreduce(&counter, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) printf("private globals on %d ranks: %s, counters sum %d (expected %d)\n", size, all_own ? "each its own" : "SHARED", sum, size * (size + 1) / 2);
  MPI_Finalize();
  return all_own && sum == size * (size + 1) / 2 ? 0 : 1;
}
