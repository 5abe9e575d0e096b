// Commands about the machine itself: topo (interconnect parameters and mappings), bcast (the
// thesis's broadcast experiment) and bench ring (kernel throughput).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/programs/broadcast_experiment.hpp"
#include "apps/cli/commands.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/resource_check.hpp"
#include "apps/programs/ring_program.hpp"
#include "parix/backend.hpp"
#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/topology.hpp"

namespace gcsim::cli {
namespace {
using namespace gcsim::programs;  // the broadcast and ring programs these commands run

// Without --nodes, bcast and bench ring use every node of the machine file (64 on the GC,
// 65536 on whatif-65536-nodes.toml).
constexpr int kWholeMachine = std::numeric_limits<int>::max();

std::string formula(double v) { return std::isnan(v) ? "-" : fmt::format("{:.2f}", v); }

void add_topo(CommandGroups& g) {
  struct Options {
    std::string config, topology = "mesh", json;
    int nodes = 64;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = g.app->add_subcommand("topo", "Interconnect parameters of a virtual topology (thesis table 2.1) and its mapping");
  cmd->footer(
      "Interconnect parameters of a virtual topology (thesis table 2.1), computed exactly on its graph\n"
      "next to the thesis's formulas, and the dilation and congestion of its mapping onto the machine's\n"
      "physical interconnect ([topology] interconnect, the GC's mesh by default).\n"
      "D = maximum, d = mean processor distance (hops); R = maximum, r = mean relay load (shortest\n"
      "paths between other pairs through a processor); k = mean links per processor; B = broadcast\n"
      "distance from the best-placed managing processor.");
  pipeline::add_config_option(cmd, o->config);
  cmd->add_option("--topology", o->topology, "Virtual topology: " + pipeline::topology_choices())
      ->check(CLI::IsMember(machine::topology_names()))
      ->capture_default_str();
  pipeline::add_nodes_option(cmd, o->nodes, "64 (a hypercube needs a power of two)", 1 << 16);
  pipeline::add_json_option(cmd, o->json, "the parameters");
  cmd->callback([o] {
    pipeline::check_writable(o->json, "--json");
    machine::MachineConfig c = o->config.empty() ? machine::default_machine_config() : machine::load_machine_config(o->config);
    c = machine::with_nodes(c, o->nodes);
    const machine::TopologyKind kind = machine::parse_topology_kind(o->topology);
    const machine::VirtualTopology t = machine::make_topology(kind, o->nodes);
    const machine::TopologyMetrics exact = machine::exact_metrics(t);
    const machine::TopologyMetrics thesis = machine::thesis_formulas(kind, o->nodes);
    const std::unique_ptr<machine::Interconnect> net = machine::make_interconnect(c);
    const machine::PhysicalMapping map = machine::map_onto(t, *net);

    fmt::print("{} of {} processors on {} ({}x{} physical {})\n\n", o->topology, o->nodes, c.name, c.mesh_width,
               c.mesh_height, net->name());
    fmt::print("  parameter                 exact    thesis formula   what it counts\n");
    const struct {
      const char* name;
      double exact, thesis;
      const char* what;
    } rows[] = {
        {"D  max distance (hops)", exact.D, thesis.D, "hops between the farthest pair"},
        {"d  mean distance", exact.d, thesis.d, "hops, mean over ordered pairs"},
        {"R  max relay load", exact.R, thesis.R, "shortest paths between two other processors through the busiest one"},
        {"r  mean relay load", exact.r, thesis.r, "the same, mean over processors (a pair with k shortest paths adds 1/k each)"},
        {"k  mean links/processor", exact.k, thesis.k, "links per processor, mean"},
        {"B  broadcast distance", exact.B, thesis.B, "steps from the best-placed manager to every processor"}};
    for (const auto& r : rows)
      fmt::print("  {:<24} {:>8.2f}  {:>12}     {}\n", r.name, r.exact, formula(r.thesis), r.what);
    fmt::print("\n  mapping onto the physical {}: dilation {} (mean {:.2f} hops per virtual link), congestion {}\n",
               net->name(), map.dilation, map.mean_dilation, map.congestion);
    if (!o->json.empty()) {
      auto num = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
      nlohmann::json j{{"topology", o->topology},
                       {"nodes", o->nodes},
                       {"interconnect", std::string(net->name())},
                       {"mesh", {c.mesh_width, c.mesh_height}},
                       {"D", exact.D},
                       {"d", exact.d},
                       {"R", exact.R},
                       {"r", exact.r},
                       {"k", exact.k},
                       {"B", exact.B},
                       {"thesis", {{"D", num(thesis.D)}, {"d", num(thesis.d)}, {"R", num(thesis.R)},
                                   {"r", num(thesis.r)}, {"k", num(thesis.k)}, {"B", num(thesis.B)}}},
                       {"mapping", {{"dilation", map.dilation}, {"mean_dilation", map.mean_dilation},
                                    {"congestion", map.congestion}, {"node_of", map.node_of}}}};
      write_json_file(o->json, j);
    }
  });
}

parix::BcastAlgo parse_algo(const std::string& s) {
  return s == "tree" ? parix::BcastAlgo::tree : parix::BcastAlgo::sequential;
}

void print_bcast_table(const MachineOptions& mo) {
  fmt::print("One all-node broadcast (thesis 4.4.2), simulated ms next to the thesis's measured ms.\n");
  fmt::print("A connection is opened for every message; every message carries SIZE bytes.\n\n");
  const char* size_names[4] = {"connect", "1 KB", "4 KB", "16 KB"};
  MachineOptions whole = mo;  // the machine file is read once; each cell takes its first n nodes
  whole.nodes = 0;
  whole.trace.clear();
  const parix::SimulationOptions whole_machine = simulation_options(whole, std::numeric_limits<int>::max());
  for (const char* algo : {"sequential", "tree"}) {
    const auto* thesis = std::string_view(algo) == "tree" ? kThesisTreeBroadcast : kThesisSequentialBroadcast;
    fmt::print("{} broadcast (thesis table {})\n", algo, std::string_view(algo) == "tree" ? "4.7" : "4.6");
    fmt::print("  nodes");
    for (const char* s : size_names) fmt::print(" | {:>7} sim  thesis", s);
    fmt::print("\n");
    for (int row = 0; row < 6; ++row) {
      const int n = thesis[row].nodes;
      fmt::print("  {:>5}", n);
      for (int s = 0; s < 4; ++s) {
        parix::RunOptions so{whole.backend, whole_machine};
        so.simulation.config = machine::with_nodes(whole_machine.config, n);
        const std::int64_t bytes = kThesisBroadcastSizes[s];
        const parix::BcastAlgo a = parse_algo(algo);
        parix::RunResult r = parix::run(so, [&](parix::Processor& p) { all_node_broadcast(p, bytes, a); });
        fmt::print(" | {:>11.2f} {:>7.2f}", machine::to_milliseconds(r.makespan), thesis[row].ms[s]);
      }
      fmt::print("\n");
    }
    fmt::print("\n");
  }
}

void add_bcast(CommandGroups& g) {
  struct Options {
    MachineOptions machine;
    std::string size = "16KB";
    std::string algo = "tree";
    bool table = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = g.app->add_subcommand("bcast", "The thesis's broadcast experiment (4.4.2): sequential or tree, simulated ms");
  cmd->footer(
      "The thesis's broadcast experiment (section 4.4.2): one all-node broadcast, where every node's data\n"
      "goes to the root (node 0) and the root sends back to every node. sequential: the nodes send to the\n"
      "root in turn and the root answers each in turn (O(N) steps); tree: up a binary tree from the leaves\n"
      "and back down (O(log N) steps). A connection (virtual link) is opened for every message.\n"
      "Message size: every message carries exactly --size bytes; data is not merged on the way, as in the\n"
      "thesis's measurements. --size 0 opens the connections and sends nothing (the 'connect only' column).");
  add_machine_options(cmd, o->machine, "every node of the machine");
  cmd->add_option("--size", o->size, "Bytes per message (suffixes: 1KB = 1024 bytes)")->capture_default_str();
  cmd->add_option("--algo", o->algo, "sequential or tree")->check(CLI::IsMember({"sequential", "tree"}))->capture_default_str();
  cmd->add_flag("--table", o->table, "Run the thesis's whole grid (N = 2..64; 0, 1, 4, 16 KB; both algorithms) and print it next to tables 4.6 and 4.7");
  cmd->callback([o] {
    if (o->table) {
      print_bcast_table(o->machine);
      return;
    }
    const std::int64_t bytes = parse_message_size(o->size);
    const parix::RunOptions so = run_options(o->machine, kWholeMachine);
    check_broadcast_resources(bytes, so.simulation.config.nodes, so.simulation.config.memory_bytes,
                              so.simulation.memory_limit);
    const parix::BcastAlgo a = parse_algo(o->algo);
    parix::RunResult r = pipeline::run_program(so, [&](parix::Processor& p) { all_node_broadcast(p, bytes, a); }, o->machine);
    fmt::print("all-node broadcast, {} algorithm, {} bytes per message, {} nodes\n", o->algo, bytes, r.nodes);
    report_run(r, o->machine, {{"experiment", "bcast"}, {"algo", o->algo}, {"size_bytes", bytes}});
  });
}

void add_bench_ring(CommandGroups& g) {
  struct Options {
    MachineOptions machine;
    int iterations = 2000;
    std::int64_t size = 64;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = g.bench->add_subcommand("ring", "Kernel throughput: simulated messages per wall-clock second on a ring");
  cmd->footer(
      "Kernel throughput: every processor sends --size bytes to its right neighbour and receives from its\n"
      "left, --iterations times, over persistent links. Prints simulated messages per wall-clock second.");
  add_machine_options(cmd, o->machine, "every node of the machine");
  cmd->add_option("--iterations", o->iterations, "Messages each processor sends")->check(CLI::Range(1, 1 << 30))->capture_default_str();
  cmd->add_option("--size", o->size, "Bytes per message")->transform(CLI::AsSizeValue(false))->transform(pipeline::no_negative_size())->capture_default_str();
  cmd->callback([o] {
    const parix::RunOptions so = run_options(o->machine, kWholeMachine);
    const int iterations = o->iterations;
    const std::int64_t bytes = o->size;
    // Each node holds the message it sends, the one it receives and the runtime's copy in flight.
    const parix::SimulationOptions& sim = so.simulation;
    pipeline::check_node_memory({{"ring message", bytes}, {"received message", bytes}, {"message in flight", bytes}}, 0,
                                sim.config.memory_bytes, sim.memory_limit);
    pipeline::check_host_memory(pipeline::saturating_product(3 * std::int64_t(sim.config.nodes), bytes),
                                fmt::format("a ring of {} per message on {} nodes", machine::format_bytes(bytes),
                                            sim.config.nodes));
    parix::RunResult r = pipeline::run_program(so, [&](parix::Processor& p) { ring_exchange(p, iterations, bytes); }, o->machine);
    const double messages = static_cast<double>(r.total_messages());
    fmt::print("ring of {} processors, {} iterations of {} bytes: {} messages\n", r.nodes, iterations, bytes, r.total_messages());
    report_run(r, o->machine, {{"benchmark", "ring"}, {"messages_per_wall_s", messages / r.wall_seconds}});
    fmt::print("rate      {:.0f} simulated messages per wall second ({:.0f} events/s)\n", messages / r.wall_seconds,
               static_cast<double>(r.events) / r.wall_seconds);
  });
}

void add_demo(CommandGroups& g) {
  auto machine = std::make_shared<MachineOptions>();
  CLI::App* demo = g.app->add_subcommand("demo", "Small programs that show how the simulated runtime behaves");
  demo->require_subcommand(1);
  CLI::App* cmd = demo->add_subcommand("deadlock", "Two processors that both receive first: the deadlock report");
  cmd->footer(
      "Two processors open a link and both receive first, so neither ever sends. The run stops at once\n"
      "with a report naming each blocked processor, its call and its peer, and exits with status 5.");
  add_machine_options(cmd, *machine, "2");
  cmd->callback([machine] {
    const parix::RunOptions so = run_options(*machine, 2);
    parix::run(so, [](parix::Processor& p) {
      if (p.id() > 1) return;
      parix::Link l = p.connect(1 - p.id());
      p.recv(l);
      p.send(l, {});
    });
  });
}

}  // namespace

void add_machine_commands(CommandGroups& g) {
  add_topo(g);
  add_bcast(g);
  add_bench_ring(g);
  add_demo(g);
}

}  // namespace gcsim::cli
