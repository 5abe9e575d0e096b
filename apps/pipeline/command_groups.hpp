#pragma once
// The verbs of the gcsim command line. `run APP` and `sweep APP` are made by the pipeline for every
// registered application (app_registry.hpp); an application's further commands (tables, accuracy,
// benchmarks, scene information) and the machine and trace commands add subcommands under these
// verbs. A subcommand does its work in its CLI11 callback.
#include <CLI/CLI.hpp>

namespace gcsim::pipeline {

struct CommandGroups {
  CLI::App* app = nullptr;       // gcsim itself (for top-level commands such as topo, bcast, plot)
  CLI::App* run = nullptr;       // gcsim run APP ...
  CLI::App* sweep = nullptr;     // gcsim sweep APP ...   (node-count sweeps)
  CLI::App* table = nullptr;     // gcsim table APP ...   (paper tables)
  CLI::App* accuracy = nullptr;  // gcsim accuracy APP ...(what accuracy costs)
  CLI::App* bench = nullptr;     // gcsim bench WHAT ...  (host speed)
  CLI::App* scene = nullptr;     // gcsim scene ...       (scene information)
};

// A subcommand that must end the process with a given status throws this.
struct ExitStatus {
  int code;
};

}  // namespace gcsim::pipeline
