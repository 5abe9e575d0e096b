/* An erroneous program under the default error handler, MPI_ERRORS_ARE_FATAL (MPI 3.1 section
 * 8.3): the last rank prints a line, then makes the error named by argv[1]; gcsim mpirun must end
 * the run naming the rank, the call, the reason and the class, with the exit status of MPI
 * errors, and still print what the ranks printed before.
 *   send:   MPI_Send to a rank outside MPI_COMM_WORLD
 *   dup:    the same on a duplicate of MPI_COMM_WORLD (which inherits the fatal handler)
 *   type:   MPI_Type_contiguous with a negative count (no communicator: MPI_COMM_WORLD's handler)
 *   return: the same as send on a communicator set to MPI_ERRORS_RETURN: no error ends the run */
#include <mpi.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size, x = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const char* kind = argc > 1 ? argv[1] : "send";
  MPI_Comm comm = MPI_COMM_WORLD;
  if (strcmp(kind, "dup") == 0) MPI_Comm_dup(MPI_COMM_WORLD, &comm);
  if (strcmp(kind, "return") == 0) MPI_Comm_set_errhandler(comm, MPI_ERRORS_RETURN);
  printf("rank %d before the error\n", rank);
  if (rank == size - 1) {
    if (strcmp(kind, "type") == 0) {
      MPI_Datatype t;
      MPI_Type_contiguous(-2, MPI_INT, &t);
    } else {
      const int code = MPI_Send(&x, 1, MPI_INT, size, 0, comm);
      printf("rank %d: MPI_Send returned %d\n", rank, code);
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  printf("rank %d after the error\n", rank);
  MPI_Finalize();
  return 0;
}
