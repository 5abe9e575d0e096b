#include "apps/pipeline/machine_options.hpp"

#include <fstream>
#include <initializer_list>
#include <stdexcept>

#include <fmt/format.h>

#include "machine/machine_config.hpp"
#include "machine/output_file.hpp"
#include "machine/network_model.hpp"
#include "machine/node_memory.hpp"
#include "machine/trace.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "apps/pipeline/time_split.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::pipeline {

namespace {

// Help lists these under their own heading, after the command's own options.
void group_as_machine_options(CLI::App* cmd, std::initializer_list<const char*> names) {
  for (const char* name : names) cmd->get_option(name)->group("Machine and run");
}

}  // namespace

void add_machine_choice_options(CLI::App* cmd, MachineOptions& o) {
  add_backend_option(cmd, o.backend);
  add_config_option(cmd, o.config);
  add_model_option(cmd, o.model);
  cmd->add_option("--memory-limit", o.memory_limit,
                  "A node's memory (the machine file's memory_mb) exceeded: enforce (the run fails at once, naming the "
                  "processor and what it holds) or warn (the run goes on and reports the peak)")
      ->check(CLI::IsMember({"enforce", "warn"}))
      ->capture_default_str();
  group_as_machine_options(cmd, {"--backend", "--config", "--model", "--memory-limit"});
}

void add_machine_options(CLI::App* cmd, MachineOptions& o, std::string_view nodes_default) {
  add_machine_choice_options(cmd, o);
  add_nodes_option(cmd, o.nodes, nodes_default);
  cmd->add_option("--shape", o.shape,
                  "Sub-mesh WxH the N nodes occupy (e.g. 8x1: a row); default: the machine file's [topology.shapes] "
                  "entry, else the most nearly square shape the GC uses")
      ->needs("--nodes");
  add_trace_option(cmd, o.trace);
  cmd->add_option("--trace-level", o.trace_level, "summary (totals only), messages (no link records) or full")
      ->check(CLI::IsMember({"summary", "messages", "full"}))
      ->capture_default_str();
  add_json_option(cmd, o.json, "the run's simulated and wall times and counters");
  cmd->add_option("--host-threads", o.host_threads,
                  "Host threads for one simulated run: the simulation keeps one, the others compute ahead the work an "
                  "application can (radiosity and render's radiosity pass: each loop's hemicube cells; raytrace and "
                  "render's view: the tiles, except with --algo B1; media: each node's photons, the SH "
                  "grids and the image tiles; render's media pass: the photons and SH grids). Results, simulated times and "
                  "traces are the same for any count; only the wall time changes")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  group_as_machine_options(cmd, {"--nodes", "--shape", "--trace", "--trace-level", "--json", "--host-threads"});
}

parix::SimulationOptions simulation_options(const MachineOptions& o, int default_nodes) {
  parix::SimulationOptions s;
  s.config = o.config.empty() ? machine::default_machine_config() : machine::load_machine_config(o.config);
  if (o.nodes > s.config.nodes)  // a usage error, before with_nodes reports it against the machine file
    throw std::invalid_argument(fmt::format("--nodes {}: machine '{}' has {} nodes (expected 1..{})", o.nodes,
                                            s.config.name, s.config.nodes, s.config.nodes));
  const int n = o.nodes > 0 ? o.nodes : std::min(default_nodes, s.config.nodes);
  std::optional<machine::MeshShape> shape;
  if (!o.shape.empty()) shape = machine::parse_mesh_shape(o.shape);
  // A --shape that cannot hold the nodes is the command line's mistake, not the machine file's.
  if (shape && std::int64_t(shape->width) * shape->height != n)
    throw std::invalid_argument(fmt::format("--shape {}: {}x{} = {} nodes, but the run has {} (--nodes); expected width * "
                                            "height == nodes",
                                            o.shape, shape->width, shape->height,
                                            std::int64_t(shape->width) * shape->height, n));
  if (shape && (shape->width > s.config.mesh_width || shape->height > s.config.mesh_height))
    throw std::invalid_argument(fmt::format("--shape {}: does not fit in machine '{}', a {}x{} mesh", o.shape,
                                            s.config.name, s.config.mesh_width, s.config.mesh_height));
  s.config = machine::with_nodes(s.config, n, shape);
  if (!o.model.empty()) s.config.network_model = o.model;
  s.memory_limit = machine::parse_memory_limit(o.memory_limit);
  s.trace.path = o.trace;
  s.trace.level = machine::parse_trace_level(o.trace_level);
  s.trace.machine = fmt::format("{}, network model {}", s.config.name, s.config.network_model);
  return s;
}

parix::RunOptions run_options(const MachineOptions& o, int default_nodes) {
  parix::RunOptions r;
  r.backend = o.backend;
  r.simulation = simulation_options(o, default_nodes);
  if (o.host_threads > 1 && o.backend != "simulated")
    throw std::invalid_argument(fmt::format("--host-threads {}: for the simulated backend only; under --backend {} every "
                                            "rank is a process of its own (start more ranks instead)",
                                            o.host_threads, o.backend));
  r.host_threads = o.host_threads;
  return r;
}

void check_machine_outputs(const MachineOptions& o) {
  check_writable(o.json, "--json");
  check_writable(o.trace, "--trace");  // its .csv and .paje go beside it, in the same directory
}

void report_interrupted_run(const parix::RunResult& partial, const MachineOptions& o, const nlohmann::json& reached,
                            const RunInputs& inputs) {
  fmt::print("interrupted at simulated time {:.6f} s ({} events, wall {:.3f} s)\n", partial.simulated_seconds(),
             partial.events, partial.wall_seconds);
  for (const auto& [key, value] : reached.items()) fmt::print("reached   {} {}\n", key, value.dump());
  if (!o.trace.empty()) fmt::print("trace     {} (closed at the interruption; .csv, .paje beside it)\n", o.trace);
  if (o.json.empty()) return;
  nlohmann::json j = partial.to_json();
  j["interrupted"] = true;
  j["finished"] = false;  // the program's results were not complete, so none are reported
  if (!reached.empty()) j["reached"] = reached;
  if (!o.trace.empty()) {
    j["trace"] = o.trace;
    j["trace_level"] = o.trace_level;
  }
  j["provenance"] = run_provenance(o, partial.config_name, inputs);
  write_json_file(o.json, j);
  fmt::print("json      {}\n", o.json);
}

parix::RunResult run_program(const parix::RunOptions& options, const parix::Program& program, const MachineOptions& o) {
  check_machine_outputs(o);
  try {
    return parix::run(options, program);
  } catch (const parix::host::Interrupted& x) {
    report_interrupted_run(x.partial(), o);
    throw;
  }
}

void write_json_file(const std::string& path, const nlohmann::json& j) {
  machine::write_text_file(path, j.dump(2) + "\n", "JSON file");
}

void report_run(const parix::RunResult& r, const MachineOptions& o, const nlohmann::json& extra, const RunInputs& inputs) {
  fmt::print("machine   {} ({} nodes, {} network)\n", r.config_name, r.nodes, r.model);
  // A real run (the MPI backend) measured its times on the host: say so instead of "simulated".
  const bool real = r.clock == parix::Clock::wall;
  fmt::print("{} {:12.6f} s   ({})\n", real ? "measured " : "simulated", r.simulated_seconds(), time_split(r));
  fmt::print("wall      {:12.6f} s   ({} events, {} messages{})\n", r.wall_seconds, r.events, r.total_messages(),
             o.host_threads > 1 ? fmt::format(", {} host threads", o.host_threads) : "");
  if (!r.memory_warning.empty()) {
    fmt::print("memory    over the node's memory (--memory-limit warn): peak {} on processor {}'s node of {}; first: {}\n",
               machine::format_bytes(r.memory_peak), r.memory_peak_processor, machine::format_bytes(r.memory_capacity),
               r.memory_warning);
  }
  if (!o.trace.empty()) fmt::print("trace     {} (and .csv, .paje beside it)\n", o.trace);
  if (!o.json.empty()) {
    nlohmann::json j = r.to_json();
    j["wall"]["host_threads"] = o.host_threads;  // beside the wall time: the host's side of the run
    if (!o.trace.empty()) {
      j["trace"] = o.trace;  // lets `gcsim report RUN.json` find the trace to plot
      j["trace_level"] = o.trace_level;
    }
    j.update(extra);
    j["provenance"] = run_provenance(o, r.config_name, inputs);
    write_json_file(o.json, j);
    fmt::print("json      {}\n", o.json);
  }
}

}  // namespace gcsim::pipeline
