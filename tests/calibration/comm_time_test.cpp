// Table 4.5's figure: the root's communication time or the mean over the processors.
#include <gtest/gtest.h>

#include "apps/calibration/calibration.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::calibration {
namespace {

// Table 4.5's figure is the root's communication time (or the mean over the processors): the
// predictor reports exactly what a direct run of the same program measures there; totals do not
// depend on the choice.
TEST(CommTimeOf, IsTheRootsOrTheMeanOfADirectRun) {
  PredictionSettings s;
  s.hemicube = 32;
  s.energy = 0.9;
  const MeasuredTable comm = table_from_spec("4.5@4+CORNELL"), total = table_from_spec("4.3@4+CORNELL");
  const auto r = std::size_t(comm.row_of(4)), k = std::size_t(comm.column_of("CORNELL"));
  const auto tr = std::size_t(total.row_of(4)), tk = std::size_t(total.column_of("CORNELL"));
  const machine::MachineConfig c = MachineFile("").config();
  Predictor root(s);
  const auto root_grids = root.predict({comm, total}, c);
  s.comm_time_of = CommTimeOf::mean;
  Predictor mean(s);
  const auto mean_grids = mean.predict({comm, total}, c);
  EXPECT_EQ(root_grids[1][tr][tk], mean_grids[1][tr][tk]);
  EXPECT_GT(root_grids[1][tr][tk], 0.0);

  radiosity::ParallelOptions o;
  o.solver.hemicube.resolution = 32;
  o.solver.energy = 0.9;
  o.cell_assignment = s.cell_assignment;
  o.side_faces = s.side_faces;
  o.merge = s.merge;
  o.ff_exchange = s.ff_exchange;
  o = radiosity::with_shared_projections(o);
  const radiosity::Scene scene = radiosity::with_reflectances_scaled(radiosity::flatten(radiosity::load_scene_world("cornell")), root.loop_matches().at("cornell").scale);
  parix::SimulationOptions sim;
  sim.config = machine::with_nodes(c, 4);
  const parix::RunResult run =
      parix::run_simulated(sim, [&](parix::Processor& p) { radiosity::radiosity_program(p, scene, o, nullptr); });
  EXPECT_EQ(root_grids[0][r][k], machine::to_seconds(run.processors.at(0).comm));
  EXPECT_EQ(mean_grids[0][r][k], run.mean_comm_seconds());
  EXPECT_NE(root_grids[0][r][k], mean_grids[0][r][k]);
  EXPECT_THROW(parse_comm_time_of("median"), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::calibration
