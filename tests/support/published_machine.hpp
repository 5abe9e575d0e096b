#pragma once
// The published GC-PowerPlus cut to N nodes, as the parallel tests of every application run it,
// and the figures of it that the runtime's tests work out by hand.
#include <cstring>
#include <string>
#include <string_view>

#include "machine/machine_config.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::test_support {

inline parix::SimulationOptions published_machine(int nodes) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), nodes);
  return o;
}

// The same machine with another network model ("": the machine file's own).
inline parix::SimulationOptions on_nodes(int nodes, const std::string& model = "") {
  parix::SimulationOptions o = published_machine(nodes);
  if (!model.empty()) o.config.network_model = model;
  return o;
}

// The published GC: neighbours connect in 0.55 + 0.24 ms; a message pays 5 us set-up and 60 us latency.
constexpr machine::SimTime kConnectNeighbour = 790 * machine::kMicrosecond;
constexpr machine::SimTime kEmptyMessageNeighbour = 65 * machine::kMicrosecond;

inline parix::Bytes bytes_of(std::string_view s) {
  parix::Bytes b(s.size());
  if (!s.empty()) std::memcpy(b.data(), s.data(), s.size());  // an empty vector's data() may be null
  return b;
}

}  // namespace gcsim::test_support
