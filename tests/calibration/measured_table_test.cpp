// Measured tables: the built-in thesis figures, the user's CSVs and their errors.
#include "apps/calibration/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>
#include <fstream>
#include "tests/support/scratch_path.hpp"

namespace gcsim::calibration {
namespace {

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  static const struct Dir {  // removed when the test program exits
    std::filesystem::path path = test_support::scratch_path("gcsim_calibration_test");
    ~Dir() { std::filesystem::remove_all(path); }
  } scratch;
  const auto& dir = scratch.path;
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(MeasuredTable, ThesisTablesCarryTheirFigures) {
  const MeasuredTable t = thesis_table("4.6");
  EXPECT_EQ(t.nodes.front(), 2);
  EXPECT_EQ(t.nodes.back(), 64);
  EXPECT_DOUBLE_EQ(t.values[t.row_of(64)][t.column_of("16kb")], 586);
  const MeasuredTable s = thesis_table("4.4");
  EXPECT_EQ(s.row_of(1), -1);  // a speedup has no 1-node figure
  EXPECT_DOUBLE_EQ(s.values[s.row_of(2)][s.column_of("CORNELL")], 122);
  EXPECT_NE(error_of([] { thesis_table("4.9"); }).find("4.3, 4.4, 4.5, 4.6, 4.7, 4.8"), std::string::npos);
}

TEST(MeasuredTable, RowSelectionKeepsOnlyTheNamedNodeCounts) {
  const MeasuredTable t = table_from_spec("4.3@1+8");
  int measured = 0;
  for (const auto& row : t.values)
    for (double v : row) measured += !std::isnan(v);
  EXPECT_EQ(measured, 6);
  EXPECT_NE(error_of([] { table_from_spec("4.3@5"); }).find("'5' is neither a node count nor a column of table 4.3"),
            std::string::npos);
}

TEST(MeasuredTable, ColumnSelectionKeepsOnlyTheNamedScenes) {
  const MeasuredTable t = table_from_spec("4.3@1+8+cornell+PICROOM");
  std::vector<std::pair<int, std::string>> kept;
  for (std::size_t r = 0; r < t.nodes.size(); ++r)
    for (std::size_t k = 0; k < t.columns.size(); ++k)
      if (!std::isnan(t.values[r][k])) kept.emplace_back(t.nodes[r], t.columns[k]);
  const std::vector<std::pair<int, std::string>> expected{{1, "PICROOM"}, {1, "CORNELL"}, {8, "PICROOM"}, {8, "CORNELL"}};
  EXPECT_EQ(kept, expected);
  EXPECT_DOUBLE_EQ(t.values[t.row_of(8)][t.column_of("CORNELL")], 144);
  const MeasuredTable columns_only = table_from_spec("4.5@CORNELL");
  int measured = 0;
  for (const auto& row : columns_only.values) measured += !std::isnan(row[columns_only.column_of("CORNELL")]);
  EXPECT_EQ(measured, 6);  // every node count of 4.5 kept
  const std::string e = error_of([] { table_from_spec("4.3@KITCHEN"); });
  EXPECT_NE(e.find("'KITCHEN' is neither a node count nor a column of table 4.3 (columns: ROOM, PICROOM, CORNELL)"),
            std::string::npos)
      << e;
}

TEST(MeasuredTable, UserCsvInATablesLayout) {
  const auto f = write_temp("mine.csv", "# my machine\nnodes,16KB,connect_only\n2,6.0,1.5\n4,,4.0\n");
  const MeasuredTable t = table_from_spec(f.string() + ":4.6");
  EXPECT_EQ(t.id, "4.6");
  ASSERT_EQ(t.columns.size(), 2u);
  EXPECT_EQ(t.columns[0], "16KB");
  EXPECT_DOUBLE_EQ(t.values[0][0], 6.0);
  EXPECT_TRUE(std::isnan(t.values[1][0]));
  EXPECT_DOUBLE_EQ(t.values[1][1], 4.0);
}

TEST(MeasuredTable, BadCsvsNameFileLineAndWhatWasExpected) {
  const auto col = write_temp("col.csv", "nodes,32KB\n2,1\n");
  EXPECT_NE(error_of([&] { load_measured_csv(col, "4.6"); }).find("col.csv:1: unknown column '32KB'"), std::string::npos);
  const auto num = write_temp("num.csv", "nodes,1KB\n2,1\n4,fast\n");
  EXPECT_NE(error_of([&] { load_measured_csv(num, "4.6"); }).find("num.csv:3: column '1KB': 'fast' is not a positive number"),
            std::string::npos);
  const auto dup = write_temp("dup.csv", "nodes,1KB\n2,1\n2,3\n");
  EXPECT_NE(error_of([&] { load_measured_csv(dup, "4.6"); }).find("dup.csv:3: a second row for 2 nodes"), std::string::npos);
  const auto cells = write_temp("cells.csv", "nodes,1KB,4KB\n2,1\n");
  EXPECT_NE(error_of([&] { load_measured_csv(cells, "4.6"); }).find("cells.csv:2: expected 3 cells"), std::string::npos);
  const auto header = write_temp("header.csv", "2,1\n");
  EXPECT_NE(error_of([&] { load_measured_csv(header, "4.6"); }).find("header.csv:1: expected a header 'nodes,connect_only"),
            std::string::npos);
  EXPECT_NE(error_of([] { load_measured_csv("no/such.csv", "4.6"); }).find("no/such.csv: cannot open"), std::string::npos);
}

TEST(MachineFile, UnknownFreeKeyListsTheValidOnes) {
  const MachineFile f("");
  const std::string e = error_of([&] { f.check_free_key("network.warp_factor"); });
  EXPECT_NE(e.find("'network.warp_factor' is not a numeric key"), std::string::npos) << e;
  EXPECT_NE(e.find("network.connect_base_us"), std::string::npos) << e;
  EXPECT_NE(e.find("ops.polygon_project"), std::string::npos) << e;
}

// The built-in default (the calibrated file, whose bases are built in too) and a file on disk.
TEST(MachineFile, OverridesGoThroughTheParser) {
  EXPECT_DOUBLE_EQ(MachineFile(GCSIM_SOURCE_DIR "/configs/gc-powerplus.toml").value("network.connect_base_us"), 550);
  const MachineFile f("");
  EXPECT_DOUBLE_EQ(f.value("network.connect_base_us"), 485.967);
  const machine::MachineConfig c = f.with({{"network.connect_base_us", 700}, {"ops.polygon_project", 1234}});
  EXPECT_EQ(c.connect_model, machine::default_machine_config().connect_model);  // inherited through the built-in bases
  EXPECT_EQ(c.connect_base, 700 * machine::kMicrosecond);
  EXPECT_DOUBLE_EQ(c.cycles_per_op.at("polygon_project"), 1234);
  EXPECT_THROW(f.with({{"network.link_bandwidth_mbps", -1}}), machine::ConfigError);  // the parser's range check
}

}  // namespace
}  // namespace gcsim::calibration
