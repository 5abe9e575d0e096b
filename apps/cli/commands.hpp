#pragma once
// The gcsim command line is assembled from command families, each in its own file
// (machine_commands.cpp, radiosity_commands.cpp, raytrace_commands.cpp, trace_commands.cpp).
// A family adds subcommands under the shared verbs below; e.g. `gcsim run radiosity` is added by
// the radiosity family to `run`. A subcommand does its work in its CLI11 callback.
#include <CLI/CLI.hpp>

namespace gcsim::cli {

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

void add_machine_commands(CommandGroups& g);
#ifdef GCSIM_HAVE_RADIOSITY_COMMANDS
void add_radiosity_commands(CommandGroups& g);
#endif
#ifdef GCSIM_HAVE_RAYTRACE_COMMANDS
void add_raytrace_commands(CommandGroups& g);
#endif
#ifdef GCSIM_HAVE_TRACE_COMMANDS
void add_trace_commands(CommandGroups& g);
#endif
#ifdef GCSIM_HAVE_MEDIA_COMMANDS
void add_media_commands(CommandGroups& g);  // in apps/media/commands.cpp
#endif

}  // namespace gcsim::cli
