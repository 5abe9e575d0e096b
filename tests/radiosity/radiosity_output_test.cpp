// Per-element radiosities written as CSV and JSON read back to exactly the solver's doubles, one
// row per element with its patch, surface and area.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/radiosity/progressive_solver.hpp"
#include "apps/radiosity/radiosity_output.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

struct Solved {
  Scene scene;
  std::vector<Rgb> b;
};

Solved solved_room() {
  Solved s{testing::lit_room(), {}};
  SolverOptions o;
  o.hemicube.resolution = 32;
  o.energy = 0.99;
  s.b = solve_progressive(s.scene, o).state.element_radiosity();
  return s;
}

TEST(RadiosityOutput, CsvReadsBackExactly) {
  const Solved s = solved_room();
  std::ostringstream out;
  write_radiosities_csv(out, s.scene, s.b);
  std::istringstream in(out.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "element,patch,surface,area,r,g,b");
  std::size_t rows = 0;
  double area = 0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string f[7];
    for (auto& x : f) std::getline(row, x, ',');
    const std::size_t e = std::stoul(f[0]);
    ASSERT_EQ(e, rows);
    EXPECT_EQ(std::stoi(f[1]), s.scene.elements[e].patch);
    EXPECT_EQ(std::stoi(f[2]), s.scene.patches[s.scene.elements[e].patch].surface);
    EXPECT_EQ(std::stod(f[3]), s.scene.elements[e].area);
    EXPECT_EQ(Rgb(std::stod(f[4]), std::stod(f[5]), std::stod(f[6])), s.b[e]);
    area += std::stod(f[3]);
    ++rows;
  }
  EXPECT_EQ(rows, s.scene.elements.size());
  double patch_area = 0;
  for (const auto& p : s.scene.patches) patch_area += p.area;
  EXPECT_NEAR(area, patch_area, 1e-12 * patch_area);
}

TEST(RadiosityOutput, JsonReadsBackExactlyAndTheFileNameChoosesTheFormat) {
  const Solved s = solved_room();
  const auto dir = std::filesystem::temp_directory_path() / ("gcsim-rad-out-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_radiosities((dir / "r.json").string(), s.scene, s.b);
  write_radiosities((dir / "r.csv").string(), s.scene, s.b);
  const auto doc = nlohmann::json::parse(std::ifstream(dir / "r.json"));
  EXPECT_EQ(doc["scene"], s.scene.name);
  ASSERT_EQ(doc["elements"].size(), s.scene.elements.size());
  for (std::size_t e = 0; e < s.b.size(); ++e) {
    const auto& row = doc["elements"][e];
    EXPECT_EQ(row["element"], e);
    EXPECT_EQ(row["patch"], s.scene.elements[e].patch);
    EXPECT_EQ(row["area"].get<double>(), s.scene.elements[e].area);
    EXPECT_EQ(Rgb(row["radiosity"][0].get<double>(), row["radiosity"][1].get<double>(), row["radiosity"][2].get<double>()),
              s.b[e]);
  }
  std::string first;
  std::getline(std::ifstream(dir / "r.csv") >> std::ws, first);
  EXPECT_EQ(first, "element,patch,surface,area,r,g,b");
  std::filesystem::remove_all(dir);
}

TEST(RadiosityOutput, ErrorsNameTheFileOrTheMismatch) {
  const Solved s = solved_room();
  try {
    write_radiosities("/nonexistent-dir/r.csv", s.scene, s.b);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/r.csv"), std::string::npos);
  }
  std::ostringstream out;
  EXPECT_THROW(write_radiosities_csv(out, s.scene, std::vector<Rgb>(3)), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::radiosity
