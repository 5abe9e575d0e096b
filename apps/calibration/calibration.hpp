#pragma once
// gcsim calibrate: fit free parameters of a machine file to measured tables by least squares,
// and write the fitted machine as a file that inherits the base and overrides only what was
// fitted, saying in its header what was fitted to what. gcsim validate then predicts the tables
// that played no part in the fit.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "apps/calibration/comparison.hpp"
#include "apps/calibration/config_overrides.hpp"
#include "apps/calibration/least_squares.hpp"
#include "apps/calibration/measured_table.hpp"
#include "apps/calibration/predictor.hpp"

namespace gcsim::calibration {

// "a+b+c" -> {"a", "b", "c"} (empty items kept, so callers can name them in errors): the rows and
// columns inside one table spec. Lists on the command line are split by CLI11 (add_list_option).
std::vector<std::string> split_list(const std::string& s, char sep);

// "4.6" (a built-in table), "4.3@1" (only its 1-node row), "4.3@1+8", "4.3@CORNELL+PICROOM" (only
// those columns), "4.3@1+8+CORNELL", or "PATH.csv:4.6[@...]" (a user's figures in table 4.6's
// layout). Cells outside the named rows and columns are left out. Throws std::invalid_argument
// naming `option`, the spec and what was expected.
MeasuredTable table_from_spec(const std::string& spec, const std::string& option = "--fit");
// The specs of a list option (--fit 4.6,4.3@1 gives {"4.6", "4.3@1"}).
std::vector<MeasuredTable> tables_from_specs(const std::vector<std::string>& specs, const std::string& option = "--fit");

struct FittedParameter {
  std::string key;
  double initial = 0;
  double value = 0;
  double sigma = 0;  // one standard error
};

struct CalibrationResult {
  std::vector<FittedParameter> parameters;
  std::vector<CellComparison> cells;  // the fitted cells at the optimum
  LeastSquaresResult fit;
  machine::MachineConfig fitted;
  std::vector<std::string> warnings;  // keys that ended at the bound of their range
};

// One evaluation of the fit: the keys' values tried and the sum of squared relative errors there.
struct CalibrationTrial {
  int number = 0;  // 1, 2, ...
  std::map<std::string, double> values;
  double cost = 0;
};

// Fits `free` keys of the machine file to every measured cell of `tables`. Each key is fitted
// as a positive factor of its value in the file (log scale), so that keys of different units
// are equally scaled, bounded to 1/1000..1000 of that value; its value in the file must be positive.
CalibrationResult calibrate(const MachineFile& file, const std::vector<MeasuredTable>& tables,
                            const std::vector<std::string>& free, Predictor& predictor,
                            const std::function<void(const CalibrationTrial&)>& on_trial = {});

// The fitted machine file: `base = ...` and the fitted keys, with a header naming the command,
// the tables and the fit's quality.
// workload: comment lines (each "#   ...\n") saying how the scenes were matched to the thesis's runs.
std::string fitted_file_text(const MachineFile& file, const std::string& out_path, const std::vector<std::string>& specs,
                             const CalibrationResult& r, const std::string& command, const std::string& workload = "");

// What an interrupted calibration leaves at --out: a machine file with the best trial's values so
// far (best may be null: no trial finished), marked interrupted in its header and name, and
// without a [calibration] section, since nothing was fitted.
std::string interrupted_file_text(const MachineFile& file, const std::string& out_path, const std::string& specs,
                                  const CalibrationTrial* best, int trials, const std::string& command);

}  // namespace gcsim::calibration
