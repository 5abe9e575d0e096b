#pragma once
// The prediction flags gcsim calibrate, validate and accuracy network share: how each measured
// table's experiment is simulated (network model, hemicube, energy, the radiosity mechanisms the
// thesis's figures imply) and on how many host threads.
#include <algorithm>
#include <vector>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "apps/calibration/calibration.hpp"
#include "apps/radiosity/radiosity.hpp"

namespace gcsim::calibration::app {

namespace cal = gcsim::calibration;  // the library the family's commands drive

// The radiosity settings start as the thesis's program (radiosity::thesis_program(), what `gcsim
// run radiosity --preset thesis` runs); --preset chooses another, options given override it.
struct PredictFlags {
  PredictFlags() : PredictFlags(radiosity::thesis_program()) {}
  explicit PredictFlags(const radiosity::ProgramPreset& p)
      : preset(p.name), hemicube(p.hemicube), energy(p.energy), cell_assignment(to_string(p.cell_assignment)),
        side_faces(to_string(p.side_faces)), merge(to_string(p.merge)), ff_exchange(to_string(p.ff_exchange)),
        workload(to_string(p.workload)), comm_time(to_string(p.comm_time)) {}
  std::string model;
  std::string preset;
  int hemicube;
  double energy;
  std::string cell_assignment;
  std::string side_faces;
  std::string merge;
  std::string ff_exchange;
  std::string workload;
  std::string comm_time;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const CLI::App* command = nullptr;  // where they were parsed: which options were given
};

// Declares --model, --preset, --hemicube, --energy, the radiosity mechanism flags and --jobs on cmd.
void add_predict_options(CLI::App* cmd, PredictFlags& f);
// After parsing: the options not given take --preset's values. Call first in the command's callback.
void apply_preset(PredictFlags& f);

// The prediction flags that differ from their defaults, as a command line would give them, so that
// a fitted file's header names everything that reproduces the fit.
std::string non_default_flags(const PredictFlags& f);

cal::PredictionSettings settings(const PredictFlags& f);

// The CSV's first row for the plot's subtitle: the command, the machine, the node counts of the
// cells (e.g. "1-64") and the network model (model: --model, "" for the machine file's).
std::string cells_comment(const std::string& command, const machine::MachineConfig& c,
                          const std::vector<cal::CellComparison>& cells, const std::string& model);

// One line per scene matched to table 4.2 (--workload thesis-loops), each prefixed.
std::string workload_lines(const cal::Predictor& p, double energy, const std::string& prefix);

}  // namespace gcsim::calibration::app
