/* A ring: every rank passes values to its right-hand neighbour with MPI_Sendrecv until each has
 * seen every rank's number; each then prints the sum, n(n-1)/2. An optional argument repeats the
 * whole ring that many times (the sum is then reps n(n-1)/2), for measuring the message path:
 * n reps (n-1) messages. An ordinary MPI program:
 *   gcsim-mpicc -o ring ring.c && gcsim mpirun -np 16 ./ring
 *   gcsim mpirun -np 64 --compute none ./ring 100     (403200 messages)
 *   mpicc -o ring ring.c && mpirun -np 4 ./ring          (Open MPI: the same output) */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int right = (rank + 1) % size, left = (rank + size - 1) % size;
  const long reps = argc > 1 ? atol(argv[1]) : 1;
  long sum = 0;
  for (long rep = 0; rep < reps; ++rep) {
    long passing = rank;
    sum += rank;
    for (int step = 1; step < size; ++step) {
      long received;
      MPI_Sendrecv(&passing, 1, MPI_LONG, right, 0, &received, 1, MPI_LONG, left, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      passing = received;
      sum += received;
    }
  }
  const long expected = reps * ((long)size * (size - 1) / 2);
  printf("rank %d of %d: ring sum %ld (expected %ld)\n", rank, size, sum, expected);
  MPI_Finalize();
  return sum == expected ? 0 : 1;
}
