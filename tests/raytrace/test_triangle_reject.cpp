// The SSE rejection in front of the watertight triangle test must never reject a triangle the
// full test hits, and finishing the test from its values must answer as the full test does, on
// the hard cases: rays through vertices and along shared edges, axis-parallel and grazing rays,
// degenerate triangles, coordinates near float's safe range.
#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/same_bits.hpp"

#include "apps/common/geometry/traversal.hpp"
#include "apps/common/geometry/triangle_finish.hpp"
#include "apps/common/geometry/triangle_reject.hpp"
#include "apps/common/rng.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "tests/raytrace/triangle_grid.hpp"

namespace gcsim::raytrace {
namespace {

struct Agreement {
  int hits = 0, misses = 0, rejected = 0, inside = 0;
};

using test_support::same_bits;

#if defined(__AVX__)
// Two triangles rejected at once (a tree node whose children are both triangles) answer as each
// does alone: the same verdict and, unless unsure, the same rows bit for bit.
void check_pair(const Triangle& first, const Triangle& second, const TriangleRejectRay& r) {
  const geometry::RejectPair pair = geometry::triangle_verdicts2(first, second, r);
  const Triangle* tris[2] = {&first, &second};
  for (int k = 0; k < 2; ++k) {
    __m128 alone[4], together[4];
    const RejectVerdict v = triangle_verdict(*tris[k], r, alone);
    ASSERT_EQ(pair.verdict[k], v) << "triangle " << k << " of the pair";
    if (v == RejectVerdict::unsure) continue;
    pair.rows(k, together);
    alignas(16) float a[4], b[4];
    for (int i = 0; i < 4; ++i) {
      _mm_store_ps(a, alone[i]);
      _mm_store_ps(b, together[i]);
      ASSERT_EQ(std::memcmp(a, b, 3 * sizeof(float)), 0) << "row " << i << " of triangle " << k;
    }
  }
}
#endif

// Checks one ray against one triangle; returns through `a` how often each outcome happened.
// `partner`: another triangle, rejected together with this one as a tree node's two children.
void check(const Triangle& tri, const Triangle& partner, const Ray& ray, Agreement& a) {
  float t, b1, b2;
  const bool hit = intersect_triangle(tri, ray, kInfinity, &t, &b1, &b2);
  const bool rejected = triangle_surely_missed(tri, TriangleRejectRay(ray));
  // With the range check skipped for a box holding the triangle (a tree's root box): the same.
  TriangleRejectRay within(ray);
  within.assume_within(union_of(tri.bounds(), Bounds3{ray.origin + 0.5f, ray.origin + 2.0f}));
  ASSERT_EQ(triangle_surely_missed(tri, within), rejected);
#if defined(__AVX__)
  // Paired with its partner, either way round.
  TriangleRejectRay wider(ray);  // the range check skipped for both
  wider.assume_within(union_of(union_of(tri.bounds(), partner.bounds()), Bounds3{ray.origin + 0.5f, ray.origin + 2.0f}));
  const TriangleRejectRay plain(ray);
  for (const TriangleRejectRay* r : {static_cast<const TriangleRejectRay*>(&wider), &plain}) {
    check_pair(tri, partner, *r);
    check_pair(partner, tri, *r);
  }
#endif
  hit ? ++a.hits : ++a.misses;
  a.rejected += rejected;
  // test_primitive_quickly (the uniformity test's fill) against test_primitive: hit and count.
  PrimitiveArrays one;
  one.triangles.push_back(tri);
  Hit quick, full;
  TestTally quick_tally, full_tally;
  test_primitive_quickly(one, 0, ray, quick, quick_tally);
  test_primitive(one, 0, ray, full, full_tally);
  ASSERT_TRUE(quick.prim == full.prim && same_bits(quick.t, full.t) && same_bits(quick.b1, full.b1) &&
              same_bits(quick.b2, full.b2));
  ASSERT_EQ(quick_tally.triangles, full_tally.triangles);
  // Inside all three edges: finishing from the rejection's own sheared vertices and edge
  // functions answers as the full test does, bit for bit, for any tmax (also exactly t).
  __m128 rows[4];
  if (triangle_verdict(tri, TriangleRejectRay(ray), rows) == RejectVerdict::inside) {
    alignas(16) float x[4], y[4], z[4], e[4];  // lanes: vertices a, b, c (p0, p1, p2); edge functions
    _mm_store_ps(x, rows[0]);
    _mm_store_ps(y, rows[1]);
    _mm_store_ps(z, rows[2]);
    _mm_store_ps(e, rows[3]);
    ++a.inside;
    for (float tmax : {kInfinity, hit ? t : 1.0f, hit ? std::nextafter(t, 0.0f) : 1e30f, hit ? 2.0f * t : 0.5f}) {
      float t1 = -1, b11 = -1, b21 = -1, t2 = -1, b12 = -1, b22 = -1;
      const bool full = intersect_triangle(tri, ray, tmax, &t1, &b11, &b21);
      const bool finished = geometry::watertight_finish<float>(x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2], e[0],
                                                               e[1], e[2], ray, tmax, &t2, &b12, &b22);
      ASSERT_EQ(full, finished);
      if (full) {
        ASSERT_TRUE(same_bits(t1, t2) && same_bits(b11, b12) && same_bits(b21, b22));
      }
    }
  }
  ASSERT_FALSE(hit && rejected) << "rejected a hit: ray (" << ray.origin.x << ", " << ray.origin.y << ", "
                                << ray.origin.z << ") dir (" << ray.direction.x << ", " << ray.direction.y << ", "
                                << ray.direction.z << ")";
}

std::vector<Triangle> hard_triangles(apps::Rng& rng, float scale) {
  auto p = [&] { return scale * glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)); };
  std::vector<Triangle> out = {
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},      // axis-aligned
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}},      // two equal vertices
      {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}},      // collinear
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},      // in a coordinate plane
  };
  for (auto& t : out) t = {t.p0 * scale, t.p1 * scale, t.p2 * scale};
  for (int i = 0; i < 40; ++i) out.push_back({p(), p(), p()});
  return out;
}

TEST(TriangleReject, NeverRejectsAHitOnHardCases) {
  apps::Rng rng(11);
  Agreement a;
  for (float scale : {1.0f, 1e-13f, 1e-6f, 1e5f, 1e12f, 3e12f}) {
    const std::vector<Triangle> tris = hard_triangles(rng, scale);
    for (std::size_t n = 0; n < tris.size(); ++n) {
      const Triangle& tri = tris[n];
      const Triangle& partner = tris[(n + 7) % tris.size()];
      const glm::vec3 verts[3] = {tri.p0, tri.p1, tri.p2};
      for (int i = 0; i < 30; ++i) {
        const glm::vec3 o = scale * glm::vec3(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
        const float s = rng.uniform();
        const glm::vec3 targets[] = {verts[i % 3], glm::mix(verts[i % 3], verts[(i + 1) % 3], s),
                                     glm::mix(verts[0], glm::mix(verts[1], verts[2], s), rng.uniform()),
                                     verts[i % 3] + scale * glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 0)};
        for (const glm::vec3& target : targets) {
          if (target == o) continue;
          check(tri, partner, Ray(o, target - o), a);
          // Axis-parallel (with negative zeros), and grazing: in the plane of an edge.
          const glm::vec3 d = target - o;
          const int k = i % 3;
          glm::vec3 axis(-0.0f);
          axis[k] = d[k] < 0 ? -1.0f : 1.0f;
          check(tri, partner, Ray(target - axis * scale, axis), a);
          check(tri, partner, Ray(verts[k] - (verts[(k + 1) % 3] - verts[k]), verts[(k + 1) % 3] - verts[k]), a);
          if (HasFatalFailure()) return;
        }
      }
    }
  }
  // The rejection is in use (many misses here are degenerate, edge-on, behind the origin or out of
  // float's safe range, which only the full test rejects).
  EXPECT_GT(a.hits, 1000);
  EXPECT_GT(a.rejected, a.misses / 8);
  EXPECT_GT(a.inside, a.hits / 4);  // and finishes from its values (vertex and edge hits cannot)
}

TEST(TriangleReject, SharedEdgesOfAGridAreNeverRejectedBoth) {
  // Straight down onto every vertex and edge midpoint of a grid of quads: some triangle is hit,
  // and every triangle the full test hits passes the rejection.
  const int n = 8;
  const std::vector<Triangle> tris = testing::unit_square_grid(n);
  Agreement a;
  for (int y = 1; y < 2 * n; ++y)
    for (int x = 1; x < 2 * n; ++x) {
      const Ray r({x / float(2 * n), y / float(2 * n), 1.0f}, {0.0f, -0.0f, -1.0f});
      const int before = a.hits;
      for (std::size_t k = 0; k < tris.size(); ++k) check(tris[k], tris[k ^ 1], r, a);  // the quad's halves paired
      ASSERT_FALSE(HasFatalFailure());
      EXPECT_GT(a.hits, before) << x << "," << y;
    }
}

}  // namespace
}  // namespace gcsim::raytrace
