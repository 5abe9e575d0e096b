#pragma once
// Measured against predicted, cell by cell, and per table: the largest and median relative error
// and how many cells fall within 15 % and 25 % (the calibration's targets: within 15 % is a good prediction, within 25 % a usable one).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/calibration/measured_table.hpp"
#include "apps/calibration/predictor.hpp"

namespace gcsim::calibration {

struct CellComparison {
  std::string table;
  int nodes = 0;
  std::string column;
  double measured = 0;
  double predicted = 0;
  bool fitted = false;  // the cell took part in the fit (not a validation)
  double error() const { return (predicted - measured) / measured; }
};

struct TableSummary {
  std::string table;
  int cells = 0;
  double max_error = 0;     // largest |relative error|
  double median_error = 0;  // median |relative error|
  int within_15 = 0;
  int within_25 = 0;
};

// One row per measured cell of each table, in table, row, column order.
std::vector<CellComparison> compare(const std::vector<MeasuredTable>& tables, const std::vector<Grid>& predicted);
// Summaries per table of the cells that were not fitted (or of all, if every cell was fitted).
std::vector<TableSummary> summarize(const std::vector<CellComparison>& cells);

void print_cells(const std::vector<CellComparison>& cells, const std::vector<MeasuredTable>& tables);
void print_summaries(const std::vector<TableSummary>& s);
nlohmann::json to_json(const std::vector<CellComparison>& cells, const std::vector<TableSummary>& s);
// table,nodes,column,measured,predicted,error,fitted: what `gcsim plot --calibration` reads.
// comment: the first row (pipeline::csv_comment), naming the machine for the plot's subtitle.
void write_csv(const std::string& path, const std::vector<CellComparison>& cells, const std::string& comment);

}  // namespace gcsim::calibration
