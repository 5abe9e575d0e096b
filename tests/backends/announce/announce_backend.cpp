// A test-only backend: says on stderr how many processors it starts, then runs them on the
// simulated machine. It exists to prove that a backend is one folder: nothing outside
// tests/backends/announce names it, yet `--backend announce` works for every application.
#include <cstdio>

#include "parix/backend.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix {
namespace {

RunResult run_announced(const RunOptions& options, const Program& program) {
  std::fprintf(stderr, "announce: %d processors on the simulated machine\n", options.simulation.config.nodes);
  RunResult r = run_simulated(options.simulation, program);
  std::fprintf(stderr, "announce: done at simulated %.6f s\n", r.simulated_seconds());
  return r;
}

const BackendRegistrar registrar{{"announce", "the simulated machine, announced on stderr (a test-only backend)",
                                  &run_announced}};

}  // namespace
}  // namespace gcsim::parix
