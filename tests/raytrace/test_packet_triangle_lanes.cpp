// The packet kernel's triangle test (packet_triangle_lanes.hpp: verdict, finish, and the scalar
// test for the lanes it cannot decide) against the scalar watertight test, lane by lane: the same
// hit or miss, and where hit the same distance and barycentrics bit for bit. Hard cases: rays
// through a grid's shared edges and vertices (each of the two triangles of an edge answers as the
// scalar test does, so the id tie-break decides as it does alone), rays parallel to the face and
// grazing it, tmax exactly at, just below and just above the hit, lanes of several octants and
// axis permutations in one packet, and lanes masked off.
#include <gtest/gtest.h>

#include "tests/support/same_bits.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "apps/common/geometry/packet_triangle_lanes.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"
#include "tests/raytrace/triangle_grid.hpp"

namespace gcsim::raytrace {
namespace {

using test_support::same_bits;

#if defined(GCSIM_PACKET_AVX2)
using namespace geometry::packet;

struct LaneAnswer {
  bool hit = false;
  float t = 0, b1 = 0, b2 = 0;
};

// Every live lane of `rays` against `tri` (primitive id 0) in the lanes, starting from tmax[i].
GCSIM_AVX2 void lanes_against(const Triangle& tri, const Ray rays[8], const float tmax[8], unsigned lanes,
                              LaneAnswer out[8]) {
  PrimitiveArrays prims;
  prims.triangles.push_back(tri);
  Lanes l;
  prepare_lanes(prims, tri.bounds(), rays, lanes, l);
  State s;
  for (int i = 0; i < 8; ++i) {
    // A hit at tmax held by a higher id: the id tie-break lets the kernel offer a hit at exactly
    // tmax, which the scalar test accepts too (t <= tmax).
    s.hit[i] = Hit{tmax[i], std::numeric_limits<std::int32_t>::max()};
    s.t[i] = tmax[i];
  }
  unsigned scalar = 0;
  for (int g = 0; g < l.axes_count; ++g) scalar |= intersect_lanes(tri, 0, l, l.axes[g], lanes, s);
  for (; scalar; scalar &= scalar - 1) scalar_triangle(tri, 0, rays, std::countr_zero(scalar), s);
  for (int i = 0; i < 8; ++i) out[i] = {s.hit[i].prim == 0, s.hit[i].t, s.hit[i].b1, s.hit[i].b2};
}

// Packs `rays` eight at a time (the last packet partial) and compares every lane with the scalar test.
int expect_lanes_match(const Triangle& tri, const std::vector<Ray>& rays, const std::vector<float>& tmax) {
  int hits = 0;
  for (std::size_t first = 0; first < rays.size(); first += 8) {
    Ray r[8];
    float tm[8];
    unsigned lanes = 0;
    for (int i = 0; i < 8 && first + i < rays.size(); ++i) r[i] = rays[first + i], tm[i] = tmax[first + i], lanes |= 1u << i;
    for (int i = 0; i < 8; ++i)
      if (!(lanes >> i & 1u)) r[i] = r[0], tm[i] = tm[0];
    LaneAnswer got[8];
    lanes_against(tri, r, tm, lanes, got);
    for (int i = 0; i < 8; ++i) {
      if (!(lanes >> i & 1u)) {
        EXPECT_FALSE(got[i].hit) << "lane " << i << " is masked off but was hit";
        continue;
      }
      float t = 0, b1 = 0, b2 = 0;
      const bool want = intersect_triangle(tri, r[i], tm[i], &t, &b1, &b2);
      EXPECT_EQ(got[i].hit, want) << "ray " << first + i;
      if (!want || !got[i].hit) continue;
      ++hits;
      EXPECT_TRUE(same_bits(got[i].t, t)) << "ray " << first + i << ": " << got[i].t << " vs " << t;
      EXPECT_TRUE(same_bits(got[i].b1, b1) && same_bits(got[i].b2, b2)) << "ray " << first + i;
    }
  }
  return hits;
}

bool host_runs_avx2() { return __builtin_cpu_supports("avx2"); }

// Rays from above and below the grid through its vertices, edge midpoints and cell centres, with
// small tilts of both signs (mixed octants and, for steep tilts, other axis permutations).
TEST(PacketTriangleLanes, GridEdgesAndVerticesAsTheScalarTest) {
  if (!host_runs_avx2()) GTEST_SKIP() << "no AVX2 on this host: the lanes are traced one by one";
  const std::vector<Triangle> grid = testing::unit_square_grid(4);
  std::vector<Ray> rays;
  std::vector<float> tmax;
  for (int y = 0; y <= 8; ++y)
    for (int x = 0; x <= 8; ++x)
      for (float above : {1.0f, -1.0f})
        for (float tilt : {0.0f, 0.25f, -0.125f, 3.0f}) {
          const glm::vec3 target(x / 8.0f, y / 8.0f, 0.0f), dir(tilt, -tilt * 0.5f, -above);
          rays.emplace_back(target - 2.0f * dir, dir);
          tmax.push_back(kInfinity);
        }
  int hits = 0;
  for (const Triangle& tri : grid) hits += expect_lanes_match(tri, rays, tmax);
  // Each interior grid point is on several triangles: far more hits than triangles.
  EXPECT_GT(hits, int(grid.size()) * 4);
}

// tmax exactly at the scalar test's t, one float below and one above, and tmin at it: the same
// inclusive upper and exclusive lower bounds in the lanes.
TEST(PacketTriangleLanes, DistanceExactlyAtTheBounds) {
  if (!host_runs_avx2()) GTEST_SKIP() << "no AVX2 on this host";
  const Triangle tri{{0.1f, 0.2f, 1.3f}, {2.7f, 0.1f, 1.1f}, {0.4f, 2.9f, 1.7f}};
  std::vector<Ray> rays;
  std::vector<float> tmax;
  for (int k = 0; k < 12; ++k) {
    const Ray r(glm::vec3(0.3f + 0.1f * k, 0.4f + 0.07f * k, -0.5f), glm::vec3(0.01f * k, 0.02f, 1.0f));
    float t, b1, b2;
    ASSERT_TRUE(intersect_triangle(tri, r, kInfinity, &t, &b1, &b2));
    for (float m : {t, std::nextafter(t, 0.0f), std::nextafter(t, kInfinity)}) rays.push_back(r), tmax.push_back(m);
    Ray from_hit(r.origin, r.direction, t);  // tmin exactly at the hit: excluded
    rays.push_back(from_hit), tmax.push_back(kInfinity);
  }
  const int hits = expect_lanes_match(tri, rays, tmax);
  EXPECT_GE(hits, 12);  // at least every ray whose tmax is at or above its hit
}

// Rays in the triangle's plane (edge functions 0 or det 0), just off it, and grazing at steep
// angles; origins in the plane, on an edge and on a vertex.
TEST(PacketTriangleLanes, ParallelAndGrazingRays) {
  if (!host_runs_avx2()) GTEST_SKIP() << "no AVX2 on this host";
  const Triangle tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Ray> rays;
  std::vector<float> tmax;
  for (float z : {0.0f, 1e-7f, -1e-7f, 1e-3f})
    for (float dz : {0.0f, -1e-6f, 1e-6f, -1e-3f})
      for (const glm::vec3& o : {glm::vec3(-1, 0.25f, 0), glm::vec3(-1, 0, 0), glm::vec3(-1, -1, 0), glm::vec3(0.5f, 0.5f, 0)}) {
        rays.emplace_back(o + glm::vec3(0, 0, z), glm::vec3(1, 0.01f, dz));
        tmax.push_back(kInfinity);
      }
  expect_lanes_match(tri, rays, tmax);
}

#else
TEST(PacketTriangleLanes, NotBuiltOnThisCompiler) { GTEST_SKIP() << "the AVX2 packet kernel needs x86-64 and GCC or Clang"; }
#endif

}  // namespace
}  // namespace gcsim::raytrace
