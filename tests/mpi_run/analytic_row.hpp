#pragma once
// A row of simulated nodes on the analytic network with round MPI costs (o = 5 us, G = 2 ns per
// byte), and what one message of `bytes` costs on it: the timing tests that hold collectives to
// their hand-computed schedules share it.
#include <cmath>
#include <memory>
#include <optional>

#include "machine/interconnect_registry.hpp"
#include "machine/machine_config.hpp"
#include "machine/network_model.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::mpi_layer {

// Simulated times in the machine's picoseconds (MPI_Wtime's seconds read back exactly).
inline machine::SimTime picoseconds(double seconds) { return std::llround(seconds * 1e12); }

struct AnalyticRow {
  parix::SimulationOptions options;
  std::unique_ptr<machine::Interconnect> interconnect;
  machine::Kernel kernel;
  std::unique_ptr<machine::NetworkModel> network;
  int bytes = 0;
  machine::SimTime cpu = 0;     // c = o + G n, as Rank::charge computes it
  machine::SimTime reduce = 0;  // R, as Rank::charge_reduction computes it
  machine::SimTime transit(int from, int to) const {
    return network->uncontended_time(interconnect->hops(from, to), bytes);
  }
};

// `nodes` in a row; the reduction's cost per byte stays the machine's unless given.
inline std::unique_ptr<AnalyticRow> analytic_row(int nodes, int bytes, std::optional<double> reduce_seconds_per_byte = {}) {
  auto m = std::make_unique<AnalyticRow>();
  machine::MachineConfig& c = m->options.config;
  c = machine::with_nodes(machine::default_machine_config(), nodes, machine::MeshShape{nodes, 1});
  c.network_model = "analytic";
  c.mpi.call_overhead = machine::from_seconds(5e-6);
  c.mpi.seconds_per_byte = 2e-9;
  if (reduce_seconds_per_byte) c.mpi.reduce_seconds_per_byte = *reduce_seconds_per_byte;
  m->interconnect = machine::make_interconnect(c);
  m->network = machine::make_network_model("analytic", {m->kernel, *m->interconnect, c, nullptr});
  m->bytes = bytes;
  m->cpu = c.mpi.call_overhead + machine::from_seconds(c.mpi.seconds_per_byte * bytes);
  m->reduce = machine::from_seconds(c.mpi.reduce_seconds_per_byte * bytes);
  return m;
}

}  // namespace gcsim::mpi_layer
