#pragma once
// The radiosity solver's command-line options (shared by run and sweep) and what they become.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity::app {

// The settings a preset covers (program_preset.hpp) start as gcsim's own program's; apply_preset
// lays the chosen preset under the options given.
struct SolveFlags {
  std::string preset = "gcsim";
  std::string workload = "as-built";  // Workload
  std::string comm_time = "mean";     // CommTimeOf: whose communication time the reports put next to table 4.5
  std::vector<std::string> preset_overridden;  // the preset's options given explicitly (apply_preset)
  std::string scene = "cornell";
  int hemicube = 256;
  int shooters = 2;
  double energy = 0.999;
  std::string parallel = "hemicube-fixed";
  std::string bcast = "sequential";
  bool aggregate = false;
  bool keep_links = false;
  int levels = 3;
  int cells = 8;
  std::string cell_assignment = "cyclic";
  std::string side_faces = "half";
  std::string merge = "own-cells";
  std::string ff_exchange = "per-shooter";
  int near_field_samples = 2;   // HemicubeOptions::max_shooter_samples
  double near_field_ratio = 1.0;
  bool each_node_projects = false;  // ParallelOptions::share_projections off
  int max_steps = 1000000;
  std::string order = "energy";
  double sort_until = 0.9;
};

void add_solve_options(CLI::App* cmd, SolveFlags& f);
// After parsing: the preset's settings for every option cmd was not given; those given go to
// f.preset_overridden.
void apply_preset(const CLI::App& cmd, SolveFlags& f);
// Checks the hemicube / partition combination (throws with the reason) and converts.
ParallelOptions parallel_options(const SolveFlags& f);
// "ex,ey,ez,tx,ty,tz[,fov]"
Camera parse_camera(const std::string& s);

}  // namespace gcsim::radiosity::app
