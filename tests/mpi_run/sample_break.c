/* A sampled body left by break: its site's next execution ends the run naming the site. */
#include <gcsim/mpi_ext.h>
#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  for (int i = 0; i < 4; ++i) {
    GCSIM_SAMPLE_LOCAL(2) {
      if (i == 0) break;
    }
  }
  MPI_Finalize();
  return 0;
}
