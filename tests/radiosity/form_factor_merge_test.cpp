// How the received form factors are merged (form_factor_merge.hpp): the whole-hemicube merge adds
// N x cells x elements per shooter on every node, inside the exchange (communication time), and
// changes nothing else: the same radiosities, the same compute, every node later by exactly the
// merges' time.
#include <gtest/gtest.h>

#include <stdexcept>

#include "apps/radiosity/form_factor_merge.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "machine/machine_config.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

TEST(FormFactorMerge, AdditionsCountEveryPartOverTheWholeHemicube) {
  EXPECT_EQ(merge_additions(FormFactorMerge::own_cells, 8, 192, 166), 0);
  EXPECT_EQ(merge_additions(FormFactorMerge::whole_hemicube, 1, 192, 166), 0);  // one node: no exchange
  EXPECT_EQ(merge_additions(FormFactorMerge::whole_hemicube, 8, 192, 166), 8LL * 192 * 166);
  EXPECT_EQ(merge_additions(FormFactorMerge::whole_hemicube, 65536, 512 * 512 * 3, 100000),
            65536LL * 512 * 512 * 3 * 100000);  // no int overflow
  // Fixed arrays: kMergeSlots element slots per cell whatever the scene, unless it has more.
  EXPECT_EQ(merge_additions(FormFactorMerge::fixed_arrays, 8, 192, 166), 8LL * 192 * kMergeSlots);
  EXPECT_EQ(merge_additions(FormFactorMerge::fixed_arrays, 8, 192, 205), 8LL * 192 * kMergeSlots);
  EXPECT_EQ(merge_additions(FormFactorMerge::fixed_arrays, 8, 192, 300), 8LL * 192 * 300);
  EXPECT_EQ(merge_additions(FormFactorMerge::fixed_arrays, 1, 192, 166), 0);
  EXPECT_EQ(parse_form_factor_merge("whole-hemicube"), FormFactorMerge::whole_hemicube);
  EXPECT_EQ(parse_form_factor_merge("fixed-arrays"), FormFactorMerge::fixed_arrays);
  EXPECT_STREQ(to_string(FormFactorMerge::fixed_arrays), "fixed-arrays");
  EXPECT_STREQ(to_string(FormFactorMerge::own_cells), "own-cells");
  EXPECT_THROW(parse_form_factor_merge("whole"), std::invalid_argument);
}

testing::SimulatedRun run_with(const Scene& scene, FormFactorMerge merge, parix::BcastAlgo bcast, int nodes) {
  ParallelOptions o = testing::quick_parallel_options(bcast);
  o.merge = merge;
  return testing::run_published(scene, o, nodes);
}

TEST(FormFactorMerge, WholeHemicubeAddsExactlyItsTimeAsCommunicationAndChangesNoRadiosity) {
  const Scene scene = testing::lit_room();
  const int cells = 48, elements = int(scene.elements.size());
  const machine::MachineConfig machine = machine::published_machine_config();
  for (parix::BcastAlgo bcast : {parix::BcastAlgo::sequential, parix::BcastAlgo::tree}) {
    const int nodes = 4;
    const testing::SimulatedRun own = run_with(scene, FormFactorMerge::own_cells, bcast, nodes);
    const testing::SimulatedRun whole = run_with(scene, FormFactorMerge::whole_hemicube, bcast, nodes);
    ASSERT_EQ(whole.out.element_radiosity, own.out.element_radiosity);
    std::int64_t shots = 0;
    for (const StepRecord& s : whole.out.steps) shots += std::int64_t(s.shooters.size());
    ASSERT_GT(shots, 2);
    const std::int64_t adds = shots * nodes * cells * elements;
    const machine::SimTime merge = machine::op_time(machine, "form_factor_merge", std::int64_t(nodes) * cells * elements);
    for (int i = 0; i < nodes; ++i) {
      const parix::ProcessorStats &a = own.result.processors[std::size_t(i)], &b = whole.result.processors[std::size_t(i)];
      EXPECT_EQ(b.ops.at("form_factor_merge"), adds) << i;
      EXPECT_FALSE(a.ops.count("form_factor_merge"));
      EXPECT_EQ(b.compute, a.compute) << i;
      EXPECT_EQ(b.comm - a.comm, shots * merge) << i;
      EXPECT_EQ(b.finish - a.finish, shots * merge) << i;
    }
  }
}

}  // namespace
}  // namespace gcsim::radiosity
