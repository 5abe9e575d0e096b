#include "apps/pipeline/app_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "apps/pipeline/bench_threads_command.hpp"
#include "apps/pipeline/run_command.hpp"
#include "apps/pipeline/sweep_command.hpp"

namespace gcsim::pipeline {

namespace {

// A function-local static: registrars in other files may run before this file's statics.
std::vector<AppSpec>& registry() {
  static std::vector<AppSpec> apps;
  return apps;
}
std::vector<CommandFamilySpec>& families() {
  static std::vector<CommandFamilySpec> f;
  return f;
}

bool name_taken(const std::string& name) {
  return std::ranges::any_of(registry(), [&](const AppSpec& a) { return a.name == name; }) ||
         std::ranges::any_of(families(), [&](const CommandFamilySpec& f) { return f.name == name; });
}

}  // namespace

void register_app(AppSpec spec) {
  if (spec.name.empty() || spec.summary.empty() || !spec.options)
    throw std::logic_error("gcsim: an application must register a name, a summary and its options");
  if (name_taken(spec.name)) throw std::logic_error("gcsim: application '" + spec.name + "' registered twice");
  registry().push_back(std::move(spec));
}

void register_command_family(CommandFamilySpec spec) {
  if (spec.name.empty() || !spec.commands)
    throw std::logic_error("gcsim: a command family must register a name and its commands");
  if (name_taken(spec.name)) throw std::logic_error("gcsim: command family '" + spec.name + "' registered twice");
  families().push_back(std::move(spec));
}

std::vector<const AppSpec*> registered_apps() {
  std::vector<const AppSpec*> apps;
  for (const AppSpec& a : registry()) apps.push_back(&a);
  std::sort(apps.begin(), apps.end(), [](const AppSpec* a, const AppSpec* b) { return a->name < b->name; });
  return apps;
}

std::string app_examples(std::size_t width) {
  std::string out;
  for (const AppSpec* app : registered_apps())
    for (const std::string& line : app->examples) {
      const std::size_t split = line.find("  ");  // "command  what it shows"
      const std::string command = line.substr(0, split);
      const std::string what = split == std::string::npos ? "" : line.substr(line.find_first_not_of(' ', split));
      out += "  " + command;
      if (!what.empty()) out += std::string(command.size() + 2 <= width ? width - command.size() : 2, ' ') + what;
      out += "\n";
    }
  return out;
}

void add_app_commands(CommandGroups& g) {
  CLI::App* threads = nullptr;
  if (g.bench) {
    threads = g.bench->add_subcommand("threads", "What --host-threads buys: an application's run on 1 host thread and on T");
    threads->require_subcommand(1);
  }
  for (const AppSpec* app : registered_apps()) {
    add_run_command(*g.run, *app);
    add_sweep_command(*g.sweep, *app);
    if (threads) add_bench_threads_command(*threads, *app);
  }
  for (const AppSpec* app : registered_apps())
    if (app->commands) app->commands(g);
  std::vector<const CommandFamilySpec*> sorted;
  for (const CommandFamilySpec& f : families()) sorted.push_back(&f);
  std::ranges::sort(sorted, {}, &CommandFamilySpec::name);
  for (const CommandFamilySpec* f : sorted) f->commands(g);
}

}  // namespace gcsim::pipeline
