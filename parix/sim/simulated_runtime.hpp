#pragma once
// Runs an SPMD program on the simulated machine: each virtual processor is a fiber (Boost.Context) whose
// blocking calls become events on the discrete-event kernel.
#include <functional>
#include <stdexcept>
#include <string>

#include "parix/processor.hpp"
#include "parix/run_result.hpp"
#include "parix/simulation_options.hpp"

namespace gcsim::parix {

// Every processor blocked and no event pending. what() is the report naming each blocked
// processor, its call and its peer.
class DeadlockError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs program on every virtual processor; returns when all have returned.
// Throws DeadlockError on deadlock, rethrows the first exception an application threw.
RunResult run_simulated(const SimulationOptions& options, const std::function<void(Processor&)>& program);

}  // namespace gcsim::parix
