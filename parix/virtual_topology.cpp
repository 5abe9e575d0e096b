#include "parix/virtual_topology.hpp"

#include <stdexcept>

#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"

namespace gcsim::parix {

VirtualTopologyView virtual_topology(const Processor& p, std::string_view name) {
  try {
    return VirtualTopologyView(machine::make_topology(name, p.count()), p.id());
  } catch (const std::invalid_argument& e) {
    throw ParixError("processor " + std::to_string(p.id()) + ": virtual_topology: " + e.what());
  }
}

std::vector<int> topology_placement(const machine::MachineConfig& config, std::string_view name, int nodes) {
  const machine::MachineConfig c = nodes > 0 ? machine::with_nodes(config, nodes) : config;
  try {
    return machine::map_onto(machine::make_topology(name, c.nodes), *machine::make_interconnect(c)).node_of;
  } catch (const std::invalid_argument& e) {
    throw ParixError(std::string("topology_placement: ") + e.what());
  }
}

}  // namespace gcsim::parix
