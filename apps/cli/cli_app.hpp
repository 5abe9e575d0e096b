#pragma once
// The gcsim command line, apart from main() so that a fuzz target can parse command lines without
// running anything (tests/fuzz/fuzz_command_line.cpp).
#include <string>

#include <CLI/CLI.hpp>

namespace gcsim::cli {

std::string gcsim_description();
// Declares every command and option of gcsim on app; the work is done in the commands' callbacks.
void declare_commands(CLI::App* app);
// Parses and runs one command line; returns the exit code (apps/pipeline/failure.hpp).
int run_gcsim(int argc, char** argv);

}  // namespace gcsim::cli
