#pragma once
// A machine described by a topology file (configs/*.toml). Every field is documented in
// configs/gc-powerplus.toml; load_machine_config() rejects unknown keys, wrong types, impossible
// values and meshes that do not match the node count, naming the file and line.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "machine/sim_time.hpp"

namespace gcsim::machine {

struct MeshShape {
  int width;
  int height;
};

// How connection set-ups proceed side by side (machine/connection_service.hpp).
enum class ConnectModel { parallel, serialized, servers, route };

struct MachineConfig {
  std::string name;
  std::string source;                  // file it came from (builtin_source(NAME) for a built-in one)
  std::vector<std::string> calibrated_on;  // [calibration] fitted: the tables a fit used (gcsim calibrate)

  // Topology
  int nodes = 64;
  // The physical interconnect, by its registered name (machine/interconnect_registry.hpp):
  // [topology] interconnect, "mesh" (the GC's) when the file gives none.
  std::string interconnect = "mesh";
  int mesh_width = 8;                  // x extent of the grid of nodes the interconnect wires
  int mesh_height = 8;                 // y extent
  // Sub-meshes that `--nodes N` uses instead of the GC's default shape ([topology.shapes]).
  std::map<int, MeshShape> shapes;

  // Node
  int cpus_per_node = 2;
  double clock_hz = 80e6;
  std::int64_t memory_bytes = 32ll << 20;
  int comm_processors = 4;             // T805 transputers per node
  int links_per_comm_processor = 4;
  std::map<std::string, double, std::less<>> cycles_per_op;

  // Network
  std::string network_model = "analytic";
  double link_bandwidth = 35e6 / 16;   // bytes/s of one transputer link
  SimTime message_setup = 5 * kMicrosecond;
  SimTime network_latency = 60 * kMicrosecond;  // minimum: one hop, zero bytes
  SimTime hop_latency = 1 * kMicrosecond;       // each further hop
  SimTime connect_base = 550 * kMicrosecond;    // opening a virtual link
  SimTime connect_per_hop = 240 * kMicrosecond;
  ConnectModel connect_model = ConnectModel::parallel;
  int connect_block_width = 4;   // with ConnectModel::servers: nodes per connection server, x
  int connect_block_height = 4;  // and y
  // The packet model cuts messages into packets of at most this many bytes.
  std::int64_t packet_bytes = 1024;

  // CPU time a node's PowerPC spends on communication ([comm_cpu]): it occupies one of the node's
  // CPUs, so it competes with compute. Zero in the published machine (the thesis gives none).
  struct CommCpu {
    SimTime send = 0;            // handing one message to the communication processors
    SimTime recv = 0;            // taking one received message
    SimTime connect = 0;         // opening one virtual link (each end)
    double seconds_per_byte = 0; // copying a message's bytes (both ends)
    bool any() const { return send > 0 || recv > 0 || connect > 0 || seconds_per_byte > 0; }
  } comm_cpu;

  // MPI programs run by `gcsim mpirun` ([mpi]): LogGP's o (CPU time per send or receive call) and
  // G (per byte), the CPU time per byte of a reduction's operands, and the size up to which a
  // standard send is eager (above it the sender waits for the matching receive). Not measured on
  // the GC (the thesis ran no MPI): documented assumptions, apps/mpi/README.md.
  struct Mpi {
    SimTime call_overhead = 0;
    double seconds_per_byte = 0;
    double reduce_seconds_per_byte = 0;
    std::int64_t eager_limit_bytes = 16384;
  } mpi;

  // Runtime (the host, not the simulated machine): bytes of stack per simulated process's fiber.
  std::int64_t fiber_stack_bytes = 64 << 10;

  int links_per_node() const { return comm_processors * links_per_comm_processor; }
  // A channel's bandwidth when the node's links are spread evenly over `directions` neighbours
  // (Interconnect::directions; the parser checks that they divide evenly).
  double channel_bandwidth(int directions) const { return link_bandwidth * (links_per_node() / directions); }
  double node_bandwidth() const { return link_bandwidth * links_per_node(); }
};

// Where a configuration error was found.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& file, int line, const std::string& what);
  std::string file;
  int line;
};

MachineConfig load_machine_config(const std::filesystem::path& file);
MachineConfig parse_machine_config(std::string_view toml_text, const std::string& source_name);
// The built-in default: the GC-PowerPlus as measured, configs/gc-powerplus-calibrated.toml and
// its bases as compiled into the binary (machine/builtin_machines.hpp); no file is read.
MachineConfig default_machine_config();
// The GC-PowerPlus as published (configs/gc-powerplus.toml, also compiled in) and its file's text.
MachineConfig published_machine_config();
std::string_view published_machine_config_text();

// The mesh shape the GC uses for its first n nodes: 2=2x1, 4=2x2, 8=4x2, 16=4x4, 32=8x4, 64=8x8;
// in general the most nearly square w x h with w >= h.
MeshShape gc_mesh_shape(int n);
// The config restricted to n nodes: in `shape` if given, else in the config's [topology.shapes]
// entry for n, else in gc_mesh_shape(n) (turned if only that fits). Throws ConfigError if the
// shape does not have n nodes or does not fit in the machine's mesh.
MachineConfig with_nodes(const MachineConfig& c, int n, std::optional<MeshShape> shape = std::nullopt);
// "WxH" -> shape; throws std::invalid_argument naming what was expected.
MeshShape parse_mesh_shape(std::string_view text);

// Simulated CPU time for count operations of the named kind on this machine.
// Throws std::out_of_range naming the operation if the config has no cost for it.
SimTime op_time(const MachineConfig& c, std::string_view op, std::int64_t count);

}  // namespace gcsim::machine
