// C++'s streams are each rank's own as its stdio is: cout, printf and cerr in the order written
// (cout and cerr are bound to the C streams gcsim mpirun replaces while the ranks run).
#include <mpi.h>

#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::cout << "rank " << rank << " cout" << std::endl;
  std::printf("rank %d printf\n", rank);
  std::cerr << "rank " << rank << " cerr\n";
  MPI_Barrier(MPI_COMM_WORLD);  // another rank runs: what this one wrote is attributed here
  std::cout << "rank " << rank << " after\n";
  MPI_Finalize();
  return 0;
}
