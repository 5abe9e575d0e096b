// Every parallel variant gives bit-identical radiosities to the sequential solver with the same K,
// for every node count; and the simulated time is deterministic.
#include <gtest/gtest.h>

#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "machine/machine_config.hpp"
#include "parix/backend.hpp"
#include "tests/support/published_machine.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

struct Variant {
  ParallelAlgorithm algorithm;
  parix::BcastAlgo bcast;
  bool aggregate;
  bool keep_links = false;
  CellAssignment cells = CellAssignment::cyclic;
  SideFaces side_faces = SideFaces::half;
};

ParallelOutcome run(const Scene& scene, const ParallelOptions& o, int nodes, parix::RunResult* result = nullptr) {
  const parix::SimulationOptions sim = test_support::published_machine(nodes);
  ParallelOutcome out;
  auto r = parix::run({"simulated", sim}, [&](parix::Processor& p) { radiosity_program(p, scene, o, &out); });
  if (result) *result = r;
  return out;
}

TEST(ParallelRadiosity, EveryVariantEqualsSequentialOnEveryNodeCount) {
  Scene scene = testing::lit_room();
  const Variant variants[] = {
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::sequential, false},
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::tree, false},
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::tree, true},
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::sequential, true, true},
      {ParallelAlgorithm::patch, parix::BcastAlgo::tree, true},
      {ParallelAlgorithm::hemicube_hierarchical, parix::BcastAlgo::sequential, false},
      {ParallelAlgorithm::patch, parix::BcastAlgo::sequential, false},
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::sequential, false, false, CellAssignment::block},
      {ParallelAlgorithm::hemicube_hierarchical, parix::BcastAlgo::tree, false, false, CellAssignment::block},
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::tree, false, false, CellAssignment::block, SideFaces::full},
      {ParallelAlgorithm::hemicube_fixed, parix::BcastAlgo::sequential, false, false, CellAssignment::cyclic, SideFaces::full},
  };
  for (const Variant& v : variants) {
    // Every K for the thesis's variant; K = 2 (the thesis's) for the others, to keep the suite short.
    const bool first = &v == &variants[0];
    for (int k : first ? std::vector<int>{1, 2, 3} : std::vector<int>{2}) {
      ParallelOptions o;
      o.solver.hemicube.resolution = 32;
      o.solver.hemicube.cells_per_side = 4;
      o.solver.shooters = k;
      o.solver.energy = 0.95;
      o.algorithm = v.algorithm;
      o.bcast = v.bcast;
      o.aggregate = v.aggregate;
      o.keep_links = v.keep_links;
      o.cell_assignment = v.cells;
      o.side_faces = v.side_faces;
      o.hierarchical_levels = 2;
      SolverOptions seq = o.solver;
      if (v.algorithm == ParallelAlgorithm::hemicube_hierarchical) seq.hemicube.hierarchical_levels = 2;
      SolveResult reference = solve_progressive(scene, seq);
      for (int nodes : {1, 2, 3, 4, 8}) {
        ParallelOutcome out = run(scene, o, nodes);
        ASSERT_EQ(out.steps.size(), reference.steps.size()) << to_string(v.algorithm) << " nodes " << nodes;
        for (std::size_t s = 0; s < out.steps.size(); ++s)
          ASSERT_EQ(out.steps[s].shooters, reference.steps[s].shooters) << "step " << s;
        // Bit-identical, not merely close.
        ASSERT_EQ(out.element_radiosity, reference.state.element_radiosity())
            << to_string(v.algorithm) << " K " << k << " nodes " << nodes << (v.aggregate ? " aggregated" : "")
            << " cells " << to_string(v.cells) << ", side faces " << to_string(v.side_faces);
      }
    }
  }
}

TEST(ParallelRadiosity, ShootingFromSeveralPointsStaysBitIdentical) {
  // Near-field sampling (shooter_samples.hpp) sums every sample inside each cell: still exact.
  Scene scene = testing::lit_room();
  for (ParallelAlgorithm a : {ParallelAlgorithm::hemicube_fixed, ParallelAlgorithm::hemicube_hierarchical,
                              ParallelAlgorithm::patch}) {
    ParallelOptions o;
    o.solver.hemicube.resolution = 64;
    o.solver.hemicube.cells_per_side = 4;
    o.solver.hemicube.max_shooter_samples = 2;
    o.solver.energy = 0.95;
    o.algorithm = a;
    o.hierarchical_levels = 2;
    SolverOptions seq = o.solver;
    if (a == ParallelAlgorithm::hemicube_hierarchical) seq.hemicube.hierarchical_levels = 2;
    SolveResult reference = solve_progressive(scene, seq);
    for (int nodes : {1, 3, 8}) {
      ParallelOutcome out = run(scene, o, nodes);
      ASSERT_EQ(out.element_radiosity, reference.state.element_radiosity()) << to_string(a) << " nodes " << nodes;
    }
  }
}

TEST(ParallelRadiosity, AClosedSceneThatNeverAbsorbsIsRefusedOnEveryNodeCount) {
  const Scene box = testing::closed_box(1.0, 1, 1, 1.0, 1.0);
  ParallelOptions o;
  o.solver.hemicube.resolution = 16;
  for (int nodes : {1, 4}) EXPECT_THROW(run(box, o, nodes), std::invalid_argument) << nodes;
}

TEST(ParallelRadiosity, IndexOrderVariantsEqualSequentialToo) {
  Scene scene = testing::lit_room();
  for (ShootingOrder order : {ShootingOrder::index, ShootingOrder::energy_then_index}) {
    ParallelOptions o;
    o.solver.hemicube.resolution = 32;
    o.solver.hemicube.cells_per_side = 4;
    o.solver.energy = 0.99;
    o.solver.order = order;
    o.solver.sort_until = 0.8;
    SolveResult reference = solve_progressive(scene, o.solver);
    ASSERT_TRUE(reference.converged);
    for (int nodes : {1, 3, 4}) {
      ParallelOutcome out = run(scene, o, nodes);
      ASSERT_EQ(out.element_radiosity, reference.state.element_radiosity()) << to_string(order) << " " << nodes;
    }
  }
}

TEST(ParallelRadiosity, SimulatedTimeIsDeterministicAndCommunicationGrowsWithNodes) {
  Scene scene = flatten(cornell_world());
  ParallelOptions o;
  o.solver.hemicube.resolution = 32;
  o.solver.energy = 0.9;
  parix::RunResult a, b, c;
  run(scene, o, 4, &a);
  run(scene, o, 4, &b);
  EXPECT_EQ(a.makespan, b.makespan);
  run(scene, o, 16, &c);
  EXPECT_GT(c.mean_comm_seconds(), a.mean_comm_seconds());
  EXPECT_GT(a.mean_comm_seconds(), 0);
}

TEST(ParallelRadiosity, AggregationAndTreeBroadcastCutCommunicationOnManyNodes) {
  Scene scene = flatten(cornell_world());
  ParallelOptions o;
  o.solver.hemicube.resolution = 32;
  o.solver.energy = 0.8;
  parix::RunResult seq, tree, agg;
  run(scene, o, 32, &seq);
  o.bcast = parix::BcastAlgo::tree;
  run(scene, o, 32, &tree);
  o.aggregate = true;
  run(scene, o, 32, &agg);
  EXPECT_LT(tree.makespan, seq.makespan);
  EXPECT_LT(agg.makespan, tree.makespan);
}

}  // namespace
}  // namespace gcsim::radiosity
