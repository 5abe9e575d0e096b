// Host work that changes nothing but the host's wall time. Computation sampling
// (projection_cache.hpp): replicas that share each shooter's projection on the host give the same
// radiosities, the same simulated times and the same per-processor counters as replicas that each
// project for themselves, for every parallel variant; and the host projects each shooter once per
// loop instead of once per node. Host threads (cell_prefetch.hpp): the same again, and the same
// trace files byte for byte, with 2 or 4 host threads computing the hemicube cells ahead.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/projection_cache.hpp"
#include "machine/machine_config.hpp"
#include "parix/backend.hpp"
#include "tests/support/published_machine.hpp"
#include "test_scenes.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::radiosity {
namespace {

struct Outcome {
  ParallelOutcome outcome;
  parix::RunResult result;
};

Outcome run(const Scene& scene, const ParallelOptions& o, int nodes, const std::string& trace = "") {
  parix::SimulationOptions sim = test_support::published_machine(nodes);
  sim.trace.path = trace;
  Outcome r;
  r.result = parix::run({"simulated", sim}, [&](parix::Processor& p) { radiosity_program(p, scene, o, &r.outcome); });
  return r;
}

void expect_same(const Outcome& a, const Outcome& b) {
  ASSERT_EQ(a.outcome.element_radiosity.size(), b.outcome.element_radiosity.size());
  for (std::size_t e = 0; e < a.outcome.element_radiosity.size(); ++e)
    EXPECT_EQ(a.outcome.element_radiosity[e], b.outcome.element_radiosity[e]) << "element " << e;
  EXPECT_EQ(a.outcome.steps.size(), b.outcome.steps.size());
  EXPECT_EQ(a.result.makespan, b.result.makespan);
  EXPECT_EQ(a.result.events, b.result.events);
  ASSERT_EQ(a.result.processors.size(), b.result.processors.size());
  for (std::size_t i = 0; i < a.result.processors.size(); ++i) {
    const parix::ProcessorStats &x = a.result.processors[i], &y = b.result.processors[i];
    EXPECT_EQ(x.finish, y.finish) << "processor " << i;
    EXPECT_EQ(x.compute, y.compute) << "processor " << i;
    EXPECT_EQ(x.comm, y.comm) << "processor " << i;
    EXPECT_EQ(x.ops, y.ops) << "processor " << i;
  }
}

struct Variant {
  ParallelAlgorithm algorithm;
  bool aggregate;
  int near_samples;
  CellAssignment cells = CellAssignment::cyclic;
};
const Variant kVariants[] = {{ParallelAlgorithm::hemicube_fixed, false, 2}, {ParallelAlgorithm::hemicube_fixed, true, 1},
                             {ParallelAlgorithm::hemicube_hierarchical, false, 2}, {ParallelAlgorithm::patch, false, 2},
                             {ParallelAlgorithm::hemicube_fixed, false, 2, CellAssignment::block}};

ParallelOptions small_options(const Variant& v) {
  ParallelOptions o;
  o.solver.hemicube.resolution = 64;
  o.solver.hemicube.cells_per_side = 4;
  o.solver.hemicube.max_shooter_samples = v.near_samples;
  o.solver.energy = 0.95;
  o.algorithm = v.algorithm;
  o.aggregate = v.aggregate;
  o.cell_assignment = v.cells;
  o.hierarchical_levels = 2;
  return o;
}

TEST(ProjectionCache, SharedProjectionsChangeNothingButHostWork) {
  const Scene scene = testing::lit_room();
  for (const Variant& v : kVariants) {
    ParallelOptions o = small_options(v);
    for (int nodes : {1, 3, 8}) {
      SCOPED_TRACE(::testing::Message() << to_string(v.algorithm) << (v.aggregate ? " aggregated" : "") << ", " << nodes
                                      << " nodes");
      o.share_projections = false;
      const Outcome alone = run(scene, with_shared_projections(o), nodes);
      o.share_projections = true;
      const ParallelOptions shared = with_shared_projections(o);
      ASSERT_NE(shared.shared_projections, nullptr);
      const Outcome together = run(scene, shared, nodes);
      expect_same(alone, together);
      const ProjectionCache& cache = *shared.shared_projections;
      // Once per shooter and loop; the other replicas (all but the owner in the patch partition) reuse it.
      std::int64_t shots = 0;
      for (const StepRecord& step : together.outcome.steps) shots += std::int64_t(step.shooters.size());
      EXPECT_EQ(cache.computed(), shots);
      if (v.algorithm != ParallelAlgorithm::patch) EXPECT_EQ(cache.shared(), shots * (nodes - 1));
      else EXPECT_EQ(cache.shared(), 0);
      EXPECT_LE(cache.entries(), std::size_t(o.solver.shooters));  // earlier loops were dropped
    }
  }
}

TEST(HostThreads, WorkersComputingTheCellsChangeNothingButWallTime) {
  const Scene scene = testing::lit_room();
  std::int64_t by_workers = 0;
  for (const Variant& v : kVariants) {
    ParallelOptions o = small_options(v);
    for (int nodes : {1, 3, 8}) {
      o.host_threads = 1;
      const Outcome one = run(scene, with_shared_projections(o), nodes);
      for (int threads : {2, 4}) {
        SCOPED_TRACE(::testing::Message() << to_string(v.algorithm) << (v.aggregate ? " aggregated" : "") << ", " << nodes
                                        << " nodes, " << threads << " host threads");
        o.host_threads = threads;
        const ParallelOptions with_workers = with_shared_projections(o);
        ASSERT_NE(with_workers.cell_prefetch, nullptr);
        expect_same(one, run(scene, with_workers, nodes));
        by_workers += with_workers.cell_prefetch->cells_by_workers();
      }
    }
  }
  // The workers did compute cells (thousands are offered); which ones depends on the host's timing.
  EXPECT_GT(by_workers, 0);
}

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HostThreads, TracesAreTheSameByteForByte) {
  const Scene scene = testing::lit_room();
  ParallelOptions o = small_options(kVariants[0]);
  const auto dir = test_support::scratch_path("gcsim_host_threads_trace");
  std::filesystem::create_directories(dir);
  for (int threads : {1, 4}) {
    o.host_threads = threads;
    run(scene, with_shared_projections(o), 8, (dir / ("t" + std::to_string(threads) + ".json")).string());
  }
  for (const char* ext : {".json", ".csv", ".paje"}) {
    const std::string one = file_bytes(dir / (std::string("t1") + ext)), four = file_bytes(dir / (std::string("t4") + ext));
    EXPECT_GT(one.size(), 1000u) << ext;
    EXPECT_TRUE(one == four) << ext << " differs between 1 and 4 host threads";
  }
  std::filesystem::remove_all(dir);
}

TEST(ProjectionCache, RefusesAProjectionOfAnotherScene) {
  const Scene a = testing::lit_room(), b = testing::closed_box(1.0, 1, 1, 0.5, 1.0);
  HemicubeOptions o;
  o.resolution = 32;
  o.cells_per_side = 4;
  HemicubeRenderer ra(a, o), rb(b, o);
  OpCounts ops;
  ra.project(int(a.patches.size()) - 1, ops);
  EXPECT_THROW(rb.use_projection(ra.projection(), ops), std::logic_error);
}

TEST(ProjectionCache, ReplicasShareOneSamplesPerSideTable) {
  const Scene room = testing::lit_room(), box = testing::closed_box(1.0, 2, 2, 0.5, 1.0);
  HemicubeOptions o;
  o.resolution = 32;
  o.cells_per_side = 4;
  o.max_shooter_samples = 2;
  ProjectionCache cache;
  const HemicubeRenderer alone(room, o), first(room, o, &cache.samples_per_side()),
      second(room, o, &cache.samples_per_side());
  EXPECT_EQ(cache.samples_per_side().computed(), 1);
  int near = 0;
  for (int p = 0; p < int(room.patches.size()); ++p) {
    EXPECT_EQ(first.samples_per_side(p), alone.samples_per_side(p)) << "patch " << p;
    EXPECT_EQ(second.samples_per_side(p), alone.samples_per_side(p)) << "patch " << p;
    near += alone.samples_per_side(p) > 1;
  }
  EXPECT_GT(near, 0);  // the table is not trivially all ones
  // Another scene or setting gets its own table.
  const HemicubeRenderer other(box, o, &cache.samples_per_side());
  EXPECT_EQ(cache.samples_per_side().computed(), 2);
  for (int p = 0; p < int(box.patches.size()); ++p)
    EXPECT_EQ(other.samples_per_side(p), HemicubeRenderer(box, o).samples_per_side(p)) << "box patch " << p;
  o.near_field_ratio = 0.25;
  const HemicubeRenderer coarser(box, o, &cache.samples_per_side());
  EXPECT_EQ(cache.samples_per_side().computed(), 3);
}

}  // namespace
}  // namespace gcsim::radiosity
