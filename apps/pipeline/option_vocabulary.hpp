#pragma once
// The options many commands share (--config, --model, --nodes, --json, --trace, --backend), each
// declared in one place so that every command checks it the same way and describes it in the same
// words. Lists of models, topologies and backends in help texts are written from their registries,
// so a model or topology added is offered everywhere without a help text going stale.
//
// Output paths (--json, --trace) are not checked here: a command checks them with check_writable
// (failure.hpp) before its work starts, so that an unwritable path is a file error, not a usage one.
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

namespace gcsim::pipeline {

// Largest --nodes any command accepts; the machine file then bounds it (64 on the GC).
inline constexpr int kMaxNodes = 1 << 20;

// --config FILE: an existing machine file. `what` says what the file is for; the help adds that
// without the option the built-in GC-PowerPlus is used.
CLI::Option* add_config_option(CLI::App* cmd, std::string& path, std::string_view what = "Machine file (configs/*.toml)");

// --model NAME: one of the registered network models, each listed with its summary. `what` names
// what the model is used for; `unset` what applies without the option.
CLI::Option* add_model_option(CLI::App* cmd, std::string& model, std::string_view what = "Network model",
                              std::string_view unset = "the machine file's");

// --nodes N: a decimal count in 1..max (CLI11 would read 010 as octal 8 and 0x10 as 16). The help
// says how the first N nodes of the machine are used; `what_default` what applies without it.
CLI::Option* add_nodes_option(CLI::App* cmd, int& nodes, std::string_view what_default, int max = kMaxNodes);

// --json FILE: "Write <what> as JSON".
CLI::Option* add_json_option(CLI::App* cmd, std::string& path, std::string_view what);

// --trace FILE: a trace of the simulated events (JSON, with .csv and .paje beside it).
CLI::Option* add_trace_option(CLI::App* cmd, std::string& path);

// --backend NAME: one of the backends this build has, each listed with its summary.
CLI::Option* add_backend_option(CLI::App* cmd, std::string& backend);

// "a, b or c" and "a, b and c": for help texts listing names.
std::string or_list(const std::vector<std::string>& names);
std::string and_list(const std::vector<std::string>& names);
// "analytic: latency + ...; flow: ...; packet: ...": every network model with its summary.
std::string network_model_summaries();
// "mesh, torus, ring, tree or hypercube": every registered topology.
std::string topology_choices();

// A comma-separated list of network models (--models): each item a registered one.
CLI::Validator each_network_model();

// A transform for whole-number options: a plain decimal integer (leading zeros dropped, so 010 is
// ten), anything else ("0x10", "1e3", "8 nodes") a usage error naming the value.
CLI::Validator decimal_integer();

}  // namespace gcsim::pipeline
