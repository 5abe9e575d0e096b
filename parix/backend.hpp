#pragma once
// One entry point for running an SPMD program: the backend is a name in RunOptions, so an
// application never calls a particular runtime. "simulated" runs the program on the discrete-event
// model of the machine (parix/sim/simulated_runtime.hpp) and is always there; another backend (parix/mpi/)
// registers itself beside it with a BackendRegistrar from its own folder, and a build without it
// simply does not offer its name.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "parix/processor.hpp"
#include "parix/run_result.hpp"
#include "parix/simulation_options.hpp"

namespace gcsim::parix {

// What every processor runs.
using Program = std::function<void(Processor&)>;

struct RunOptions {
  std::string backend = "simulated";  // a name from backend_names()
  SimulationOptions simulation;       // machine, node count, network model, trace
  // Host threads an application may use beside the simulation's own for work it can compute ahead
  // (a pure function of its inputs, e.g. the radiosity's hemicube cells): 1, none. The kernel and the
  // processors stay on one thread, so results, simulated times and traces are the same for any count.
  int host_threads = 1;
};

// A backend runs program on every processor of options and returns when all have returned.
using BackendRunner = RunResult (*)(const RunOptions& options, const Program& program);

struct Backend {
  std::string_view name;
  std::string_view summary;  // one line for --help
  BackendRunner run;
};

// Adds a backend when its translation unit is linked (a namespace-scope constant in its folder).
struct BackendRegistrar {
  explicit BackendRegistrar(const Backend& backend);
};

// The backends this build has, "simulated" first, then in registration order.
const std::vector<Backend>& backends();
std::vector<std::string> backend_names();

// Runs program on the backend options names. Throws std::invalid_argument for an unknown
// backend (naming the known ones), and whatever the backend throws (e.g. DeadlockError).
RunResult run(const RunOptions& options, const Program& program);

}  // namespace gcsim::parix
