#pragma once
// Named presets of the radiosity program: the choices with which `gcsim run radiosity`, `gcsim
// sweep radiosity`, `gcsim validate` and `gcsim calibrate` run one and the same program.
// - `gcsim`: the simulator's own program (the run and sweep defaults): cells dealt cyclically,
//   half side faces, each part merged over its own cells, each shooter exchanged alone, the
//   scenes as built. Even work per node and little merging: faster than the thesis's.
// - `thesis`: the program the thesis's text and tables describe (docs/calibration.md), which
//   the default machine (configs/gc-powerplus-calibrated.toml) was fitted with: blocks of cells
//   cut from five equal faces, fixed merge arrays, two exchanges per loop, each built-in scene's
//   reflectances scaled to take table 4.2's loops, table 4.5 read on the root.
// Options given explicitly on a command line override its preset's settings.
#include <string>
#include <string_view>
#include <vector>

#include "apps/radiosity/cell_assignment.hpp"
#include "apps/radiosity/form_factor_exchange.hpp"
#include "apps/radiosity/form_factor_merge.hpp"

namespace gcsim::radiosity {

// Which scene a run solves: as built, or a built-in scene matched to table 4.2's loops
// (thesis_workload.hpp: every reflectance times one factor).
enum class Workload { as_built, thesis_loops };
Workload parse_workload(const std::string& s);  // "as-built", "thesis-loops"; throws std::invalid_argument
const char* to_string(Workload w);

// Whose communication time stands for a run's next to table 4.5 (the thesis does not say): the
// root's (processor 0, which every exchange gathers to and scatters from) or the processors' mean.
enum class CommTimeOf { mean, root };
CommTimeOf parse_comm_time_of(const std::string& s);  // "mean", "root"; throws std::invalid_argument
const char* to_string(CommTimeOf c);

struct ProgramPreset {
  std::string_view name;
  std::string_view summary;  // one line for help texts and run headers
  int hemicube = 256;
  int shooters = 2;
  double energy = 0.999;
  CellAssignment cell_assignment = CellAssignment::cyclic;
  SideFaces side_faces = SideFaces::half;
  FormFactorMerge merge = FormFactorMerge::own_cells;
  FormFactorExchange ff_exchange = FormFactorExchange::per_shooter;
  Workload workload = Workload::as_built;
  CommTimeOf comm_time = CommTimeOf::mean;
};

// Lays preset p under a command's flags: each setting whose option was not given on the command
// line (given("--side-faces") false) takes the preset's value; returns the options that were
// given, which override it. Flags: a struct with members hemicube, energy, cell_assignment,
// side_faces, merge, ff_exchange, workload, comm_time (strings for the choices) and optionally
// shooters, as the radiosity and calibration commands declare them.
template <class Flags, class Given>
std::vector<std::string> apply_program_preset(const ProgramPreset& p, Flags& f, Given&& given) {
  std::vector<std::string> overridden;
  auto set = [&](const char* option, auto& member, const auto& value) {
    if (given(option)) overridden.emplace_back(option);
    else member = value;
  };
  set("--hemicube", f.hemicube, p.hemicube);
  if constexpr (requires { f.shooters; }) set("--shooters", f.shooters, p.shooters);
  set("--energy", f.energy, p.energy);
  set("--cell-assignment", f.cell_assignment, to_string(p.cell_assignment));
  set("--side-faces", f.side_faces, to_string(p.side_faces));
  set("--ff-merge", f.merge, to_string(p.merge));
  set("--ff-exchange", f.ff_exchange, to_string(p.ff_exchange));
  set("--workload", f.workload, to_string(p.workload));
  set("--comm-time", f.comm_time, to_string(p.comm_time));
  return overridden;
}

const ProgramPreset& gcsim_program();
const ProgramPreset& thesis_program();
// By name; throws std::invalid_argument naming the presets.
const ProgramPreset& program_preset(std::string_view name);
std::vector<std::string> program_preset_names();

}  // namespace gcsim::radiosity
