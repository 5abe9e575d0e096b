// The thesis's broadcast experiment (4.4.2) on the simulated GC: the shape the thesis reports,
// and the sequential algorithm's figures within a stated tolerance of table 4.6.
#include "apps/programs/broadcast_experiment.hpp"

#include <gtest/gtest.h>

#include "parix/backend.hpp"

namespace gcsim::programs {
namespace {

double broadcast_ms(const std::string& config_file, int nodes, std::int64_t bytes, parix::BcastAlgo algo,
                    const std::string& model = "") {
  parix::SimulationOptions o;
  o.config = config_file.empty() ? machine::published_machine_config() : machine::load_machine_config(config_file);
  o.config = machine::with_nodes(o.config, nodes);
  if (!model.empty()) o.config.network_model = model;  // "": the machine file's own
  return machine::to_milliseconds(
      parix::run({"simulated", o}, [&](parix::Processor& p) { all_node_broadcast(p, bytes, algo); }).makespan);
}

TEST(BroadcastExperiment, TreeBeatsSequentialAt64NodesAnd16KB) {
  for (const char* model : {"analytic", "flow"}) {
    EXPECT_LT(broadcast_ms("", 64, 16384, parix::BcastAlgo::tree, model),
              broadcast_ms("", 64, 16384, parix::BcastAlgo::sequential, model))
        << model;
  }
}

TEST(BroadcastExperiment, SequentialTimeGrowsWithNodes) {
  double previous = 0;
  for (int n : {2, 4, 8, 16, 32, 64}) {
    const double t = broadcast_ms("", n, 16384, parix::BcastAlgo::sequential);
    EXPECT_GT(t, previous) << n;
    previous = t;
  }
}

TEST(BroadcastExperiment, SequentialMatchesThesisTable46) {
  // Calibrated machine: within 20% of every measured figure except the 8-node row, which the
  // thesis itself shows out of line (its connect-only time per connection is 40% above its
  // neighbours'); there we require 35%.
  const std::string cal = GCSIM_SOURCE_DIR "/configs/gc-powerplus-calibrated.toml";
  for (const ThesisBroadcastRow& row : kThesisSequentialBroadcast) {
    for (int s = 0; s < 4; ++s) {
      const double sim = broadcast_ms(cal, row.nodes, kThesisBroadcastSizes[s], parix::BcastAlgo::sequential);
      const double tolerance = row.nodes == 8 ? 0.35 : 0.20;
      EXPECT_NEAR(sim / row.ms[s], 1.0, tolerance) << row.nodes << " nodes, " << kThesisBroadcastSizes[s] << " bytes";
    }
  }
}

TEST(BroadcastExperiment, ConnectOnlyIsCheaperThanTransfer) {
  for (auto algo : {parix::BcastAlgo::sequential, parix::BcastAlgo::tree}) {
    EXPECT_LT(broadcast_ms("", 16, 0, algo), broadcast_ms("", 16, 1024, algo));
    EXPECT_LT(broadcast_ms("", 16, 1024, algo), broadcast_ms("", 16, 16384, algo));
  }
}

}  // namespace
}  // namespace gcsim::programs
