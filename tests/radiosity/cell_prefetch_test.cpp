// CellPrefetch on its own, without the simulation's fibers (so ThreadSanitizer can watch it): the
// cells replicas take are the cells a renderer computes, value for value and count for count,
// whichever thread computed them, over several loops and shooters; a prefetch destroyed with cells
// nobody took stops its workers.
#include <gtest/gtest.h>

#include "apps/radiosity/cell_prefetch.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

HemicubeOptions small_hemicube() {
  HemicubeOptions o;
  o.resolution = 64;
  o.cells_per_side = 4;
  return o;
}

void expect_same_counts(const OpCounts& a, const OpCounts& b) {
  EXPECT_EQ(a.polygon_project, b.polygon_project);
  EXPECT_EQ(a.hemicube_pixel, b.hemicube_pixel);
  EXPECT_EQ(a.hemicube_sample, b.hemicube_sample);
  EXPECT_EQ(a.hemicube_cull, b.hemicube_cull);
  EXPECT_EQ(a.form_factor_sum, b.form_factor_sum);
}

TEST(CellPrefetch, ReplicasTakeTheCellsARendererComputes) {
  const Scene scene = testing::lit_room();
  const HemicubeOptions o = small_hemicube();
  HemicubeRenderer replica(scene, o), reference(scene, o);
  CellPrefetch prefetch(3);
  const int nodes = 3, patches = int(scene.patches.size());
  for (int step = 0; step < 4; ++step) {
    for (int shooter : {patches - 1, step}) {
      OpCounts projecting;
      replica.project(shooter, projecting);
      reference.project(shooter, projecting);
      for (int r = 0; r < nodes; ++r)
        for (int c = r; c < replica.cell_count(); c += nodes) {
          SCOPED_TRACE(::testing::Message() << "step " << step << ", shooter " << shooter << ", cell " << c);
          OpCounts taken, computed;
          const CellFormFactors a = prefetch.take(replica, scene, step, c, nodes, taken);
          const CellFormFactors b = reference.cell_form_factors(c, computed);
          EXPECT_EQ(a.cell, c);
          EXPECT_EQ(a.element, b.element);
          EXPECT_EQ(a.value, b.value);
          expect_same_counts(taken, computed);
        }
    }
  }
  EXPECT_EQ(prefetch.workers(), 3);
}

TEST(CellPrefetch, StopsWithCellsNobodyTook) {
  const Scene scene = testing::lit_room();
  HemicubeRenderer replica(scene, small_hemicube());
  OpCounts ops;
  replica.project(int(scene.patches.size()) - 1, ops);
  {
    CellPrefetch prefetch(2);
    prefetch.take(replica, scene, 0, 0, 1, ops);  // one cell of many: a run that ended early
  }  // joins without hanging
  SUCCEED();
}

TEST(CellPrefetch, NeedsAWorker) { EXPECT_THROW(CellPrefetch(0), std::invalid_argument); }

}  // namespace
}  // namespace gcsim::radiosity
