#pragma once
// The physical interconnects a machine file may name ([topology] interconnect = "mesh"): name ->
// factory. Each registers itself from its own file with a namespace-scope InterconnectRegistrar,
// so adding one is one class and one registrar line (machine/mesh.cpp registers the GC's mesh;
// tests/interconnects/torus is a test-only one). The machine-file parser checks names against
// this list, and the simulation, `gcsim topo`, placements and the trace writers build the
// machine's interconnect with make_interconnect().
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::machine {

class Interconnect;
struct MachineConfig;

struct InterconnectEntry {
  std::string_view name;
  std::string_view summary;  // one line, for help texts
  // Builds it for the machine: config.nodes nodes, laid out as config.mesh_width x mesh_height.
  std::function<std::unique_ptr<Interconnect>(const MachineConfig& config)> make;
  int order = 100;  // help texts list entries by order, then name; the mesh is 10
};

// Adds an interconnect when its file is linked (a namespace-scope constant in that file).
struct InterconnectRegistrar {
  explicit InterconnectRegistrar(InterconnectEntry entry);
};

// Every registered interconnect, in the order help texts list them ("mesh" first).
const std::vector<InterconnectEntry>& interconnects();
std::vector<std::string> interconnect_names();
// "mesh, torus": for error messages.
std::string interconnect_list();
bool is_interconnect(std::string_view name);

// The interconnect config.interconnect names, built for config. Throws std::invalid_argument
// listing the registered names if that name is unknown.
std::unique_ptr<Interconnect> make_interconnect(const MachineConfig& config);
// The same for a grid of width x height nodes only (what a trace file records of its machine).
std::unique_ptr<Interconnect> make_interconnect(std::string_view name, int width, int height);

}  // namespace gcsim::machine
