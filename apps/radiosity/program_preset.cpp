#include "apps/radiosity/program_preset.hpp"

#include <array>
#include <stdexcept>

namespace gcsim::radiosity {

namespace {

// The thesis's program, each choice with the figures that imply it in docs/calibration.md.
constexpr ProgramPreset kThesis{
    .name = "thesis",
    .summary = "the thesis's program: K = 2, blocks of cells from five equal faces, fixed merge arrays, two exchanges "
               "per loop, scenes matched to table 4.2's loops",
    .hemicube = 256,
    .shooters = 2,                                       // 3.5.2
    .energy = 0.999,                                     // tables 4.3-4.8 run to 99.9 %
    .cell_assignment = CellAssignment::block,            // figure 4.1
    .side_faces = SideFaces::full,                       // node 0's share on 2, 4, 8 nodes
    .merge = FormFactorMerge::fixed_arrays,              // tables 4.5 with 4.8, and 4.2 with 4.5
    .ff_exchange = FormFactorExchange::together,         // 4.4.1: two synchronizations per loop
    .workload = Workload::thesis_loops,                  // table 4.2
    .comm_time = CommTimeOf::root,
};

constexpr ProgramPreset kGcsim{
    .name = "gcsim",
    .summary = "gcsim's own program: cells dealt cyclically, half side faces, each part merged over its own cells, "
               "each shooter exchanged alone, the scenes as built",
};

constexpr std::array<const ProgramPreset*, 2> kPresets = {&kGcsim, &kThesis};

}  // namespace

Workload parse_workload(const std::string& s) {
  if (s == "as-built") return Workload::as_built;
  if (s == "thesis-loops") return Workload::thesis_loops;
  throw std::invalid_argument("workload '" + s + "': expected as-built or thesis-loops");
}

const char* to_string(Workload w) { return w == Workload::as_built ? "as-built" : "thesis-loops"; }

CommTimeOf parse_comm_time_of(const std::string& s) {
  if (s == "root") return CommTimeOf::root;
  if (s == "mean") return CommTimeOf::mean;
  throw std::invalid_argument("comm time of '" + s + "': expected root or mean");
}

const char* to_string(CommTimeOf c) { return c == CommTimeOf::root ? "root" : "mean"; }

const ProgramPreset& gcsim_program() { return kGcsim; }
const ProgramPreset& thesis_program() { return kThesis; }

const ProgramPreset& program_preset(std::string_view name) {
  for (const ProgramPreset* p : kPresets)
    if (p->name == name) return *p;
  std::string names;
  for (const ProgramPreset* p : kPresets) names += (names.empty() ? "" : ", ") + std::string(p->name);
  throw std::invalid_argument("preset '" + std::string(name) + "': expected one of " + names);
}

std::vector<std::string> program_preset_names() {
  std::vector<std::string> names;
  for (const ProgramPreset* p : kPresets) names.emplace_back(p->name);
  return names;
}

}  // namespace gcsim::radiosity
