// The packet traversal must give every lane exactly what traverse_ordered gives its ray alone:
// hit, distance, barycentrics, primitive, and the counts the simulated time is charged from. Hard
// cases: mixed octants in one packet, rays grazing box edges and lying in slab planes, lanes
// masked off, lanes that start with a hit, empty and one-primitive trees. And the camera's four-
// at-a-time rays equal its single ones bit for bit.
#include <gtest/gtest.h>

#include "tests/support/same_bits.hpp"

#include <array>
#include <cstring>
#include <string_view>
#include <utility>
#include <vector>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/geometry/packet_traversal.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/common/rng.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "tests/raytrace/box_corner_rays.hpp"

namespace gcsim::raytrace {
namespace {

using test_support::same_bits;

void expect_same_tally(const TestTally& a, const TestTally& b, int lane) {
  EXPECT_EQ(a.boxes, b.boxes) << "lane " << lane;
  EXPECT_EQ(a.spheres, b.spheres) << "lane " << lane;
  EXPECT_EQ(a.triangles, b.triangles) << "lane " << lane;
  EXPECT_EQ(a.sorts, b.sorts) << "lane " << lane;
}

// One packet against the single-ray walk, lane by lane; lanes outside `lanes` stay untouched.
// `start` is every lane's hit before the walk. Returns how many lanes hit something.
int expect_packet_matches(const Scene& s, const PackedTree& tree, const Ray rays[8], unsigned lanes,
                          const Hit& start = Hit{}) {
  Hit hits[8];
  TestTally tallies[8];
  const Hit sentinel{1.5f, 12345, 0.25f, 0.5f};
  for (int i = 0; i < 8; ++i) hits[i] = lanes >> i & 1u ? start : sentinel;
  traverse_ordered_packet(s, tree, rays, lanes, hits, tallies);
  int hit_lanes = 0;
  for (int i = 0; i < 8; ++i) {
    if (!(lanes >> i & 1u)) {
      EXPECT_EQ(hits[i].prim, sentinel.prim) << "lane " << i << " is masked off but was written";
      expect_same_tally(tallies[i], TestTally{}, i);
      continue;
    }
    Hit ref = start;
    TestTally ref_tally;
    traverse_ordered(s, tree, rays[i], ref, ref_tally);
    EXPECT_EQ(hits[i].prim, ref.prim) << "lane " << i;
    EXPECT_TRUE(same_bits(hits[i].t, ref.t)) << "lane " << i << ": " << hits[i].t << " vs " << ref.t;
    EXPECT_TRUE(same_bits(hits[i].b1, ref.b1) && same_bits(hits[i].b2, ref.b2)) << "lane " << i;
    expect_same_tally(tallies[i], ref_tally, i);
    hit_lanes += ref.valid();
  }
  return hit_lanes;
}

class PacketScene : public ::testing::TestWithParam<std::string_view> {};

// Every 4 x 2 block of a small image, over the whole tree: the image's centre lines put rays of
// different octants into one packet, and the border blocks of a 37-pixel image are partial.
TEST_P(PacketScene, EveryBlockOfPixelsMatchesSingleRays) {
  const Scene s = make_builtin_scene(GetParam());
  const Bvh bvh = build_bvh_by_clustering(s);
  const int size = 37;
  const Camera cam(s.camera, size, size);
  int hit_lanes = 0;
  for (int by = 0; by < size; by += 2)
    for (int bx = 0; bx < size; bx += 4) {
      Ray rays[8];
      unsigned lanes = 0;
      for (int i = 0; i < 8; ++i) {
        const int x = bx + i % 4, y = by + i / 4;
        if (x >= size || y >= size) continue;
        rays[i] = cam.pixel_ray(x, y);
        lanes |= 1u << i;
      }
      hit_lanes += expect_packet_matches(s, bvh.packed, rays, lanes);
    }
  EXPECT_GT(hit_lanes, 0);
}

INSTANTIATE_TEST_SUITE_P(Builtins, PacketScene,
                         ::testing::Values("spheres-a", "spheres-b", "spheres-random", "teapot", "teapots", "whitted"));

// Rays aimed at the corners and edge midpoints of every node's child boxes, from points around the
// scene (directions of all octants mixed), and axis-parallel rays lying in the boxes' slab planes
// (0 * inf = NaN in the slab test); random lane masks, and lanes that start with a hit already.
TEST(PacketTraversal, GrazingRaysMixedOctantsAndMaskedLanes) {
  const Scene s = make_builtin_scene("teapots");
  const Bvh bvh = build_bvh_by_clustering(s);
  apps::Rng rng(5);
  const Bounds3 b = s.bounds();
  const glm::vec3 c = 0.5f * (b.lo + b.hi), reach = 2.0f * (b.hi - b.lo);
  std::vector<Ray> rays = testing::box_corner_rays(bvh.packed, b, rng, 0, false);
  // In the root box's own face planes (the packet tests the root box apart), and from inside it.
  const Bounds3& root = bvh.packed.root_box;
  for (int i = 0; i < 64; ++i) {
    const int axis = i % 3, along = (i / 3) % 3;
    if (axis == along) continue;
    glm::vec3 o = c + 0.3f * (b.hi - b.lo) * glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    o[axis] = i % 2 ? root.lo[axis] : root.hi[axis];
    glm::vec3 d(0.0f);
    d[along] = i % 4 < 2 ? 1.0f : -1.0f;
    rays.emplace_back(o, d);
    rays.emplace_back(c, glm::normalize(glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))));
  }
  int hit_lanes = 0;
  for (std::size_t first = 0; first + 8 <= rays.size(); first += 8) {
    const unsigned lanes = first % 3 == 0 ? 0xffu : (rng.next_u32() & 0xffu);
    hit_lanes += expect_packet_matches(s, bvh.packed, &rays[first], lanes);
    Hit start;
    start.t = rng.uniform(0.5f, 1.5f) * glm::length(reach);  // prunes part of the walk at once
    start.prim = 0;
    expect_packet_matches(s, bvh.packed, &rays[first], lanes, start);
  }
  EXPECT_GT(hit_lanes, 0);
}

TEST(PacketTraversal, EmptyAndOnePrimitiveTrees) {
  Scene s;
  const int m = s.add_material({});
  s.add_sphere({{0, 0, 0}, 1.0f}, m);
  Ray rays[8];
  for (int i = 0; i < 8; ++i) rays[i] = Ray({0.1f * i, 0, 5}, {0, 0, -1});
  const PackedTree empty;
  expect_packet_matches(s, empty, rays, 0xffu);
  const Bvh one = build_bvh_by_clustering(s);
  EXPECT_EQ(expect_packet_matches(s, one.packed, rays, 0x7fu), 7);
}

TEST(PacketTraversal, CameraRaysInLanesEqualSingleRays) {
  // pixel_rays makes eight at a time (AVX), then four: whole images of 70, 81 and 4288 pixels take both.
  Scene s = make_builtin_scene("teapots");
  // Teapots' own view, then views down each axis both ways and along diagonals, where the
  // dominant axis changes across the image and |components| tie (every kz, kx, ky and swap).
  std::vector<scene::Camera> views = {s.camera};
  for (const glm::dvec3 at : {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0.001), glm::dvec3(0, -1, 0.001),
                              glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(1, 1, 0), glm::dvec3(1, -1, 1),
                              glm::dvec3(-1, 1, -1), glm::dvec3(0, 1, 1), glm::dvec3(1, 0, -1)}) {
    scene::Camera c = s.camera;
    c.eye = glm::dvec3(0.25, -0.5, 2.0);
    c.look_at = c.eye + at;
    c.fov_y_degrees = 100.0;
    views.push_back(c);
  }
  std::array<int, 3> kz_seen{};
  // 9 x 9: the centre pixel's ray is the view direction itself, where |components| tie exactly.
  for (const scene::Camera& view : views)
  for (const auto& [width, height] : {std::pair{7, 10}, std::pair{9, 9}, std::pair{64, 67}}) {
    const Camera cam(view, width, height);
    std::vector<int> xs, ys;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) xs.push_back(x), ys.push_back(y);
    std::vector<Ray> rays(xs.size());
    cam.pixel_rays(xs.data(), ys.data(), int(xs.size()), rays.data());
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Ray ref = cam.pixel_ray(xs[i], ys[i]);
      const Ray& r = rays[i];
      ASSERT_EQ(std::memcmp(&r.origin, &ref.origin, sizeof ref.origin), 0);
      ASSERT_EQ(std::memcmp(&r.direction, &ref.direction, sizeof ref.direction), 0) << xs[i] << ", " << ys[i];
      ASSERT_EQ(std::memcmp(&r.inv_direction, &ref.inv_direction, sizeof ref.inv_direction), 0);
      ASSERT_TRUE(r.kx == ref.kx && r.ky == ref.ky && r.kz == ref.kz && r.tmin == ref.tmin);
      ASSERT_TRUE(same_bits(r.shear_x, ref.shear_x) && same_bits(r.shear_y, ref.shear_y) &&
                  same_bits(r.shear_z, ref.shear_z));
      ++kz_seen[std::size_t(ref.kz)];
    }
  }
  for (int k = 0; k < 3; ++k) EXPECT_GT(kz_seen[std::size_t(k)], 100) << "axis " << k;
}

}  // namespace
}  // namespace gcsim::raytrace
