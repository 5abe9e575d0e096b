#pragma once
// The prediction flags gcsim calibrate, validate and accuracy network share: how each measured
// table's experiment is simulated (network model, hemicube, energy, the radiosity mechanisms the
// thesis's figures imply) and on how many host threads.
#include <algorithm>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "apps/calibration/calibration.hpp"

namespace gcsim::calibration::app {

namespace cal = gcsim::calibration;  // the library the family's commands drive

struct PredictFlags {
  std::string model;
  int hemicube = 256;
  double energy = 0.999;
  std::string cell_assignment = "block";
  std::string side_faces = "full";
  std::string merge = "fixed-arrays";
  std::string ff_exchange = "together";
  std::string workload = "thesis-loops";
  std::string comm_time = "root";
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
};

// Declares --model, --hemicube, --energy, the radiosity mechanism flags and --jobs on cmd.
void add_predict_options(CLI::App* cmd, PredictFlags& f);

// The prediction flags that differ from their defaults, as a command line would give them, so that
// a fitted file's header names everything that reproduces the fit.
std::string non_default_flags(const PredictFlags& f);

cal::PredictionSettings settings(const PredictFlags& f);

// One line per scene matched to table 4.2 (--workload thesis-loops), each prefixed.
std::string workload_lines(const cal::Predictor& p, double energy, const std::string& prefix);

}  // namespace gcsim::calibration::app
