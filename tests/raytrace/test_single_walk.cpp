// The single-ray walk compiled per octant (traversal.cpp: far distances carried negated, one max
// per axis) must give exactly what the generic walk, which reads the octant at run time, gives,
// and both what a plainly written walk gives: hit, distance and barycentrics bit for bit, and
// every count. Hard cases: rays through the
// corners and edge midpoints of every child box, axis-parallel rays lying in the boxes' slab
// planes (0 * inf = NaN), rays from inside boxes, rays starting with a hit, empty and
// one-primitive trees, over every built-in scene and its subtrees.
#include <gtest/gtest.h>

#include "tests/support/same_bits.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>
#include <utility>
#include <vector>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/bvh.hpp"
#include "apps/common/geometry/primitive_intersection.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/common/rng.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/subtree.hpp"
#include "tests/raytrace/box_corner_rays.hpp"

namespace gcsim::raytrace {
namespace {

using test_support::same_bits;

// The walk's slab test of one child box, plainly: near and far planes picked by the direction's
// sign (so a NaN from 0 * inf, a ray lying in a slab plane, is skipped on either side, where
// intersect_box's swap by comparison may keep it), the far end scaled up and clipped to tmax.
bool plain_box(const PairNode& n, int child, const Ray& ray, float tmax, float* entry) {
  float t0 = ray.tmin, t1 = kInfinity;
  for (int a = 0; a < 3; ++a) {
    float tn = (n.bounds[a][child] - ray.origin[a]) * ray.inv_direction[a];
    float tf = (n.bounds[a][2 + child] - ray.origin[a]) * ray.inv_direction[a];
    if (std::signbit(ray.inv_direction[a])) std::swap(tn, tf);
    t0 = tn > t0 ? tn : t0;
    t1 = tf < t1 ? tf : t1;
  }
  *entry = t0 * (1.0f - 2.0f * gamma(3));
  return t0 <= std::min(t1 * (1.0f + 2.0f * gamma(3)), tmax);
}

// The paper's ordered walk spelled out plainly, as the reference for everything the fast walk
// does differently on the host (slabs of both children at once, far distances negated, triangle
// tests finished from the rejection, the next node kept out of the stack): a plain stack, one
// box test per node child against the nearest hit so far, primitive children first.
void reference_walk(const Scene& s, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally) {
  if (tree.empty) return;
  if (is_primitive(tree.root)) return test_primitive(s, primitive_of(tree.root), ray, hit, tally);
  struct Entry { NodeRef node; float entry; };
  std::vector<Entry> stack;  // reserved, and the children found in a fixed pair: no allocation per
  stack.reserve(64);         // node, which made this test 40 times slower under ASan than in release
  float entry;
  ++tally.boxes;
  if (!intersect_box(tree.root_box, ray, hit.t, &entry)) return;
  stack.push_back({tree.root, entry});
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    if (e.entry > hit.t) continue;
    const PairNode& n = tree.nodes[e.node];
    for (int i = 0; i < 2; ++i)
      if (is_primitive(n.child[i])) test_primitive(s, primitive_of(n.child[i]), ray, hit, tally);
    Entry found[2];
    int count = 0;
    for (int i = 0; i < 2; ++i) {
      if (is_primitive(n.child[i])) continue;
      ++tally.boxes;
      if (plain_box(n, i, ray, hit.t, &entry)) found[count++] = {n.child[i], entry};
    }
    if (count == 2) {
      ++tally.sorts;
      if (found[0].entry < found[1].entry) std::swap(found[0], found[1]);  // the farther below
    }
    for (int i = 0; i < count; ++i) stack.push_back(found[i]);
  }
}

// Returns whether the ray hit something.
bool expect_walks_agree(const Scene& s, const PackedTree& tree, const Ray& ray, const Hit& start = Hit{}) {
  Hit fast = start, ref = start, plain = start;
  TestTally fast_tally, ref_tally, plain_tally;
  traverse_ordered(s, tree, ray, fast, fast_tally);
  traverse_ordered_generic(s, tree, ray, ref, ref_tally);
  reference_walk(s, tree, ray, plain, plain_tally);
  EXPECT_EQ(plain.prim, ref.prim);
  EXPECT_TRUE(same_bits(plain.t, ref.t) && same_bits(plain.b1, ref.b1) && same_bits(plain.b2, ref.b2));
  EXPECT_EQ(plain_tally.boxes, ref_tally.boxes);
  EXPECT_EQ(plain_tally.spheres, ref_tally.spheres);
  EXPECT_EQ(plain_tally.triangles, ref_tally.triangles);
  EXPECT_EQ(plain_tally.sorts, ref_tally.sorts);
  EXPECT_EQ(fast.prim, ref.prim);
  EXPECT_TRUE(same_bits(fast.t, ref.t)) << fast.t << " vs " << ref.t;
  EXPECT_TRUE(same_bits(fast.b1, ref.b1) && same_bits(fast.b2, ref.b2));
  EXPECT_EQ(fast_tally.boxes, ref_tally.boxes);
  EXPECT_EQ(fast_tally.spheres, ref_tally.spheres);
  EXPECT_EQ(fast_tally.triangles, ref_tally.triangles);
  EXPECT_EQ(fast_tally.sorts, ref_tally.sorts);
  return ref.valid();
}

// The hard rays of every child box of `tree` (tests/raytrace/box_corner_rays.hpp), those from
// inside the boxes and in their slab planes included.
std::vector<Ray> hard_rays(const PackedTree& tree, const Bounds3& scene, apps::Rng& rng) {
  return testing::box_corner_rays(tree, scene, rng, 1, true);
}

// Every ninth 8 x 8 tile of a 64 x 64 view: fn(the tile's subtree, the camera, x0, y0, tile).
template <class Fn>
void for_sample_tiles(const Scene& s, const Bvh& bvh, Fn&& fn) {
  const Camera cam(s.camera, 64, 64);
  Subtree sub;
  TraceCounters counters;
  for (int tile = 0; tile < 64; tile += 9) {
    const int x0 = 8 * (tile % 8), y0 = 8 * (tile / 8);
    build_subtree(bvh, pyramid_planes(cam, x0, y0, x0 + 8, y0 + 8), sub, counters);
    fn(sub.packed, cam, x0, y0, tile);
  }
}

class SingleWalkScene : public ::testing::TestWithParam<std::string_view> {};

TEST_P(SingleWalkScene, PerOctantWalksEqualTheGenericWalk) {
  const Scene s = make_builtin_scene(GetParam());
  const Bvh bvh = build_bvh_by_clustering(s);
  apps::Rng rng(11);
  int hits = 0, rays = 0;
  for (const Ray& ray : hard_rays(bvh.packed, s.bounds(), rng)) {
    hits += expect_walks_agree(s, bvh.packed, ray);
    Hit start;
    start.t = rng.uniform(0.2f, 2.0f) * glm::length(s.bounds().hi - s.bounds().lo);  // prunes at once
    start.prim = 0;
    expect_walks_agree(s, bvh.packed, ray, start);
    ++rays;
  }
  // The subtrees A3 and A4 walk: camera rays of a few tiles, and the hard rays of one subtree.
  for_sample_tiles(s, bvh, [&](const PackedTree& sub, const Camera& cam, int x0, int y0, int tile) {
    for (int y = y0; y < y0 + 8; ++y)
      for (int x = x0; x < x0 + 8; ++x) hits += expect_walks_agree(s, sub, cam.pixel_ray(x, y));
    if (tile == 27)
      for (const Ray& ray : hard_rays(sub, s.bounds(), rng)) hits += expect_walks_agree(s, sub, ray);
  });
  EXPECT_GT(rays, 0);
  EXPECT_GT(hits, 0);
}

// traverse_ordered_rays over a run (octants and origins mixed, or a tile's rays from one origin,
// some starting with a hit) gives each ray's traverse_ordered hit and the sum of their counts.
void expect_run_agrees(const Scene& s, const PackedTree& tree, const std::vector<Ray>& rays, apps::Rng& rng) {
  std::vector<Hit> run(rays.size()), alone(rays.size());
  for (std::size_t i = 0; i < rays.size(); i += 3) {
    run[i].t = alone[i].t = rng.uniform(0.2f, 2.0f) * glm::length(s.bounds().hi - s.bounds().lo);
    run[i].prim = alone[i].prim = 0;
  }
  TestTally run_tally, alone_tally;
  traverse_ordered_rays(s, tree, rays.data(), int(rays.size()), run.data(), run_tally);
  for (std::size_t i = 0; i < rays.size(); ++i) traverse_ordered(s, tree, rays[i], alone[i], alone_tally);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(run[i].prim, alone[i].prim) << "ray " << i;
    EXPECT_TRUE(same_bits(run[i].t, alone[i].t) && same_bits(run[i].b1, alone[i].b1) && same_bits(run[i].b2, alone[i].b2));
  }
  EXPECT_EQ(run_tally.boxes, alone_tally.boxes);
  EXPECT_EQ(run_tally.spheres, alone_tally.spheres);
  EXPECT_EQ(run_tally.triangles, alone_tally.triangles);
  EXPECT_EQ(run_tally.sorts, alone_tally.sorts);
}

TEST_P(SingleWalkScene, RunsOfRaysEqualOneRayAtATime) {
  const Scene s = make_builtin_scene(GetParam());
  const Bvh bvh = build_bvh_by_clustering(s);
  apps::Rng rng(12);
  const std::vector<Ray> hard = hard_rays(bvh.packed, s.bounds(), rng);
  ASSERT_GT(hard.size(), 100u);
  expect_run_agrees(s, bvh.packed, hard, rng);
  for_sample_tiles(s, bvh, [&](const PackedTree& sub, const Camera& cam, int x0, int y0, int tile) {
    std::vector<Ray> tile_rays;
    for (int y = y0; y < y0 + 8; ++y)
      for (int x = x0; x < x0 + 8; ++x) tile_rays.push_back(cam.pixel_ray(x, y));
    expect_run_agrees(s, sub, tile_rays, rng);
    if (tile == 27) expect_run_agrees(s, sub, hard_rays(sub, s.bounds(), rng), rng);
  });
}

INSTANTIATE_TEST_SUITE_P(Builtins, SingleWalkScene,
                         ::testing::Values("spheres-a", "spheres-b", "spheres-random", "teapot", "teapots", "whitted"));

TEST(SingleWalk, EmptyAndOnePrimitiveTrees) {
  Scene s;
  const int m = s.add_material({});
  s.add_sphere({{0, 0, 0}, 1.0f}, m);
  const PackedTree empty;
  const Ray ray({0.1f, 0, 5}, {0, 0, -1});
  EXPECT_FALSE(expect_walks_agree(s, empty, ray));
  const Bvh one = build_bvh_by_clustering(s);
  EXPECT_TRUE(expect_walks_agree(s, one.packed, ray));
  s.add_sphere({{3, 0, 0}, 1.0f}, m);  // two: a root node with two primitive children
  const Bvh two = build_bvh_by_clustering(s);
  EXPECT_TRUE(expect_walks_agree(s, two.packed, Ray({3, 0, 5}, {0, 0, -1})));
  EXPECT_FALSE(expect_walks_agree(s, two.packed, Ray({1.5f, 0, 5}, {0, 0, -1})));
}

}  // namespace
}  // namespace gcsim::raytrace
