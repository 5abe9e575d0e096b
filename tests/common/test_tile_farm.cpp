// The tile farm itself (apps/common/tile_farm.hpp) on the simulated runtime: whatever the number of
// processors, the pool's form and the stop timing, every tile is rendered exactly once and
// assembled exactly once on node 0, the workers share the work, and the statistics count what
// the workers sent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "apps/common/tile_farm.hpp"
#include "tests/support/published_machine.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::apps {
namespace {

struct FarmCase {
  AssignmentFormat format;
  StopTiming stops;
  int longest_run;  // tiles per run the pool hands out at most
};

// What a farm run did, as the test's host-side check slots saw it.
struct FarmRun {
  std::vector<int> rendered;       // per tile: how often any processor rendered it
  std::vector<int> assembled;      // per tile: how often node 0 assembled its record
  std::vector<int> rendered_by;    // per tile: the node that rendered it
  std::uint64_t worker_bytes = 0;  // records the workers rendered
  TileFarmStats stats;
  double seconds = 0.0;
};

// A record: [int32 tile][int32 node][tile % 5 filler bytes], so records differ in size.
parix::Bytes record_of(int tile, int node) {
  const std::int32_t head[2] = {tile, node};
  parix::Bytes b(sizeof head + std::size_t(tile % 5));
  std::memcpy(b.data(), head, sizeof head);
  return b;
}

FarmRun run_farm(int nodes, int tiles, const FarmCase& c) {
  FarmRun out;
  out.rendered.assign(std::size_t(tiles), 0);
  out.assembled.assign(std::size_t(tiles), 0);
  out.rendered_by.assign(std::size_t(tiles), -1);
  int next = 0;
  TileFarm farm{.tag = 7, .format = c.format, .stops = c.stops};
  farm.next_run = [&]() -> std::optional<TileRun> {
    if (next >= tiles) return std::nullopt;
    const int count = std::min(c.longest_run, tiles - next);
    const TileRun run{next, count};
    next += count;
    return run;
  };
  farm.render = [&](parix::Processor& q, int t) {
    q.compute("memcpy_byte", std::int64_t(200000) * (1 + (t * 7) % 5));  // uneven tile costs
    ++out.rendered.at(std::size_t(t));
    out.rendered_by.at(std::size_t(t)) = q.id();
    parix::Bytes r = record_of(t, q.id());
    if (q.id() != 0) out.worker_bytes += r.size();
    return r;
  };
  farm.assemble = [&](parix::Processor& q, std::span<const std::byte> records) {
    ASSERT_EQ(q.id(), 0);
    std::size_t at = 0;
    while (at < records.size()) {
      std::int32_t head[2];
      ASSERT_LE(at + sizeof head, records.size());
      std::memcpy(head, records.data() + at, sizeof head);
      ASSERT_GE(head[0], 0);
      ASSERT_LT(head[0], tiles);
      EXPECT_EQ(head[1], out.rendered_by.at(std::size_t(head[0])));
      ++out.assembled.at(std::size_t(head[0]));
      at += sizeof head + std::size_t(head[0] % 5);
    }
    EXPECT_EQ(at, records.size());
  };
  const parix::RunResult r = parix::run_simulated(test_support::published_machine(nodes), [&](parix::Processor& p) {
    const TileFarmStats s = run_tile_farm(p, farm);
    if (p.id() == 0) out.stats = s;
  });
  out.seconds = r.simulated_seconds();
  return out;
}

class TileFarmTest : public ::testing::TestWithParam<FarmCase> {};

TEST_P(TileFarmTest, EveryTileIsRenderedAndAssembledExactlyOnce) {
  for (int nodes : {1, 2, 3, 7})
    for (int tiles : {0, 1, 5, 40}) {
      SCOPED_TRACE(testing::Message() << nodes << " nodes, " << tiles << " tiles");
      const FarmRun run = run_farm(nodes, tiles, GetParam());
      for (int t = 0; t < tiles; ++t) {
        EXPECT_EQ(run.rendered[std::size_t(t)], 1) << "tile " << t;
        EXPECT_EQ(run.assembled[std::size_t(t)], 1) << "tile " << t;
      }
      // Only the workers' records travel, and the statistics count exactly those.
      EXPECT_EQ(run.stats.result_bytes, run.worker_bytes);
      if (nodes == 1) {
        EXPECT_EQ(run.stats.assignments, 0u);
      }
    }
}

TEST_P(TileFarmTest, TheWorkersShareTheTiles) {
  for (int nodes : {2, 3, 7}) {
    SCOPED_TRACE(testing::Message() << nodes << " nodes");
    const FarmRun run = run_farm(nodes, 40, GetParam());
    std::vector<int> per_node(std::size_t(nodes), 0);
    for (int by : run.rendered_by) ++per_node.at(std::size_t(by));
    for (int n = 0; n < nodes; ++n) EXPECT_GT(per_node[std::size_t(n)], 0) << "node " << n << " rendered nothing";
    // Each assignment is one run of at most longest_run tiles.
    const int by_workers = 40 - per_node[0];
    EXPECT_GE(run.stats.assignments * std::uint64_t(GetParam().longest_run), std::uint64_t(by_workers));
    EXPECT_LE(run.stats.assignments, std::uint64_t(by_workers));
  }
}

TEST_P(TileFarmTest, MoreProcessorsFinishSooner) {
  const double one = run_farm(1, 40, GetParam()).seconds, seven = run_farm(7, 40, GetParam()).seconds;
  EXPECT_LT(seven, 0.5 * one);
}

TEST_P(TileFarmTest, ARunIsDeterministic) {
  const FarmRun a = run_farm(7, 40, GetParam()), b = run_farm(7, 40, GetParam());
  EXPECT_EQ(a.rendered_by, b.rendered_by);
  EXPECT_EQ(a.seconds, b.seconds);
}

INSTANTIATE_TEST_SUITE_P(Forms, TileFarmTest,
                         ::testing::Values(FarmCase{AssignmentFormat::single_tile, StopTiming::at_end, 1},
                                           FarmCase{AssignmentFormat::tile_run, StopTiming::when_dry, 3},
                                           FarmCase{AssignmentFormat::tile_run, StopTiming::at_end, 2}),
                         [](const ::testing::TestParamInfo<FarmCase>& info) {
                           const FarmCase& c = info.param;
                           return std::string(c.format == AssignmentFormat::single_tile ? "SingleTiles" : "RunsOf") +
                                  (c.format == AssignmentFormat::single_tile ? "" : std::to_string(c.longest_run)) +
                                  (c.stops == StopTiming::when_dry ? "StopWhenDry" : "StopAtEnd");
                         });

TEST(TileFarm, ASingleTileFarmRefusesARunOfSeveralTiles) {
  TileFarm farm{.tag = 7, .format = AssignmentFormat::single_tile};
  int next = 0;
  farm.next_run = [&]() -> std::optional<TileRun> {
    if (next >= 4) return std::nullopt;
    next += 2;
    return TileRun{next - 2, 2};
  };
  farm.render = [](parix::Processor&, int t) { return record_of(t, 0); };
  farm.assemble = [](parix::Processor&, std::span<const std::byte>) {};
  EXPECT_THROW(parix::run_simulated(test_support::published_machine(2), [&](parix::Processor& p) { run_tile_farm(p, farm); }),
               std::exception);
}

}  // namespace
}  // namespace gcsim::apps
