#pragma once
// gcsim bench threads APP: what --host-threads buys on this host. The application's run, on one
// host thread and on T, alternately for R rounds (the one-thread run is the anchor of each round),
// checking that every run gives the same simulated time and events; prints each round's wall
// times and their ratio, and the medians.
#include <CLI/CLI.hpp>

#include "apps/pipeline/app_registry.hpp"

namespace gcsim::pipeline {

void add_bench_threads_command(CLI::App& threads, const AppSpec& app);

}  // namespace gcsim::pipeline
