#include "apps/calibration/measured_table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/programs/broadcast_experiment.hpp"
#include "machine/input_file.hpp"
#include "apps/radiosity/radiosity.hpp"

namespace gcsim::calibration {
namespace {

bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

MeasuredTable broadcast_table(std::string id, const programs::ThesisBroadcastRow (&rows)[6], const char* title) {
  MeasuredTable t{std::move(id), title, "ms", {"connect_only", "1KB", "4KB", "16KB"}, {}, {}, "thesis"};
  for (const auto& r : rows) {
    t.nodes.push_back(r.nodes);
    t.values.push_back({r.ms[0], r.ms[1], r.ms[2], r.ms[3]});
  }
  return t;
}

// Tables 4.3, 4.4, 4.5, 4.8: one column per scene; `pick` selects the figure of a scene.
template <class Pick>
MeasuredTable radiosity_table(std::string id, const char* title, const char* unit, bool with_one_node, Pick pick) {
  MeasuredTable t{std::move(id), title, unit, {"ROOM", "PICROOM", "CORNELL"}, {}, {}, "thesis"};
  for (std::size_t i = with_one_node ? 0 : 1; i < radiosity::thesis::kNodes.size(); ++i) {
    t.nodes.push_back(radiosity::thesis::kNodes[i]);
    std::vector<double> row;
    for (const auto& scene : radiosity::thesis::kScenes) row.push_back(pick(scene)[i]);
    t.values.push_back(std::move(row));
  }
  return t;
}

}  // namespace

int MeasuredTable::row_of(int n) const {
  auto it = std::find(nodes.begin(), nodes.end(), n);
  return it == nodes.end() ? -1 : static_cast<int>(it - nodes.begin());
}

int MeasuredTable::column_of(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (same_name(columns[i], name)) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> thesis_table_ids() { return {"4.3", "4.4", "4.5", "4.6", "4.7", "4.8"}; }

MeasuredTable thesis_table(std::string_view id) {
  using radiosity::thesis::SceneFigures;
  if (id == "4.3")
    return radiosity_table("4.3", "radiosity, seconds to shoot 99.9% (sequential broadcast)", "s", true,
                           [](const SceneFigures& s) { return s.time_sequential_bcast; });
  if (id == "4.4")
    return radiosity_table("4.4", "speedup over 1 node, percent (sequential broadcast)", "%", false,
                           [](const SceneFigures& s) { return s.speedup_percent; });
  if (id == "4.5")
    return radiosity_table("4.5", "radiosity, seconds spent communicating (sequential broadcast)", "s", false,
                           [](const SceneFigures& s) { return s.comm_seconds; });
  if (id == "4.6") return broadcast_table("4.6", programs::kThesisSequentialBroadcast, "one all-node broadcast, sequential");
  if (id == "4.7") return broadcast_table("4.7", programs::kThesisTreeBroadcast, "one all-node broadcast, tree");
  if (id == "4.8")
    return radiosity_table("4.8", "radiosity, seconds to shoot 99.9% (tree broadcast)", "s", true,
                           [](const SceneFigures& s) { return s.time_tree_bcast; });
  std::string ids;
  for (const auto& i : thesis_table_ids()) ids += (ids.empty() ? "" : ", ") + i;
  throw std::invalid_argument(fmt::format("unknown table '{}' (expected one of: {})", id, ids));
}

namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    cell.erase(0, cell.find_first_not_of(" \t\r"));
    cell.erase(cell.find_last_not_of(" \t\r") + 1);
    out.push_back(cell);
  }
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

[[noreturn]] void fail(const std::filesystem::path& f, int line, const std::string& what) {
  throw std::invalid_argument(fmt::format("{}:{}: {}", f.string(), line, what));
}

double parse_cell(const std::string& cell, const std::filesystem::path& f, int line, const std::string& column) {
  if (cell.empty()) return kNotMeasured;
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(cell, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != cell.size() || !std::isfinite(v) || v <= 0)
    fail(f, line, fmt::format("column '{}': '{}' is not a positive number (leave the cell empty if not measured)", column, cell));
  return v;
}

}  // namespace

MeasuredTable load_measured_csv(const std::filesystem::path& file, std::string_view like) {
  const MeasuredTable layout = thesis_table(like);
  machine::InputFile read = machine::read_input_file(file, machine::kMaxDataFileBytes);
  if (!read.ok()) throw std::invalid_argument(fmt::format("{}: cannot open the table: it {}", file.string(), read.error));
  std::istringstream in(std::move(read.text));
  MeasuredTable t{layout.id, layout.title, layout.unit, {}, {}, {}, file.string()};
  std::vector<int> column_index;  // CSV column -> layout column
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    const std::vector<std::string> cells = split_csv(line);
    if (column_index.empty()) {
      std::string expected;
      for (const auto& c : layout.columns) expected += "," + c;
      if (cells.empty() || !same_name(cells[0], "nodes") || cells.size() < 2)
        fail(file, number, "expected a header 'nodes" + expected + "' (any subset of the columns)");
      for (std::size_t i = 1; i < cells.size(); ++i) {
        const int c = layout.column_of(cells[i]);
        if (c < 0) fail(file, number, fmt::format("unknown column '{}' for table {} (expected: nodes{})", cells[i], like, expected));
        column_index.push_back(c);
        t.columns.push_back(layout.columns[c]);
      }
      continue;
    }
    if (cells.size() != column_index.size() + 1)
      fail(file, number, fmt::format("expected {} cells (nodes and {} figures), found {}", column_index.size() + 1,
                                     column_index.size(), cells.size()));
    int n = 0;
    try {
      std::size_t used = 0;
      n = std::stoi(cells[0], &used);
      if (used != cells[0].size()) n = 0;
    } catch (const std::exception&) {
    }
    if (n < 1 || n > (1 << 20)) fail(file, number, fmt::format("'{}' is not a node count (expected 1 to 1048576)", cells[0]));
    if (t.row_of(n) >= 0) fail(file, number, fmt::format("a second row for {} nodes", n));
    t.nodes.push_back(n);
    std::vector<double> row;
    for (std::size_t i = 1; i < cells.size(); ++i) row.push_back(parse_cell(cells[i], file, number, t.columns[i - 1]));
    t.values.push_back(std::move(row));
  }
  if (column_index.empty()) fail(file, 1, "empty table: expected a header line 'nodes,...' and rows of figures");
  if (t.nodes.empty()) fail(file, 1, "no rows of figures after the header");
  return t;
}

}  // namespace gcsim::calibration
