/* A ring of MPI_Sendrecv: every rank passes BYTES bytes to its right-hand neighbour and receives
 * from its left, in ROUNDS rounds of one step per rank, after WARMUP such rounds (default 2).
 * Rank 0 prints the time per step, by MPI_Wtime. Why rounds: the steps settle into a pattern
 * that repeats every n steps (the ring is one cycle of n dependencies), so only whole rounds
 * give the ring's pace; why warm-up: gcsim's first messages pay the connection set-ups, which
 * start the ranks out of step, and SMPI has none. An ordinary MPI program: the same source
 * builds with gcsim-mpicc and SimGrid's smpicc.
 *   sendrecv_ring BYTES ROUNDS [WARMUP]   prints: ring ranks N bytes B step_s T checksum ok */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int bytes = argc > 1 ? atoi(argv[1]) : 8;
  const int rounds = argc > 2 ? atoi(argv[2]) : 1;
  const int warmup_rounds = argc > 3 ? atoi(argv[3]) : 2;
  if (bytes < (int)sizeof(int) || rounds < 1 || warmup_rounds < 0) {
    if (rank == 0) fprintf(stderr, "usage: sendrecv_ring BYTES ROUNDS [WARMUP] with BYTES >= %d\n", (int)sizeof(int));
    MPI_Finalize();
    return 2;
  }
  const int right = (rank + 1) % size, left = (rank + size - 1) % size;
  char* out = calloc((size_t)bytes, 1);
  char* in = calloc((size_t)bytes, 1);
  int token = rank;
  long checksum = 0;
  double start = 0;
  const int warmup = warmup_rounds * size, iterations = rounds * size;
  for (int step = 0; step < warmup + iterations; ++step) {
    if (step == warmup) start = MPI_Wtime();
    memcpy(out, &token, sizeof token);
    MPI_Sendrecv(out, bytes, MPI_CHAR, right, 0, in, bytes, MPI_CHAR, left, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    memcpy(&token, in, sizeof token);
    checksum += token;
  }
  /* Every token passes every rank: after k steps rank r holds (r - k) mod n. */
  const long steps = warmup + iterations;
  long expected = 0;
  for (long k = 1; k <= steps; ++k) expected += ((rank - k) % size + size) % size;
  if (rank == 0)
    printf("ring ranks %d bytes %d step_s %.9e checksum %s\n", size, bytes, (MPI_Wtime() - start) / iterations,
           checksum == expected ? "ok" : "wrong");
  free(out);
  free(in);
  MPI_Finalize();
  return checksum == expected ? 0 : 1;
}
