#pragma once
// A table of measured figures to calibrate against or validate on: rows are node counts, columns
// are the table's cases (message sizes, scenes). The thesis's tables 4.3-4.8 are built in (their
// figures copied into the project); a user's own CSV in the same layout stands in for any of them.
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::calibration {

inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

struct MeasuredTable {
  std::string id;                          // the experiment: "4.6", "4.3", ...
  std::string title;
  std::string unit;                        // "ms", "s" or "%"
  std::vector<std::string> columns;
  std::vector<int> nodes;                  // one row per node count
  std::vector<std::vector<double>> values;  // [row][column]; kNotMeasured where there is no figure
  std::string source;                      // "thesis" or the CSV's path

  int row_of(int n) const;                 // -1 if absent
  int column_of(std::string_view name) const;  // case-insensitive; -1 if absent
};

// The ids of the built-in tables, in order.
std::vector<std::string> thesis_table_ids();
// Throws std::invalid_argument listing the ids if id is unknown.
MeasuredTable thesis_table(std::string_view id);
// A CSV with the layout of thesis table `like`: a header "nodes,<its columns>" (any subset, any
// order), then one row per node count; '#' starts a comment line; an empty cell is not measured.
// Errors name the file, the line and what was expected.
MeasuredTable load_measured_csv(const std::filesystem::path& file, std::string_view like);

}  // namespace gcsim::calibration
