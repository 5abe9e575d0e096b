#include "machine/interconnect_registry.hpp"

#include <stdexcept>

#include "machine/interconnect.hpp"
#include "machine/machine_config.hpp"
#include "machine/registry.hpp"

namespace gcsim::machine {

namespace {
Registry<InterconnectEntry>& interconnect_registry() { return Registry<InterconnectEntry>::instance(); }
}  // namespace

InterconnectRegistrar::InterconnectRegistrar(InterconnectEntry entry) { interconnect_registry().add(std::move(entry)); }

const std::vector<InterconnectEntry>& interconnects() { return interconnect_registry().entries(); }
std::vector<std::string> interconnect_names() { return interconnect_registry().names(); }
std::string interconnect_list() { return interconnect_registry().list(); }
bool is_interconnect(std::string_view name) { return interconnect_registry().find(name) != nullptr; }

std::unique_ptr<Interconnect> make_interconnect(const MachineConfig& config) {
  const InterconnectEntry* e = interconnect_registry().find(config.interconnect);
  if (!e) {
    throw std::invalid_argument("unknown interconnect '" + config.interconnect + "' (expected one of: " + interconnect_list() + ")");
  }
  return e->make(config);
}

std::unique_ptr<Interconnect> make_interconnect(std::string_view name, int width, int height) {
  MachineConfig c;
  c.interconnect = std::string(name);
  c.mesh_width = width;
  c.mesh_height = height;
  c.nodes = width * height;
  return make_interconnect(c);
}

}  // namespace gcsim::machine
