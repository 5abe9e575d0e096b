/* Calls MPI functions that gcsim's mpi.h does not declare (one-sided communication): C compiles
 * them as implicit declarations, so the program still names MPI_Win_create and MPI_Win_free. gcsim
 * mpirun must refuse to load it, naming both, instead of binding them to another MPI library's
 * functions in its own process. */
#include <mpi.h>
#include <stdio.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int window = 0, value = 0;
  if (argc > 99) { /* never taken: the calls only have to be in the program */
    MPI_Win_create(&value, sizeof value, sizeof value, 0, MPI_COMM_WORLD, &window);
    MPI_Win_free(&window);
  }
  printf("not reached: the program must not be loaded\n");
  MPI_Finalize();
  return 0;
}
