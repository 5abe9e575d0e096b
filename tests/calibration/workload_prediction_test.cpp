// The predictor runs each built-in scene matched to table 4.2 (apps/radiosity/thesis_workload.hpp).
#include <gtest/gtest.h>

#include "apps/calibration/calibration.hpp"

namespace gcsim::calibration {
namespace {

using radiosity::LoopMatch;

// The predictor runs the matched scenes and says so; as built, it matches nothing.
TEST(MatchLoops, ThePredictorRunsTheMatchedScene) {
  PredictionSettings s;
  s.hemicube = 32;
  s.energy = 0.9;
  const MeasuredTable t = table_from_spec("4.3@1+CORNELL");
  const machine::MachineConfig c = MachineFile("").config();
  const auto r = std::size_t(t.row_of(1)), k = std::size_t(t.column_of("CORNELL"));
  Predictor matched(s);
  const double t_matched = matched.predict({t}, c)[0][r][k];
  ASSERT_EQ(matched.loop_matches().size(), 1u);
  const LoopMatch m = matched.loop_matches().at("cornell");
  s.match_thesis_loops = false;
  Predictor as_built(s);
  const double t_built = as_built.predict({t}, c)[0][r][k];
  EXPECT_TRUE(as_built.loop_matches().empty());
  // One node charges the same work per loop, to within what brighter walls change in the
  // element updates: the times are in the ratio of the loops.
  EXPECT_NEAR(t_matched / t_built, double(m.loops) / m.loops_as_built, 0.03);
}

}  // namespace
}  // namespace gcsim::calibration
