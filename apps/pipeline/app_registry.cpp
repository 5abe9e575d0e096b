#include "apps/pipeline/app_registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "apps/pipeline/run_command.hpp"
#include "apps/pipeline/sweep_command.hpp"

namespace gcsim::pipeline {

namespace {

// A function-local static: registrars in other files may run before this file's statics.
std::vector<AppSpec>& registry() {
  static std::vector<AppSpec> apps;
  return apps;
}

}  // namespace

void register_app(AppSpec spec) {
  if (spec.name.empty() || spec.summary.empty() || !spec.options)
    throw std::logic_error("gcsim: an application must register a name, a summary and its options");
  for (const AppSpec& a : registry())
    if (a.name == spec.name) throw std::logic_error("gcsim: application '" + spec.name + "' registered twice");
  registry().push_back(std::move(spec));
}

std::vector<const AppSpec*> registered_apps() {
  std::vector<const AppSpec*> apps;
  for (const AppSpec& a : registry()) apps.push_back(&a);
  std::sort(apps.begin(), apps.end(), [](const AppSpec* a, const AppSpec* b) { return a->name < b->name; });
  return apps;
}

void add_app_commands(CommandGroups& g) {
  for (const AppSpec* app : registered_apps()) {
    add_run_command(*g.run, *app);
    add_sweep_command(*g.sweep, *app);
  }
  for (const AppSpec* app : registered_apps())
    if (app->commands) app->commands(g);
}

}  // namespace gcsim::pipeline
