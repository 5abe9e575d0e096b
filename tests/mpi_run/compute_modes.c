/* Every kind of computation a program can ask gcsim to charge: annotated seconds and flops, a
 * sampled loop, and a busy loop between calls that only --compute measured charges; with a ring
 * exchange so a trace has messages. Prints what it computed (the same under every mode) and, on
 * rank 0, the simulated time: under none it is the same on every rerun, and under annotated too
 * when run with the argument `nosample` (sampled bodies are timed on the host). */
#include <gcsim/mpi_ext.h>
#include <mpi.h>
#include <stdio.h>
#include <string.h>

static double chain(long n) {
  double x = 1.0;
  for (long i = 0; i < n; ++i) x = x * 1.0000001 + 1e-9;
  return x;
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  gcsim_mpi_compute(0.001 * (rank + 1));
  gcsim_mpi_compute_flops(1e5 * (rank + 1));
  double x = chain(2000000);  /* charged only when measured */
  int token = rank, got = -1;
  MPI_Sendrecv(&token, 1, MPI_INT, (rank + 1) % size, 0, &got, 1, MPI_INT, (rank + size - 1) % size, 0, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
  int bodies = 0;
  const int sample = !(argc > 1 && strcmp(argv[1], "nosample") == 0);
  for (int i = 0; sample && i < 8; ++i) {
    GCSIM_SAMPLE_LOCAL(2) {
      x += chain(100000);
      ++bodies;
    }
  }
  MPI_Barrier(MPI_COMM_WORLD);
  const double t = MPI_Wtime();
  printf("rank %d got %d, ran %d sampled bodies, chain %s\n", rank, got, bodies, x > 1 ? "ok" : "wrong");
  if (rank == 0) printf("simulated time after the barrier %.12f s\n", t);
  MPI_Finalize();
  return 0;
}
