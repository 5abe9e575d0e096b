/* gcsim's extensions to MPI for programs run by `gcsim mpirun` (apps/mpi/README.md).
 * gcsim_mpi_compute(seconds): the calling rank computes for `seconds` of simulated time on its
 * node's CPU (`--compute annotated`): the one way a program's computation between MPI calls takes
 * simulated time, deterministically. Under `--compute none` it is ignored. Returns MPI_SUCCESS. */
#ifndef GCSIM_MPI_EXT_H
#define GCSIM_MPI_EXT_H
#ifdef __cplusplus
extern "C" {
#endif
int gcsim_mpi_compute(double seconds);
#ifdef __cplusplus
}
#endif
#endif
