// The media program on the simulated GC: the image is bit-identical for 1, 2, 4 and 8 nodes and equal
// to the sequential render; compute is charged and splits over the nodes.
#include <gtest/gtest.h>

#include "apps/media/lower_media_scene.hpp"
#include "apps/media/parallel_media.hpp"
#include "machine/machine_config.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::media {
namespace {

TEST(ParallelMedia, ImageDoesNotDependOnTheNodeCount) {
  MediaScene s = load_media_scene("small");
  s.photons_emitted = 3000, s.k_nearest = 30, s.image.width = 20, s.image.height = 15;
  const MarchSettings settings{Estimator::radiance, 4.0};
  SceneCaches caches = build_caches(s, trace_photons(s, 0, s.photons_emitted));
  apps::Image sequential(s.image.width, s.image.height);
  RenderCounters counters;
  render_rows(s, caches, settings, 5, 0, s.image.height, sequential, counters);
  double previous_time = 0.0;
  for (int nodes : {1, 2, 4, 8}) {
    ParallelMediaResult r = render_media_parallel(s, settings, 5, test_support::published_machine(nodes));
    ASSERT_EQ(r.image.pixels().size(), sequential.pixels().size());
    for (std::size_t i = 0; i < sequential.pixels().size(); ++i)
      ASSERT_EQ(r.image.pixels()[i].x, sequential.pixels()[i].x) << nodes << " nodes, pixel " << i;
    EXPECT_EQ(r.counters.march.samples, counters.march.samples);
    EXPECT_GT(r.run.simulated_seconds(), 0.0);
    // Every phase is split over the nodes, so the mean compute per node shrinks (on this tiny scene
    // the all-gathers of the replicated photon maps make 8 nodes slower overall than 4).
    if (nodes > 1) {
      EXPECT_LT(r.run.mean_compute_seconds(), previous_time) << nodes;
    }
    previous_time = r.run.mean_compute_seconds();
  }
}

// Tiles are handed out by simulated time, which is deterministic: the same run twice gives the same
// makespan to the picosecond, and every tile is assigned once.
TEST(ParallelMedia, DynamicTilesGiveADeterministicMakespan) {
  MediaScene s = load_media_scene("small");
  s.photons_emitted = 2000, s.k_nearest = 20, s.image.width = 40, s.image.height = 36;
  const MarchSettings settings{Estimator::radiance, 4.0};
  const ParallelMediaResult a = render_media_parallel(s, settings, 7, test_support::published_machine(4));
  const ParallelMediaResult b = render_media_parallel(s, settings, 7, test_support::published_machine(4));
  EXPECT_EQ(a.run.makespan, b.run.makespan);
  EXPECT_EQ(a.tiles, 9u);  // 3 x 3 tiles of 16 x 16
  EXPECT_LE(a.tile_messages, a.tiles);  // the rest rendered by the master's own thread
  for (std::size_t i = 0; i < a.image.pixels().size(); ++i) ASSERT_EQ(a.image.pixels()[i].x, b.image.pixels()[i].x);
}

// --host-threads: tiles rendered ahead from node 0's caches (parallel_media.hpp) change no pixel,
// no count and no simulated time; some tiles were rendered by the workers.
TEST(ParallelMedia, HostThreadsChangeNothingButWallTime) {
  MediaScene s = load_media_scene("small");
  s.photons_emitted = 2000, s.k_nearest = 20, s.image.width = 96, s.image.height = 64;
  const MarchSettings settings{Estimator::radiance, 4.0};
  std::int64_t by_workers = 0;
  for (int nodes : {1, 4}) {
    const ParallelMediaResult one = render_media_parallel(s, settings, 7, test_support::published_machine(nodes));
    for (int threads : {2, 4}) {
      SCOPED_TRACE(::testing::Message() << nodes << " nodes, " << threads << " host threads");
      const ParallelMediaResult more = render_media_parallel(s, settings, 7, test_support::published_machine(nodes), threads);
      EXPECT_EQ(more.run.makespan, one.run.makespan);
      EXPECT_EQ(more.run.events, one.run.events);
      EXPECT_EQ(more.counters.march.samples, one.counters.march.samples);
      EXPECT_EQ(more.counters.pixels, one.counters.pixels);
      ASSERT_EQ(more.run.processors.size(), one.run.processors.size());
      for (std::size_t i = 0; i < one.run.processors.size(); ++i) EXPECT_EQ(more.run.processors[i].ops, one.run.processors[i].ops);
      EXPECT_TRUE(more.image.pixels() == one.image.pixels());
      by_workers += more.tiles_by_workers;
    }
  }
  EXPECT_GT(by_workers, 0);  // 24 tiles each time; which ones depends on the host's timing
}

}  // namespace
}  // namespace gcsim::media
