#pragma once
// gcsim sweep APP: the same experiment on several node counts. Every point is a fresh, independent
// simulation (its own kernel, network, trace writer and fibers), so points run on several host
// threads (--jobs); rows are printed and written in node-count order, identical to a sequential
// sweep except for the host's wall times.
#include <CLI/CLI.hpp>

#include "apps/pipeline/app_registry.hpp"

namespace gcsim::pipeline {

void add_sweep_command(CLI::App& sweep, const AppSpec& app);

}  // namespace gcsim::pipeline
