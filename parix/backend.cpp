#include "parix/backend.hpp"

#include <stdexcept>

#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix {

namespace {

RunResult run_on_simulated_machine(const RunOptions& options, const Program& program) {
  return run_simulated(options.simulation, program);
}

// Built on first use, so registrars in other translation units may run in any order.
std::vector<Backend>& registry() {
  static std::vector<Backend> all{
      {"simulated", "the discrete-event model of the machine (simulated time)", &run_on_simulated_machine},
  };
  return all;
}

}  // namespace

BackendRegistrar::BackendRegistrar(const Backend& backend) { registry().push_back(backend); }

const std::vector<Backend>& backends() { return registry(); }

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const Backend& b : backends()) names.emplace_back(b.name);
  return names;
}

RunResult run(const RunOptions& options, const Program& program) {
  for (const Backend& b : backends())
    if (b.name == options.backend) return b.run(options, program);
  std::string known;
  for (const Backend& b : backends()) known += (known.empty() ? "" : ", ") + std::string(b.name);
  throw std::invalid_argument("unknown backend '" + options.backend + "': expected one of " + known);
}

}  // namespace gcsim::parix
