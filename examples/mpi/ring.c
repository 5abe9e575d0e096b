/* A ring: every rank passes values to its right-hand neighbour with MPI_Sendrecv until each has
 * seen every rank's number; each then prints the sum, n(n-1)/2. An ordinary MPI program:
 *   gcsim-mpicc -o ring ring.c && gcsim mpirun -np 16 ./ring
 *   mpicc -o ring ring.c && mpirun -np 4 ./ring          (Open MPI: the same output) */
#include <mpi.h>
#include <stdio.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank, size;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int right = (rank + 1) % size, left = (rank + size - 1) % size;
  long passing = rank, sum = rank;
  for (int step = 1; step < size; ++step) {
    long received;
    MPI_Sendrecv(&passing, 1, MPI_LONG, right, 0, &received, 1, MPI_LONG, left, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    passing = received;
    sum += received;
  }
  printf("rank %d of %d: ring sum %ld (expected %ld)\n", rank, size, sum, (long)size * (size - 1) / 2);
  MPI_Finalize();
  return sum == (long)size * (size - 1) / 2 ? 0 : 1;
}
