// The packet kernel's sphere test (packet_sphere_lanes.hpp: intersect_sphere four lanes at a time
// in doubles) against the scalar test, lane by lane: the same hit or miss, and where hit the same
// distance bit for bit. Hard cases: rays grazing the sphere (discriminant 0 or just either side),
// origins inside, on the surface and at the centre, rays pointing away, tmax exactly at, just below
// and just above the hit, tmin at the hit, tiny and huge radii far from the origin, lanes of
// several octants in one packet, and lanes masked off.
#include <gtest/gtest.h>

#include "tests/support/same_bits.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "apps/common/geometry/packet_sphere_lanes.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {
namespace sphere_lanes_cases {  // named: a unity build joins this file with the triangle lanes test

using test_support::same_bits;

#if defined(GCSIM_PACKET_AVX2)
using namespace geometry::packet;

struct LaneAnswer {
  bool hit = false;
  float t = 0;
};

// Every live lane of `rays` against `sphere` (primitive id 0) in the lanes, starting from tmax[i].
GCSIM_AVX2 void lanes_against(const Sphere& sphere, const Ray rays[8], const float tmax[8], unsigned lanes,
                              LaneAnswer out[8]) {
  PrimitiveArrays prims;
  prims.spheres.push_back(sphere);
  Lanes l;
  prepare_lanes(prims, sphere.bounds(), rays, lanes, l);
  State s;
  for (int i = 0; i < 8; ++i) {
    // A hit at tmax held by a higher id: the id tie-break lets a hit at exactly tmax be offered.
    s.hit[i] = Hit{tmax[i], std::numeric_limits<std::int32_t>::max()};
    s.t[i] = tmax[i];
  }
  sphere_lanes(sphere, 0, l, lanes, s);
  for (int i = 0; i < 8; ++i) out[i] = {s.hit[i].prim == 0, s.hit[i].t};
}

// Packs `rays` eight at a time (the last packet partial, every third packet with lanes 2 and 5
// masked off) and compares every lane with the scalar test.
int expect_lanes_match(const Sphere& sphere, const std::vector<Ray>& rays, const std::vector<float>& tmax) {
  int hits = 0, packet = 0;
  for (std::size_t first = 0; first < rays.size(); first += 8, ++packet) {
    Ray r[8];
    float tm[8];
    unsigned lanes = 0;
    for (int i = 0; i < 8 && first + i < rays.size(); ++i) r[i] = rays[first + i], tm[i] = tmax[first + i], lanes |= 1u << i;
    if (packet % 3 == 2 && lanes != 0b100100u) lanes &= ~0b100100u;
    for (int i = 0; i < 8; ++i)
      if (first + i >= rays.size()) r[i] = r[0], tm[i] = tm[0];
    LaneAnswer got[8];
    lanes_against(sphere, r, tm, lanes, got);
    for (int i = 0; i < 8; ++i) {
      if (!(lanes >> i & 1u)) {
        EXPECT_FALSE(got[i].hit) << "lane " << i << " is masked off but was hit";
        continue;
      }
      float t = 0;
      const bool want = intersect_sphere(sphere, r[i], tm[i], &t);
      EXPECT_EQ(got[i].hit, want) << "ray " << first + i;
      if (!want || !got[i].hit) continue;
      ++hits;
      EXPECT_TRUE(same_bits(got[i].t, t)) << "ray " << first + i << ": " << got[i].t << " vs " << t;
    }
  }
  return hits;
}

bool host_runs_avx2() { return __builtin_cpu_supports("avx2"); }

// Rays parallel to z at offsets around the radius (the discriminant through 0), from in front,
// behind and inside, in all four x/y octants.
TEST(PacketSphereLanes, GrazingAndInsideRaysAsTheScalarTest) {
  if (!host_runs_avx2()) GTEST_SKIP() << "no AVX2 on this host: the lanes are traced one by one";
  const Sphere sphere{{0.25f, -0.5f, 3.0f}, 0.75f};
  std::vector<Ray> rays;
  std::vector<float> tmax;
  for (float offset : {0.0f, 0.5f, 0.7499999f, 0.75f, 0.7500001f, 0.76f})
    for (float angle : {0.0f, 0.7f, 1.9f, 3.3f})
      for (float z : {-2.0f, 3.0f, 3.7f, 3.75f, 6.0f})  // in front, centre plane, inside, on the surface, behind
        for (float dz : {1.0f, -1.0f}) {
          const glm::vec3 o(0.25f + offset * std::cos(angle), -0.5f + offset * std::sin(angle), z);
          rays.emplace_back(o, glm::vec3(1e-3f * std::cos(angle), -2e-3f, dz));
          tmax.push_back(kInfinity);
        }
  rays.emplace_back(sphere.center, glm::vec3(0.3f, -0.4f, 1.0f));  // from the centre
  tmax.push_back(kInfinity);
  const int hits = expect_lanes_match(sphere, rays, tmax);
  EXPECT_GT(hits, 50);
}

// tmax exactly at the scalar test's t, one float below and one above, and tmin at it.
TEST(PacketSphereLanes, DistanceExactlyAtTheBounds) {
  if (!host_runs_avx2()) GTEST_SKIP() << "no AVX2 on this host";
  const Sphere sphere{{0.1f, 0.2f, 5.3f}, 1.3f};
  std::vector<Ray> rays;
  std::vector<float> tmax;
  for (int k = 0; k < 12; ++k) {
    const Ray r(glm::vec3(0.3f - 0.1f * k, 0.4f + 0.07f * k, -0.5f), glm::vec3(0.01f * k, -0.02f, 1.0f));
    float t;
    ASSERT_TRUE(intersect_sphere(sphere, r, kInfinity, &t));
    for (float m : {t, std::nextafter(t, 0.0f), std::nextafter(t, kInfinity)}) rays.push_back(r), tmax.push_back(m);
    rays.push_back(Ray(r.origin, r.direction, t)), tmax.push_back(kInfinity);  // tmin at the near hit: the far one
  }
  // At least the rays whose tmax is a float above the hit; at tmax exactly, the double t may
  // lie above the float tmax and miss, in the lanes as in the scalar test.
  const int hits = expect_lanes_match(sphere, rays, tmax);
  EXPECT_GE(hits, 12);
}

// Tiny and huge spheres far from the rays' origins, hit and just missed: the double test's range.
TEST(PacketSphereLanes, TinyAndHugeSpheresFarAway) {
  if (!host_runs_avx2()) GTEST_SKIP() << "no AVX2 on this host";
  for (float radius : {1e-4f, 1.0f, 1e4f}) {
    const Sphere sphere{{3e3f, -2e3f, 4e4f}, radius};
    std::vector<Ray> rays;
    std::vector<float> tmax;
    for (float miss : {0.0f, 0.5f, 0.999f, 1.0f, 1.001f})
      for (float sx : {1.0f, -1.0f}) {
        const glm::vec3 o(sx * 7.0f, 11.0f, -13.0f);
        const glm::vec3 to = sphere.center + glm::vec3(miss * radius, 0.0f, 0.0f) - o;
        rays.emplace_back(o, to), tmax.push_back(kInfinity);
        rays.emplace_back(o, -to), tmax.push_back(kInfinity);  // pointing away
      }
    expect_lanes_match(sphere, rays, tmax);
  }
}

#else
TEST(PacketSphereLanes, NotBuiltOnThisCompiler) { GTEST_SKIP() << "the AVX2 packet kernel needs x86-64 and GCC or Clang"; }
#endif

}  // namespace sphere_lanes_cases
}  // namespace gcsim::raytrace
