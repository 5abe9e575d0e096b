#include "apps/calibration/comparison.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::calibration {

std::vector<CellComparison> compare(const std::vector<MeasuredTable>& tables, const std::vector<Grid>& predicted) {
  std::vector<CellComparison> out;
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const MeasuredTable& m = tables[t];
    for (std::size_t r = 0; r < m.nodes.size(); ++r)
      for (std::size_t k = 0; k < m.columns.size(); ++k)
        if (!std::isnan(m.values[r][k])) out.push_back({m.id, m.nodes[r], m.columns[k], m.values[r][k], predicted[t][r][k]});
  }
  return out;
}

std::vector<TableSummary> summarize(const std::vector<CellComparison>& cells) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> validated, all;
  for (const auto& c : cells) {
    if (!all.count(c.table)) order.push_back(c.table);
    all[c.table].push_back(std::abs(c.error()));
    if (!c.fitted) validated[c.table].push_back(std::abs(c.error()));
  }
  std::vector<TableSummary> out;
  for (const auto& table : order) {
    std::vector<double> e = validated[table].empty() ? all[table] : validated[table];
    std::sort(e.begin(), e.end());
    TableSummary s{table, int(e.size())};
    s.max_error = e.back();
    s.median_error = e.size() % 2 ? e[e.size() / 2] : 0.5 * (e[e.size() / 2 - 1] + e[e.size() / 2]);
    s.within_15 = int(std::count_if(e.begin(), e.end(), [](double x) { return x <= 0.15; }));
    s.within_25 = int(std::count_if(e.begin(), e.end(), [](double x) { return x <= 0.25; }));
    out.push_back(s);
  }
  return out;
}

void print_cells(const std::vector<CellComparison>& cells, const std::vector<MeasuredTable>& tables) {
  std::string current;
  for (const auto& c : cells) {
    if (c.table != current) {
      current = c.table;
      const auto it = std::find_if(tables.begin(), tables.end(), [&](const MeasuredTable& t) { return t.id == c.table; });
      fmt::print("\ntable {}: {} ({}; measured: {})\n", c.table, it->title, it->unit, it->source);
      fmt::print("  {:>5} {:<13} {:>10} {:>10} {:>8}\n", "nodes", "case", "measured", "predicted", "error");
    }
    fmt::print("  {:>5} {:<13} {:>10.4g} {:>10.4g} {:>+7.1f}%{}\n", c.nodes, c.column, c.measured, c.predicted,
               100 * c.error(), c.fitted ? "  (fitted)" : "");
  }
}

void print_summaries(const std::vector<TableSummary>& summaries) {
  fmt::print("\n{:<6} {:>6} {:>9} {:>9} {:>11} {:>11}\n", "table", "cells", "max", "median", "within 15%", "within 25%");
  for (const auto& s : summaries)
    fmt::print("{:<6} {:>6} {:>8.1f}% {:>8.1f}% {:>7}/{:<3} {:>7}/{:<3}\n", s.table, s.cells, 100 * s.max_error,
               100 * s.median_error, s.within_15, s.cells, s.within_25, s.cells);
}

nlohmann::json to_json(const std::vector<CellComparison>& cells, const std::vector<TableSummary>& summaries) {
  nlohmann::json j;
  for (const auto& c : cells)
    j["cells"].push_back({{"table", c.table}, {"nodes", c.nodes}, {"case", c.column}, {"measured", c.measured},
                          {"predicted", c.predicted}, {"error", c.error()}, {"fitted", c.fitted}});
  for (const auto& s : summaries)
    j["tables"].push_back({{"table", s.table}, {"cells", s.cells}, {"max_error", s.max_error},
                           {"median_error", s.median_error}, {"within_15", s.within_15}, {"within_25", s.within_25}});
  return j;
}

void write_csv(const std::string& path, const std::vector<CellComparison>& cells, const std::string& comment) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write CSV file '" + path + "'");
  out << comment << '\n';
  out << "table,nodes,case,measured,predicted,error,fitted\n";
  for (const auto& c : cells)
    out << fmt::format("{},{},{},{:.9g},{:.9g},{:.6f},{}\n", c.table, c.nodes, c.column, c.measured, c.predicted, c.error(),
                       c.fitted ? 1 : 0);
}

}  // namespace gcsim::calibration
