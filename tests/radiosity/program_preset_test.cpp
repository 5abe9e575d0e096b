// The radiosity program's presets: gcsim's own program is the solver's defaults, the thesis's is
// what docs/calibration.md fits the default machine with, and options given override a preset.
#include "apps/radiosity/program_preset.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "apps/radiosity/parallel_radiosity.hpp"

namespace gcsim::radiosity {
namespace {

TEST(ProgramPreset, GcsimIsTheParallelProgramsDefaults) {
  const ProgramPreset& g = gcsim_program();
  const ParallelOptions defaults;
  EXPECT_EQ(g.cell_assignment, defaults.cell_assignment);
  EXPECT_EQ(g.side_faces, defaults.side_faces);
  EXPECT_EQ(g.merge, defaults.merge);
  EXPECT_EQ(g.ff_exchange, defaults.ff_exchange);
  EXPECT_EQ(g.shooters, defaults.solver.shooters);
  EXPECT_EQ(g.energy, defaults.solver.energy);
  EXPECT_EQ(g.workload, Workload::as_built);
  EXPECT_EQ(g.comm_time, CommTimeOf::mean);
}

TEST(ProgramPreset, ThesisIsTheProgramTheDefaultMachineWasFittedWith) {
  const ProgramPreset& t = program_preset("thesis");
  EXPECT_EQ(&t, &thesis_program());
  EXPECT_EQ(t.shooters, 2);
  EXPECT_EQ(t.energy, 0.999);
  EXPECT_EQ(t.hemicube, 256);
  EXPECT_EQ(t.cell_assignment, CellAssignment::block);
  EXPECT_EQ(t.side_faces, SideFaces::full);
  EXPECT_EQ(t.merge, FormFactorMerge::fixed_arrays);
  EXPECT_EQ(t.ff_exchange, FormFactorExchange::together);
  EXPECT_EQ(t.workload, Workload::thesis_loops);
  EXPECT_EQ(t.comm_time, CommTimeOf::root);
}

TEST(ProgramPreset, UnknownNamesListThePresets) {
  EXPECT_EQ(program_preset_names(), (std::vector<std::string>{"gcsim", "thesis"}));
  try {
    program_preset("paper");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gcsim, thesis"), std::string::npos) << e.what();
  }
  EXPECT_EQ(parse_workload(to_string(Workload::thesis_loops)), Workload::thesis_loops);
  EXPECT_EQ(parse_comm_time_of(to_string(CommTimeOf::root)), CommTimeOf::root);
  EXPECT_THROW(parse_workload("brighter"), std::invalid_argument);
  EXPECT_THROW(parse_comm_time_of("median"), std::invalid_argument);
}

// The flags as a command declares them; shooters is optional (calibration has no --shooters).
struct Flags {
  int hemicube = 64, shooters = 1;
  double energy = 0.5;
  std::string cell_assignment, side_faces, merge, ff_exchange, workload, comm_time;
};
struct FlagsWithoutShooters {
  int hemicube = 64;
  double energy = 0.5;
  std::string cell_assignment, side_faces, merge, ff_exchange, workload, comm_time;
};

TEST(ApplyProgramPreset, FillsWhatWasNotGivenAndReportsWhatWas) {
  Flags f;
  f.side_faces = "half";
  const std::set<std::string> given = {"--side-faces", "--hemicube"};
  const auto overridden =
      apply_program_preset(thesis_program(), f, [&](const char* option) { return given.count(option) > 0; });
  EXPECT_EQ(overridden, (std::vector<std::string>{"--hemicube", "--side-faces"}));
  EXPECT_EQ(f.hemicube, 64);         // given
  EXPECT_EQ(f.side_faces, "half");   // given
  EXPECT_EQ(f.shooters, 2);
  EXPECT_EQ(f.energy, 0.999);
  EXPECT_EQ(f.cell_assignment, "block");
  EXPECT_EQ(f.merge, "fixed-arrays");
  EXPECT_EQ(f.ff_exchange, "together");
  EXPECT_EQ(f.workload, "thesis-loops");
  EXPECT_EQ(f.comm_time, "root");

  FlagsWithoutShooters g;
  EXPECT_TRUE(apply_program_preset(gcsim_program(), g, [](const char*) { return false; }).empty());
  EXPECT_EQ(g.hemicube, 256);
  EXPECT_EQ(g.cell_assignment, "cyclic");
  EXPECT_EQ(g.workload, "as-built");
}

}  // namespace
}  // namespace gcsim::radiosity
