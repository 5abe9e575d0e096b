// 3D-DDA: the spans tile the clipped ray, each lies in its voxel, neighbours share a face; hard rays.
#include <gtest/gtest.h>

#include <algorithm>

#include <glm/geometric.hpp>

#include "apps/common/rng.hpp"
#include "apps/common/media/grid_dda.hpp"

namespace gcsim::media {
namespace {

void check_walk(const UniformGrid& g, glm::dvec3 o, glm::dvec3 d, double t_max, bool expect_hit) {
  auto spans = traverse_grid(g, o, d, 0.0, t_max);
  double t0 = 0.0, t1 = t_max;
  bool hit = clip_to_box(g, o, d, t0, t1);
  ASSERT_EQ(hit, expect_hit);
  if (!hit) { EXPECT_TRUE(spans.empty()); return; }
  ASSERT_FALSE(spans.empty());
  EXPECT_NEAR(spans.front().t0, t0, 1e-12);
  EXPECT_NEAR(spans.back().t1, t1, 1e-12);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const auto& s = spans[i];
    EXPECT_GT(s.t1, s.t0);
    glm::dvec3 mid = o + 0.5 * (s.t0 + s.t1) * d;
    glm::dvec3 lo = g.lo + glm::dvec3(s.cell) * g.cell_size(), hi = lo + g.cell_size();
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(mid[a], lo[a] - 1e-9);
      EXPECT_LE(mid[a], hi[a] + 1e-9);
    }
    if (i > 0) {
      EXPECT_DOUBLE_EQ(spans[i - 1].t1, s.t0);
      glm::ivec3 step = glm::abs(s.cell - spans[i - 1].cell);
      // One face crossed, or an edge/corner crossed at once (zero-length spans are skipped).
      EXPECT_LE(std::max({step.x, step.y, step.z}), 1);
      EXPECT_GE(step.x + step.y + step.z, 1);
    }
  }
}

TEST(GridDda, RandomRaysTileTheirClippedInterval) {
  UniformGrid g{{-1, -2, 0}, {3, 1, 5}, {7, 5, 9}};
  apps::Rng rng(17, 1);
  for (int i = 0; i < 2000; ++i) {
    glm::dvec3 o(rng.uniform(-3, 5), rng.uniform(-4, 3), rng.uniform(-2, 7));
    glm::dvec3 target(rng.uniform(-1, 3), rng.uniform(-2, 1), rng.uniform(0, 5));
    check_walk(g, o, glm::normalize(target - o), 100.0, true);
  }
}

TEST(GridDda, AxisParallelRaysOnVoxelFacesAndGrazingRays) {
  UniformGrid g{{0, 0, 0}, {4, 4, 4}, {4, 4, 4}};
  check_walk(g, {0.5, 0.5, -1}, {0, 0, 1}, 10, true);           // axis-parallel through centres
  check_walk(g, {1.0, 2.0, -1}, {0, 0, 1}, 10, true);           // along a voxel edge
  check_walk(g, {2.0, 0.5, 0.5}, {1, 0, 0}, 10, true);          // origin on an inner face
  check_walk(g, {2.0, 0.5, 0.5}, {-1, 0, 0}, 10, true);         // leaving from a face backwards
  check_walk(g, {0, 0, 0}, glm::normalize(glm::dvec3(1, 1, 1)), 10, true);  // through voxel corners
  check_walk(g, {4.0, 1.5, 1.5}, {0, 1, 0}, 10, true);          // grazing the box face x = 4
  check_walk(g, {4.0 + 1e-9, 1.5, 1.5}, {0, 1, 0}, 10, false);  // just outside: a miss
  check_walk(g, {-1, 1e-13, 2}, glm::normalize(glm::dvec3(1, 1e-14, 0)), 10, true);  // nearly grazing
  check_walk(g, {1.5, 1.5, 1.5}, {0, 0, 1}, 0.25, true);        // ends inside one voxel
}

TEST(GridDda, SingleVoxelGridGivesOneSpan) {
  UniformGrid g{{0, 0, 0}, {1, 1, 1}, {1, 1, 1}};
  auto spans = traverse_grid(g, {-1, 0.3, 0.4}, glm::normalize(glm::dvec3(1, 0.2, 0.1)), 0, 10);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].cell, glm::ivec3(0));
}

}  // namespace
}  // namespace gcsim::media
