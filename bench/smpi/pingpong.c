/* Ping-pong between rank 0 and rank PEER: BYTES bytes there and back REPS times, after one
 * warm-up exchange (gcsim pays a pair's connection set-up on its first message; SMPI has none),
 * timed by rank 0 with MPI_Wtime. The other ranks only take part in MPI_Init/MPI_Finalize.
 * An ordinary MPI program: the same source builds with gcsim-mpicc and SimGrid's smpicc.
 *   pingpong PEER BYTES REPS   prints: pingpong peer P bytes B round_trip_s T */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int peer = argc > 1 ? atoi(argv[1]) : 1;
  const int bytes = argc > 2 ? atoi(argv[2]) : 0;
  const int reps = argc > 3 ? atoi(argv[3]) : 10;
  if (peer < 1 || peer >= size || bytes < 0 || reps < 1) {
    if (rank == 0) fprintf(stderr, "usage: pingpong PEER BYTES REPS with 0 < PEER < %d ranks\n", size);
    MPI_Finalize();
    return 2;
  }
  char* buffer = calloc((size_t)bytes + 1, 1);
  int failures = 0;
  if (rank == 0 || rank == peer) {
    const int other = rank == 0 ? peer : 0;
    double start = 0;
    for (int i = 0; i <= reps; ++i) {
      if (i == 1) start = MPI_Wtime();
      if (rank == 0) {
        if (bytes > 0) buffer[bytes - 1] = (char)i;
        MPI_Send(buffer, bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD);
        MPI_Recv(buffer, bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (bytes > 0 && buffer[bytes - 1] != (char)(i + 1)) ++failures;
      } else {
        MPI_Recv(buffer, bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (bytes > 0) buffer[bytes - 1] = (char)(buffer[bytes - 1] + 1);
        MPI_Send(buffer, bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD);
      }
    }
    if (rank == 0) printf("pingpong peer %d bytes %d round_trip_s %.9e failures %d\n", peer, bytes, (MPI_Wtime() - start) / reps, failures);
  }
  free(buffer);
  MPI_Finalize();
  return failures ? 1 : 0;
}
