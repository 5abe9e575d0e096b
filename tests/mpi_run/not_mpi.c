/* An ordinary executable, not built with gcsim-mpicc: gcsim mpirun must refuse it with a clear
 * message (exit 3), not crash. */
#include <stdio.h>
int main(void) {
  printf("not an MPI program\n");
  return 0;
}
