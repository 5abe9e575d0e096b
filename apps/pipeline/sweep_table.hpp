#pragma once
// The columns of `gcsim sweep APP`: the generic sweep computes, per node count, the run's figures
// and the speedup; the table prints them with the application's own columns and overlays (e.g. the
// thesis's figures). Rows arrive in node-count order on the main thread, whatever --jobs is.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>


namespace gcsim::pipeline {

struct Outcome;

// How the speedup of a row is measured.
enum class SpeedupBase {
  first_point,         // t(first count) / t
  first_point_scaled,  // t(first count) * first count / t: ideal linear speedup before the first count
};

struct SweepRow {
  int nodes = 0;
  const Outcome& outcome;
  double speedup = 1;
  bool first = false;  // the sweep's first row
};

class SweepTable {
 public:
  virtual ~SweepTable() = default;
  virtual SpeedupBase speedup_base() const { return SpeedupBase::first_point; }
  virtual void print_header() = 0;
  virtual std::string csv_header() const = 0;  // without the newline
  // Prints the row (and any note about it) on stdout.
  virtual void print_row(const SweepRow& row) = 0;
  virtual std::string csv_row(const SweepRow& row) const = 0;  // without the newline
  virtual nlohmann::json json_row(const SweepRow& row) const;    // default: the run's JSON, with "speedup"
  // After the last row: summary lines; then the document --json writes (default: the rows' array).
  virtual void print_footer() {}
  virtual nlohmann::json json_document(nlohmann::json rows) const { return rows; }
  // Whether the sweep prints "csv  FILE" / "json FILE" after the table.
  virtual bool announce_files() const { return true; }
  // The scene swept, for the CSV's comment row (and so the plot's title); "" when none.
  virtual std::string scene() const { return {}; }
};

// nodes, simulated s, speedup, comm s (mean per node), wall s.
std::unique_ptr<SweepTable> standard_sweep_table();

}  // namespace gcsim::pipeline
