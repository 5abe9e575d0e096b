#pragma once
// Options and reporting shared by every command that runs something on the simulated machine.
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "parix/backend.hpp"
#include "parix/run_result.hpp"
#include "apps/pipeline/run_provenance.hpp"

namespace gcsim::pipeline {

struct MachineOptions {
  std::string backend = "simulated";  // parix::backend_names()
  std::string config;                 // "" : the built-in GC-PowerPlus (configs/gc-powerplus.toml)
  int nodes = 0;                      // 0 : the command's default
  std::string shape;                  // "" : the machine file's shape for that many nodes
  std::string model;                  // "" : the config's network model
  std::string trace;                  // trace file (.json, with .csv beside it)
  std::string trace_level = "full";
  std::string json;                   // where to write the run's JSON summary
  std::string memory_limit = "enforce";  // a node's memory exceeded: enforce (fail) or warn
  int host_threads = 1;                  // parix::RunOptions::host_threads
};

// Adds the choice options below and --nodes, --shape, --trace, --trace-level, --json and
// --host-threads to cmd; `nodes_default` says in --nodes's help what runs without it.
void add_machine_options(CLI::App* cmd, MachineOptions& o, std::string_view nodes_default);
// Adds only --backend, --config, --model and --memory-limit: for commands that run several node counts (sweeps).
// Each option is declared by option_vocabulary.hpp, as every other command's of that name.
void add_machine_choice_options(CLI::App* cmd, MachineOptions& o);
// Loads the config (or the built-in one) restricted to o.nodes (or default_nodes) nodes.
parix::SimulationOptions simulation_options(const MachineOptions& o, int default_nodes);
// The backend and simulation options of one run on o.nodes (or default_nodes) nodes.
parix::RunOptions run_options(const MachineOptions& o, int default_nodes);
// Prints "simulated X s   wall Y s ..." and, with --json, writes result.to_json() merged with extra
// and the run's provenance (run_provenance.hpp; inputs: what the application read and wrote).
void report_run(const parix::RunResult& r, const MachineOptions& o, const nlohmann::json& extra = {},
                const RunInputs& inputs = {});
// Checks that --json and --trace can be written, before the run (throws FileError).
void check_machine_outputs(const MachineOptions& o);
// An interrupted run: the simulated time reached on stdout, and --json with "interrupted": true,
// the figures so far and no application results.
// `reached`: what the program had finished (Experiment::report_interrupted), printed and put in
// --json as "reached".
void report_interrupted_run(const parix::RunResult& partial, const MachineOptions& o,
                            const nlohmann::json& reached = nlohmann::json::object(), const RunInputs& inputs = {});
// parix::run with o's output paths checked first and an interruption reported as above (then
// parix::host::Interrupted is rethrown, for the interrupted exit code).
parix::RunResult run_program(const parix::RunOptions& options, const parix::Program& program, const MachineOptions& o);
// Writes JSON to a file, failing with a clear message.
void write_json_file(const std::string& path, const nlohmann::json& j);

}  // namespace gcsim::pipeline
