#pragma once
// The applications gcsim knows: each registers itself from its own folder, and the gcsim command,
// `gcsim run APP`, `gcsim sweep APP`, the reports and CMake find it here. Registering an app:
//
//   // apps/NAME/app/NAME_app.cpp
//   namespace {
//   gcsim::pipeline::AppSpec make_spec() {
//     gcsim::pipeline::AppSpec s;
//     s.name = "NAME";
//     s.summary = "What `gcsim run NAME` does, in one sentence.";
//     s.options = [](CLI::App& cmd, gcsim::pipeline::Verb verb) {
//       auto flags = std::make_shared<Flags>();          // the app's options, declared on cmd
//       cmd.add_option("--scene", flags->scene, "...");
//       return [flags] { return std::make_unique<MyExperiment>(*flags); };  // called after parsing
//     };
//     return s;
//   }
//   const gcsim::pipeline::AppRegistrar registrar{make_spec()};
//   }  // namespace
//
// and apps/NAME/CMakeLists.txt calls gcsim_add_app(NAME NAME SOURCES app/NAME_app.cpp LIBS ...).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/pipeline/command_groups.hpp"
#include "apps/pipeline/experiment.hpp"

namespace gcsim::pipeline {

// Which command the application's options are declared for.
enum class Verb { run, sweep };

// Called after the command line is parsed: loads and checks the scene, returns the experiment.
// Bad input throws (std::invalid_argument, CLI::ValidationError) with a message naming it.
using ExperimentFactory = std::function<std::unique_ptr<Experiment>()>;

struct AppSpec {
  std::string name;          // gcsim run NAME, gcsim sweep NAME
  std::string summary;       // description of `run NAME`; its first sentence is shown in lists
  std::string run_footer;    // e.g. examples, shown at the end of `run NAME --help`
  std::string sweep_summary; // description of `sweep NAME` (default: a generic one)
  std::string sweep_footer;
  // Lines for the examples of `gcsim --help`: a command, then what it shows (may be empty).
  std::vector<std::string> examples;
  int default_nodes = 1;     // node count of `run NAME` without --nodes
  // Declares the application's own options on `run NAME` or `sweep NAME` (the pipeline adds the
  // machine options, --nodes, --json, ...) and returns the factory of its experiment.
  std::function<ExperimentFactory(CLI::App& cmd, Verb verb)> options;
  // Further commands under the shared verbs (table, accuracy, bench, scene); may be empty.
  std::function<void(CommandGroups& g)> commands;
};

// Adds an application; throws std::logic_error if the name is taken or a field is missing.
void register_app(AppSpec spec);

// A static object of this type in an app's source registers it before main() runs.
struct AppRegistrar {
  explicit AppRegistrar(AppSpec spec) { register_app(std::move(spec)); }
};

// Every registered application, sorted by name (registration order across files is unspecified).
std::vector<const AppSpec*> registered_apps();

// A family of commands that is not an application (nothing to `run` or `sweep`) but lives in its own
// folder under apps/ and registers itself the same way, e.g. calibration's calibrate, validate and
// `accuracy network`, which drive other apps' programs. Its folder calls gcsim_add_app like an app.
struct CommandFamilySpec {
  std::string name;
  std::function<void(CommandGroups& g)> commands;
};
// Throws std::logic_error if the name is taken (by a family or an application) or a field is missing.
void register_command_family(CommandFamilySpec spec);
struct CommandFamilyRegistrar {
  explicit CommandFamilyRegistrar(CommandFamilySpec spec) { register_command_family(std::move(spec)); }
};

// Every registered application's example lines for `gcsim --help`, each command padded to `width`.
std::string app_examples(std::size_t width);

// Adds `run NAME` and `sweep NAME` for every registered application, then the applications' own
// commands, then every command family's, each in order of name.
void add_app_commands(CommandGroups& g);

}  // namespace gcsim::pipeline
