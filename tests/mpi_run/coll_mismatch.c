/* An erroneous program: the ranks disagree about a collective, in the way argv[1] names. Rank 0
 * calls it right; the others call it differently, after a simulated second of computation (so
 * rank 0's call is always the first to arrive). gcsim mpirun finds the difference when the
 * second call arrives (MPI 3.1 section 5.1) and, under the default MPI_ERRORS_ARE_FATAL, ends the
 * run naming this rank's call and rank 0's, with the class of the difference:
 *   root: MPI_Reduce to root 1 against root 0 (MPI_ERR_ROOT)   op: MPI_MAX against MPI_SUM (MPI_ERR_OP)
 *   count: 2 ints against 1 (MPI_ERR_COUNT)   type: MPI_FLOAT against MPI_INT (MPI_ERR_TYPE)
 *   call: MPI_Bcast against MPI_Reduce (MPI_ERR_OTHER)
 *   gatherv: MPI_Gatherv whose root expects 1 int from each rank but rank 1 sends 2: found by
 *            the size of the block as it arrives at the root (MPI_ERR_TRUNCATE). */
#include <gcsim/mpi_ext.h>
#include <mpi.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const char* kind = argc > 1 ? argv[1] : "root";
  int in[2] = {rank, rank}, out[2] = {0, 0}, all[64];
  float f = 1.0f;
  if (strcmp(kind, "gatherv") == 0) {
    int counts[64], displs[64];
    for (int r = 0; r < size; ++r) counts[r] = 1, displs[r] = r;
    MPI_Gatherv(in, rank == 1 ? 2 : 1, MPI_INT, all, counts, displs, MPI_INT, 0, MPI_COMM_WORLD);
  } else if (rank == 0) {
    MPI_Reduce(in, out, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
  } else {
    gcsim_mpi_compute(1.0);
    if (strcmp(kind, "root") == 0) MPI_Reduce(in, out, 1, MPI_INT, MPI_SUM, 1, MPI_COMM_WORLD);
    if (strcmp(kind, "op") == 0) MPI_Reduce(in, out, 1, MPI_INT, MPI_MAX, 0, MPI_COMM_WORLD);
    if (strcmp(kind, "count") == 0) MPI_Reduce(in, out, 2, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
    if (strcmp(kind, "type") == 0) MPI_Reduce(&f, out, 1, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
    if (strcmp(kind, "call") == 0) MPI_Bcast(in, 1, MPI_INT, 0, MPI_COMM_WORLD);
  }
  printf("rank %d left the collective\n", rank);
  MPI_Finalize();
  return 0;
}
