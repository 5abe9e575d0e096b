#pragma once
// gcsim run APP: the application's options next to the machine options, one run, its report.
#include <CLI/CLI.hpp>

#include "apps/pipeline/app_registry.hpp"

namespace gcsim::pipeline {

void add_run_command(CLI::App& run, const AppSpec& app);

}  // namespace gcsim::pipeline
