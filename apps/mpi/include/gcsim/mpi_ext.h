/* gcsim's extensions to MPI for programs run by `gcsim mpirun` (apps/mpi/README.md, "Computation").
 *
 * gcsim_mpi_compute(seconds): the calling rank computes for `seconds` of simulated time on its
 * node's CPU. gcsim_mpi_compute_flops(flops): the same for `flops` floating-point operations at the
 * node's rate from the machine file ([ops] flop cycles at [node] clock_mhz: 80 Mflop/s on the GC).
 * Both charge under `--compute annotated` and `--compute measured` (there on top of the measured
 * host time: they stand for work the program does not do on the host), never under `none`, and
 * never depend on --host-speed. They return MPI_SUCCESS, or MPI_ERR_ARG for a negative argument.
 *
 * Sampling, in the spirit of SMPI's SMPI_SAMPLE_LOCAL/GLOBAL, for a loop whose iterations cost
 * about the same:
 *
 *   for (i = 0; i < n; i++) {
 *     GCSIM_SAMPLE_LOCAL(3) { expensive_kernel(block); }
 *   }
 *
 * The block is a site (its file and line). Its first `samples` executions run and are timed as the
 * rank's host CPU time (any MPI call inside left out); every later execution skips the block and
 * is charged the mean of the timed ones. So n executions charge n x mean. Times are host seconds
 * scaled by the host speed (--host-speed) to node seconds. LOCAL counts per rank; GLOBAL shares
 * the site among the run's ranks: the first `samples` executions on any ranks run, the rest of
 * every rank are skipped. Charged: under annotated the timed bodies and the skipped ones; under
 * measured the same (the timed bodies as measured time between calls); under none nothing, but
 * the same bodies run and are skipped. The timed bodies are host measurements, so a run that
 * samples is not byte-identical from run to run, even under annotated; which bodies of a LOCAL
 * site run is (the first `samples`), and so is everything else of annotated and none runs.
 * The body must not leave by break, goto or return (the run ends naming the site). Skipped
 * bodies do not run: whatever they would have computed must not be needed. */
#ifndef GCSIM_MPI_EXT_H
#define GCSIM_MPI_EXT_H
#ifdef __cplusplus
extern "C" {
#endif
int gcsim_mpi_compute(double seconds);
int gcsim_mpi_compute_flops(double flops);
/* The sampling macros' calls: begin returns 1 when the body runs (0: skipped and charged). */
int gcsim_mpi_sample_begin(const char* file, int line, int global, int samples);
int gcsim_mpi_sample_end(const char* file, int line, int global);
#ifdef __cplusplus
}
#endif

#define GCSIM_SAMPLE_SITE_(global, samples)                                                     \
  for (int gcsim_sample_runs_ = gcsim_mpi_sample_begin(__FILE__, __LINE__, (global), (samples)); \
       gcsim_sample_runs_; gcsim_sample_runs_ = gcsim_mpi_sample_end(__FILE__, __LINE__, (global)))
#define GCSIM_SAMPLE_LOCAL(samples) GCSIM_SAMPLE_SITE_(0, (samples))
#define GCSIM_SAMPLE_GLOBAL(samples) GCSIM_SAMPLE_SITE_(1, (samples))
#endif
