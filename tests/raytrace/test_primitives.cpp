// Hard cases of the intersection routines: watertightness, axis-parallel rays, grazing hits,
// degenerate triangles, tiny and huge spheres.
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "apps/common/rng.hpp"
#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/sphere.hpp"
#include "apps/common/geometry/triangle.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "tests/raytrace/triangle_grid.hpp"

namespace gcsim::raytrace {
namespace {

// A unit square split into a fan of triangles around an interior vertex, and a grid of quads:
// every ray aimed at the inside of the square must hit exactly one... or at least one triangle.
std::vector<Triangle> fan(glm::vec3 centre, int n) {
  std::vector<Triangle> out;
  const glm::vec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < n; ++k) {
      const glm::vec3 a = glm::mix(corners[i], corners[(i + 1) % 4], float(k) / n);
      const glm::vec3 b = glm::mix(corners[i], corners[(i + 1) % 4], float(k + 1) / n);
      out.push_back({centre, a, b});
    }
  return out;
}

int hits(const std::vector<Triangle>& tris, const Ray& r) {
  int count = 0;
  for (const auto& t : tris) {
    float th, b1, b2;
    if (intersect_triangle(t, r, kInfinity, &th, &b1, &b2)) ++count;
  }
  return count;
}

TEST(Watertight, RaysThroughSharedVerticesAndEdgesNeverMiss) {
  const auto tris = fan({0.37f, 0.61f, 0.0f}, 7);
  apps::Rng rng(7);
  // Aim exactly at the shared centre vertex and at points of shared edges from many origins.
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 o(rng.uniform(-3.0f, 4.0f), rng.uniform(-3.0f, 4.0f), rng.uniform(0.5f, 5.0f));
    const auto& t = tris[i % tris.size()];
    const float s = rng.uniform();
    for (glm::vec3 target : {t.p0, t.p1, glm::mix(t.p0, t.p1, s), glm::mix(t.p0, t.p2, s)}) {
      if (target.x <= 0 || target.x >= 1 || target.y <= 0 || target.y >= 1) continue;  // outer boundary
      const Ray r(o, target - o);
      EXPECT_GE(hits(tris, r), 1) << "crack at (" << target.x << ", " << target.y << ")";
    }
  }
}

TEST(Watertight, GridOfQuadsHasNoCracksForAxisParallelRays) {
  const int n = 16;
  const std::vector<Triangle> tris = testing::unit_square_grid(n);
  // Straight down onto every vertex and edge midpoint: direction (0, 0, -1) has two zero components.
  for (int y = 1; y < 2 * n; ++y)
    for (int x = 1; x < 2 * n; ++x) {
      const Ray r({x / float(2 * n), y / float(2 * n), 1.0f}, {0.0f, 0.0f, -1.0f});
      EXPECT_GE(hits(tris, r), 1) << x << "," << y;
    }
}

TEST(AxisParallel, BoxTestWithZeroDirectionComponents) {
  const Bounds3 box{{0, 0, 0}, {1, 1, 1}};
  float entry;
  // Inside the slab of the zero components: hit.
  EXPECT_TRUE(intersect_box(box, Ray({0.5f, 0.5f, -1.0f}, {0, 0, 1}), kInfinity, &entry));
  EXPECT_NEAR(entry, 1.0f, 1e-5f);
  // Outside a slab with zero direction component: miss.
  EXPECT_FALSE(intersect_box(box, Ray({1.5f, 0.5f, -1.0f}, {0, 0, 1}), kInfinity, &entry));
  // Exactly on a slab plane (0 * inf = NaN): the boundary counts as inside.
  EXPECT_TRUE(intersect_box(box, Ray({1.0f, 0.5f, -1.0f}, {0, 0, 1}), kInfinity, &entry));
  EXPECT_TRUE(intersect_box(box, Ray({0.0f, 1.0f, -1.0f}, {0, 0, 1}), kInfinity, &entry));
  // Negative zero.
  EXPECT_TRUE(intersect_box(box, Ray({0.5f, 0.5f, 2.0f}, {-0.0f, 0.0f, -1.0f}), kInfinity, &entry));
}

TEST(AxisParallel, SphereAndTriangle) {
  float t, b1, b2;
  EXPECT_TRUE(intersect_sphere({{0, 0, 0}, 1}, Ray({0, 0, -5}, {0, 0, 1}), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  EXPECT_TRUE(intersect_sphere({{0, 0, 0}, 1}, Ray({-5, 0, 0}, {1, 0, 0}), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  const Triangle tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(intersect_triangle(tri, Ray({0.25f, 0.25f, 1}, {0, 0, -1}), kInfinity, &t, &b1, &b2));
  EXPECT_FLOAT_EQ(t, 1.0f);
  EXPECT_FLOAT_EQ(b1, 0.25f);
  EXPECT_FALSE(intersect_triangle(tri, Ray({0.75f, 0.75f, 1}, {0, 0, -1}), kInfinity, &t, &b1, &b2));
}

TEST(Grazing, TangentRaysAndEdgeOnTriangles) {
  float t, b1, b2;
  const Sphere s{{0, 0, 0}, 1};
  // Just inside and just outside the silhouette.
  EXPECT_TRUE(intersect_sphere(s, Ray({-5, 0.9999f, 0}, {1, 0, 0}), kInfinity, &t));
  EXPECT_FALSE(intersect_sphere(s, Ray({-5, 1.0001f, 0}, {1, 0, 0}), kInfinity, &t));
  // Whatever the tangent ray does, the result is finite and the box agrees.
  if (intersect_sphere(s, Ray({-5, 1.0f, 0}, {1, 0, 0}), kInfinity, &t)) {
    EXPECT_TRUE(std::isfinite(t));
    float entry;
    EXPECT_TRUE(intersect_box(s.bounds(), Ray({-5, 1.0f, 0}, {1, 0, 0}), kInfinity, &entry));
  }
  // A ray in the plane of a triangle sees it edge-on: no hit, no NaN.
  const Triangle tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(intersect_triangle(tri, Ray({-1, 0.2f, 0}, {1, 0, 0}), kInfinity, &t, &b1, &b2));
  // Nearly grazing: hit with a finite t.
  const Ray r({-1, 0.2f, 1e-3f}, glm::normalize(glm::vec3(1, 0, -1e-3f)));
  if (intersect_triangle(tri, r, kInfinity, &t, &b1, &b2)) {
    EXPECT_TRUE(std::isfinite(t));
    EXPECT_GT(t, 0);
  }
}

TEST(Degenerate, ZeroAreaTrianglesAreNeverHit) {
  float t, b1, b2;
  apps::Rng rng(3);
  const Triangle point{{0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}};
  const Triangle line{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}};
  const Triangle twice{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 o(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(0.1f, 3));
    const glm::vec3 target(rng.uniform(0, 1), rng.uniform(0, 1), 0);
    for (const Triangle& tri : {point, line, twice}) {
      EXPECT_FALSE(intersect_triangle(tri, Ray(o, target - o), kInfinity, &t, &b1, &b2));
      EXPECT_FALSE(intersect_triangle(tri, Ray(o, tri.p0 - o), kInfinity, &t, &b1, &b2));
    }
  }
  EXPECT_FALSE(point.bounds().empty());
}

TEST(Scale, TinyAndHugeSpheres) {
  float t;
  for (float r : {1e-4f, 1e-2f, 1.0f, 1e2f, 1e4f}) {
    const Sphere s{{3 * r, -2 * r, 7 * r}, r};
    const glm::vec3 eye = s.center + glm::vec3(0, 0, -10 * r);
    ASSERT_TRUE(intersect_sphere(s, Ray(eye, {0, 0, 1}), kInfinity, &t)) << r;
    EXPECT_NEAR(t, 9 * r, 9 * r * 1e-5f) << r;
    // Off-centre: t = 10r - sqrt(r^2 - d^2).
    const float d = 0.6f * r;
    ASSERT_TRUE(intersect_sphere(s, Ray(eye + glm::vec3(d, 0, 0), {0, 0, 1}), kInfinity, &t)) << r;
    EXPECT_NEAR(t, 10 * r - 0.8f * r, r * 1e-4f) << r;
    EXPECT_FALSE(intersect_sphere(s, Ray(eye + glm::vec3(1.01f * r, 0, 0), {0, 0, 1}), kInfinity, &t)) << r;
    // From far away (1e3 radii): the stable discriminant keeps the hit.
    const glm::vec3 far = s.center + glm::vec3(0, 0, -1000 * r);
    ASSERT_TRUE(intersect_sphere(s, Ray(far + glm::vec3(0.5f * r, 0, 0), {0, 0, 1}), kInfinity, &t)) << r;
    EXPECT_NEAR(t, 1000 * r - std::sqrt(0.75f) * r, 1000 * r * 1e-6f) << r;
    // From inside: the far side.
    ASSERT_TRUE(intersect_sphere(s, Ray(s.center, {1, 0, 0}), kInfinity, &t));
    EXPECT_NEAR(t, r, r * 1e-5f);
  }
}

// Bounds3::distance_to (maxss, no branches) against the glm formulation it replaced, bit for bit:
// points inside, on faces, edges and corners, at +-0 coordinates, far away, and a flat box.
TEST(BoxDistance, BranchFreeEqualsTheGlmFormulation) {
  apps::Rng rng(3);
  const Bounds3 boxes[] = {{{-1, -2, -3}, {1, 2, 3}}, {{0, 0, 0}, {0, 0, 0}}, {{-0.0f, 1, 2}, {0.0f, 1, 5}},
                           {{1e-20f, -1e20f, 3}, {1e-10f, 1e20f, 3}}};
  for (const Bounds3& b : boxes) {
    std::vector<glm::vec3> points;
    for (int i = 0; i < 27; ++i) {  // corners, edge and face midpoints, the centre
      glm::vec3 p;
      for (int a = 0, k = i; a < 3; ++a, k /= 3) p[a] = k % 3 == 0 ? b.lo[a] : k % 3 == 1 ? b.center()[a] : b.hi[a];
      points.push_back(p);
      points.push_back(-p);
    }
    for (int i = 0; i < 200; ++i)
      points.push_back(b.center() + glm::vec3(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4)) *
                                        glm::max(b.extent(), glm::vec3(1.0f)));
    points.push_back({-0.0f, -0.0f, -0.0f});
    for (const glm::vec3& p : points) {
      const glm::vec3 d = glm::max(glm::max(b.lo - p, p - b.hi), glm::vec3(0.0f));
      const float ref = std::sqrt(glm::dot(d, d)), got = b.distance_to(p);
      EXPECT_EQ(std::memcmp(&ref, &got, sizeof ref), 0) << ref << " vs " << got;
    }
  }
}

// The in-line steps equal std::nextafter towards +-inf bit for bit: at zeros, denormals, the
// largest finite float, the infinities, NaN, and on random bit patterns of every exponent.
TEST(NextFloat, EqualsNextafterForEveryKindOfFloat) {
  constexpr float kMax = std::numeric_limits<float>::max(), kTiny = std::numeric_limits<float>::denorm_min();
  std::vector<float> values = {0.0f, -0.0f, kTiny, -kTiny, std::numeric_limits<float>::min(), 1.0f, -1.0f, kMax,
                               -kMax, kInfinity, -kInfinity, std::numeric_limits<float>::quiet_NaN()};
  apps::Rng rng(9);
  for (int i = 0; i < 200000; ++i)
    values.push_back(std::bit_cast<float>(rng.next_u32()));
  auto same = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); };
  for (float v : values) {
    ASSERT_TRUE(same(next_float_up(v), std::nextafter(v, kInfinity))) << v;
    ASSERT_TRUE(same(next_float_down(v), std::nextafter(v, -kInfinity))) << v;
  }
}

// largest_with_sqrt_at_most(m) = T must split the floats exactly: sqrt(s) > m iff s > T, checked
// at T and its neighbours and over random squares, for limits tiny, huge, zero, infinite and NaN.
TEST(SqrtThreshold, SplitsTheFloatsAsTheSquareRootDoes) {
  apps::Rng rng(8);
  std::vector<float> limits = {0.0f, -0.0f, -1.0f, 1.0f, 2.0f, 1e-30f, 1e-20f, 3e-23f, 1.8e19f, 2e19f, 1e30f,
                               std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(), kInfinity,
                               -kInfinity, std::numeric_limits<float>::quiet_NaN()};
  for (int i = 0; i < 2000; ++i) limits.push_back(std::exp2(rng.uniform(-60, 60)) * rng.uniform(1, 2));
  for (float m : limits) {
    const float t = largest_with_sqrt_at_most(m);
    std::vector<float> squares = {t, next_float_up(t), next_float_down(t), 0.0f, kInfinity, m * m};
    for (int k = 0; k < 20; ++k) squares.push_back(m * m * rng.uniform(0.999f, 1.001f));
    for (float s : squares) {
      if (std::isnan(s) || s < 0.0f) continue;
      ASSERT_EQ(std::sqrt(s) > m, s > t) << "limit " << m << " square " << s << " threshold " << t;
    }
  }
}

}  // namespace
}  // namespace gcsim::raytrace
