// The gcsim command line: every command declared on one CLI::App, and running it with one way to fail.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <exception>

#include <fmt/format.h>

#include "apps/cli/cli_app.hpp"
#include "apps/cli/commands.hpp"
#include "apps/cli/errors.hpp"
#include "apps/cli/interrupt_signals.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/pipeline/shared_files.hpp"
#include "apps/pipeline/run_provenance.hpp"
#include "apps/pipeline/app_registry.hpp"
#include "apps/pipeline/version.hpp"

namespace gcsim::cli {

namespace {

// The first sentence of a description, on one line: up to a full stop followed by a capital, a
// digit or the end (not after a short abbreviation such as "ch."), or a colon outside parentheses; at most ~100 characters.
std::string first_sentence(std::string d) {
  std::replace(d.begin(), d.end(), '\n', ' ');
  int depth = 0;
  std::size_t cut = d.size();
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (d[i] == '(') ++depth;
    if (d[i] == ')') --depth;
    bool sentence_end = false;
    if (d[i] == '.') {
      std::size_t next = i + 1;
      while (next < d.size() && d[next] == ' ') ++next;
      std::size_t word = i;
      while (word > 0 && std::isalpha(static_cast<unsigned char>(d[word - 1]))) --word;
      const bool abbreviation = i - word <= 2 && i > word && std::islower(static_cast<unsigned char>(d[word]));
      sentence_end = next == d.size() || (next > i + 1 && !abbreviation && !std::islower(static_cast<unsigned char>(d[next])));
    }
    const bool colon = d[i] == ':' && depth == 0 && i + 1 < d.size() && d[i + 1] == ' ';
    if (sentence_end || colon) {
      cut = i;
      break;
    }
  }
  d = d.substr(0, cut);
  constexpr std::size_t kMax = 100;
  if (d.size() > kMax) d = d.substr(0, d.rfind(' ', kMax)) + " ...";
  return d;
}

// Command lists show one line per command; a longer description moves into the command's own help.
void summarize_descriptions(CLI::App* app) {
  for (CLI::App* sub : app->get_subcommands({})) {
    const std::string d = sub->get_description();
    if (d.find('\n') != std::string::npos) {
      sub->footer("\n" + d + sub->get_footer());
      sub->description(first_sentence(d));
    }
    summarize_descriptions(sub);
  }
}

}  // namespace

std::string gcsim_description() {
  return
      "gcsim simulates the Parsytec GC-PowerPlus, a 64-node distributed-memory machine of the 1990s\n"
      "(PowerPC 601 nodes, T805 transputer links, 2D mesh), under a PARIX-like message-passing API,\n"
      "and runs parallel graphics applications on it. Every run reports the simulated machine's time\n"
      "next to the host's wall-clock time.\n\n"
      "Machines are described in topology files (configs/*.toml); without --config the built-in\n"
      "GC-PowerPlus as measured is used (configs/gc-powerplus-calibrated.toml, fitted to the thesis's\n"
      "tables; configs/gc-powerplus.toml is the GC as published). `gcsim COMMAND --help` explains each command.";
}

void declare_commands(CLI::App* app) {
  app->set_version_flag("--version", std::string(pipeline::version_line()));
  app->require_subcommand(1);
  CommandGroups g{app};
  g.run = app->add_subcommand("run", "Run an application on the simulated machine");
  g.sweep = app->add_subcommand("sweep", "Run an application for several node counts: time, speedup, communication");
  g.table = app->add_subcommand("table", "Reproduce a paper's table next to the published figures");
  g.accuracy = app->add_subcommand("accuracy", "What accuracy costs: error against reference next to time");
  g.bench = app->add_subcommand("bench", "Measure the host's speed (simulated events or rays per wall second)");
  g.scene = app->add_subcommand("scene", "Information about built-in and file scenes");
  for (CLI::App* verb : {g.run, g.sweep, g.table, g.accuracy, g.bench, g.scene}) verb->require_subcommand(1);

  add_machine_commands(g);
  pipeline::add_app_commands(g);  // run APP, sweep APP, every app's commands and command family's (calibrate, ...)
  add_trace_commands(g);
  add_help_command(app);
  summarize_descriptions(app);
  pipeline::reject_non_finite_numbers(app);
  pipeline::refuse_shared_files(app);
  // Verbs that no application or command family filled in are hidden rather than offered empty.
  for (CLI::App* verb : {g.run, g.sweep, g.table, g.accuracy, g.bench, g.scene}) {
    if (verb->get_subcommands({}).empty()) app->remove_subcommand(verb);
  }

  app->footer(
      "\nExamples:\n"
      "  gcsim topo --topology hypercube --nodes 64        thesis table 2.1 parameters, exact and by formula\n"
      "  gcsim bcast --nodes 64 --size 16KB --algo tree    one all-node broadcast (thesis 4.4.2)\n"
      "  gcsim bcast --table                               the whole grid next to thesis tables 4.6/4.7\n"
      "  gcsim bench ring --nodes 64 --iterations 2000     kernel throughput in simulated messages/s\n" +
      pipeline::app_examples(50) +  // each registered application's own lines
      "  gcsim plot t.json --out plots/                    pictures of a trace written with --trace t.json\n\n" +
      pipeline::exit_code_table());
  // (after the subcommands exist, so they do not inherit it)
}

int run_gcsim(int argc, char** argv) {
  CLI::App app{gcsim_description(), "gcsim"};
  declare_commands(&app);
  install_interrupt_handlers();
  pipeline::remember_command_line(argc, argv);  // for every run JSON's provenance block
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --help-all
    pipeline::print_error(std::string(e.what()) + "\nRun with --help for more information.");
    return pipeline::kExitUsage;
  } catch (...) {
    return report_failure(std::current_exception());
  }
  return pipeline::kExitOk;
}

}  // namespace gcsim::cli
