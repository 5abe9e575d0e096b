// The BVH builder on any finite geometry: huge (1e23, 1e30), tiny (1e-30), flat and coincident
// triangles must give a valid tree (every primitive once, every box holding its children) whose
// nearest hits are brute force's. Regression: a vertex at 1e23 made every float surface area
// infinite, no cluster was ever chosen and the builder popped an empty chain (SIGSEGV).
#include <gtest/gtest.h>

#include <vector>

#include "apps/common/rng.hpp"
#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/scene.hpp"
#include "apps/common/geometry/traversal.hpp"

namespace gcsim::raytrace {
namespace {

bool box_holds(const Bounds3& outer, const Bounds3& inner) {
  return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) && glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}

// Every primitive reached exactly once, n - 1 nodes, every node's box holding its children's.
void expect_valid_tree(const Scene& s, const Bvh& bvh) {
  const int n = s.prim_count();
  std::vector<int> seen(n, 0);
  ASSERT_EQ(int(bvh.nodes.size()), n - 1);
  std::vector<NodeRef> stack{bvh.root};
  int visited_nodes = 0;
  while (!stack.empty()) {
    const NodeRef r = stack.back();
    stack.pop_back();
    if (is_primitive(r)) {
      ASSERT_GE(primitive_of(r), 0);
      ASSERT_LT(primitive_of(r), n);
      ++seen[primitive_of(r)];
      continue;
    }
    ASSERT_LT(r, NodeRef(bvh.nodes.size()));
    ASSERT_LE(++visited_nodes, n - 1) << "a node is reached twice";
    const BvhNode& node = bvh.nodes[r];
    for (NodeRef c : node.child) {
      const Bounds3 cb = is_primitive(c) ? bvh.prim_bounds[primitive_of(c)] : bvh.nodes[c].box;
      EXPECT_TRUE(box_holds(node.box, cb));
      stack.push_back(c);
    }
  }
  for (int p = 0; p < n; ++p) EXPECT_EQ(seen[p], 1) << "primitive " << p;
}

// Rays from points around the scene towards points on random triangles, plus the axis directions.
std::vector<Ray> probe_rays(const Scene& s, int count) {
  apps::Rng rng(7);
  const Bounds3 b = s.bounds();
  const glm::vec3 c = 0.5f * b.lo + 0.5f * b.hi, half = 0.5f * b.hi - 0.5f * b.lo;
  const float reach = 3.0f * std::max({half.x, half.y, half.z, 1e-37f});
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Triangle& t = s.triangles[rng.next_u32() % s.triangles.size()];
    const float u = rng.uniform(0.05f, 0.45f), v = rng.uniform(0.05f, 0.45f);
    const glm::vec3 to = (1 - u - v) * t.p0 + u * t.p1 + v * t.p2;
    // Every other ray starts near its target, at the scale of its triangle: a float direction
    // aimed from 1e20 away misses a triangle 2 wide by far more than its width.
    const glm::vec3 te = 0.5f * t.bounds().hi - 0.5f * t.bounds().lo;
    const float near_reach = 2.0f * std::max({te.x, te.y, te.z, 1e-37f});
    const glm::vec3 from = (i % 2 ? to : c) + (i % 2 ? near_reach : reach) *
                                                  glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    // Divided by its largest component first: the squared length of a 1e30 vector overflows.
    glm::vec3 d = to - from;
    const glm::vec3 m = abs_components(d);
    const float largest = std::max({m.x, m.y, m.z});
    if (!(largest > 0) || !std::isfinite(largest)) continue;
    d /= largest;
    rays.emplace_back(from, glm::normalize(d));
  }
  for (int a = 0; a < 3; ++a) {
    glm::vec3 d(0.0f);
    d[a] = -1.0f;
    glm::vec3 o = c;
    o[a] += reach;
    rays.emplace_back(o, d);
  }
  return rays;
}

// Nearest hits of both traversals equal brute force's; returns how many rays hit something.
int expect_hits_equal_brute_force(const Scene& s, const Bvh& bvh, int count = 400) {
  int hits = 0;
  for (const Ray& ray : probe_rays(s, count)) {
    Hit ref, ordered, unordered;
    TestTally tally;
    intersect_brute_force(s, ray, ref, tally);
    traverse_ordered(s, bvh.packed, ray, ordered, tally);
    traverse_unordered(s, bvh.packed, ray, unordered, tally);
    EXPECT_EQ(ordered.prim, ref.prim);
    EXPECT_EQ(ordered.t, ref.t);
    EXPECT_EQ(unordered.prim, ref.prim);
    EXPECT_EQ(unordered.t, ref.t);
    hits += ref.valid();
  }
  return hits;
}

Scene cube(glm::vec3 odd_vertex) {
  Scene s;
  s.name = "cube";
  const int m = s.add_material({});
  glm::vec3 v[8];
  for (int i = 0; i < 8; ++i) v[i] = {i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f};
  v[3] = odd_vertex;  // (1, 1, -1) normally
  const int quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.add_triangle({v[q[0]], v[q[1]], v[q[2]]}, m);
    s.add_triangle({v[q[0]], v[q[2]], v[q[3]]}, m);
  }
  return s;
}

// A seeded soup of triangles in the unit cube, scaled by k.
Scene soup(int n, float k, std::uint64_t seed = 3) {
  Scene s;
  s.name = "soup";
  const int m = s.add_material({});
  apps::Rng rng(seed);
  for (int i = 0; i < n; ++i) {
    const glm::vec3 c(rng.uniform(), rng.uniform(), rng.uniform());
    auto corner = [&] { return k * (c + 0.1f * glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))); };
    s.add_triangle({corner(), corner(), corner()}, m);
  }
  return s;
}

TEST(BvhRobustness, CubeWithAVertexAt1e23) {
  // The smallest OBJ that crashed the builder: a cube with `v 1 1e23 -1`.
  for (float y : {1e20f, 1e23f, 1e30f, 3e38f}) {
    const Scene s = cube({1.0f, y, -1.0f});
    const Bvh bvh = build_bvh_by_clustering(s);
    expect_valid_tree(s, bvh);
    EXPECT_GT(expect_hits_equal_brute_force(s, bvh), 0) << y;
  }
}

TEST(BvhRobustness, HugeAndTinyScales) {
  const int unit_depth = build_bvh_by_clustering(soup(300, 1.0f)).depth();
  for (float k : {1.0f, 1e30f, 1e-30f, 1e36f, 1e-36f}) {
    const Scene s = soup(300, k);
    const Bvh bvh = build_bvh_by_clustering(s);
    expect_valid_tree(s, bvh);
    EXPECT_GT(expect_hits_equal_brute_force(s, bvh), 100) << k;
    // Areas compared for real, not all tied at infinity or zero: a tree as shallow as at scale 1.
    EXPECT_LE(bvh.depth(), unit_depth + 2) << k;
  }
}

TEST(BvhRobustness, AllTrianglesCoincident) {
  Scene s;
  s.name = "coincident";
  const int m = s.add_material({});
  for (int i = 0; i < 200; ++i) s.add_triangle({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, m);
  const Bvh bvh = build_bvh_by_clustering(s);
  expect_valid_tree(s, bvh);
  EXPECT_GT(expect_hits_equal_brute_force(s, bvh), 100);
}

// A tetrahedron whose one face is repeated: clustering tied every merge and chained the copies
// into a tree half as deep as their count (226 for 450), and the subtree walks that recurse on
// a 64 KiB fiber stack overflowed it. The depth is bounded by log2 of the count plus a constant.
TEST(BvhRobustness, RepeatedFaceGivesAShallowTree) {
  for (int copies : {450, 2000, 5000}) {
    Scene s;
    s.name = "tetrahedron";
    const int m = s.add_material({});
    const glm::vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
    s.add_triangle({a, b, d}, m);
    s.add_triangle({a, c, d}, m);
    s.add_triangle({b, c, d}, m);
    for (int i = 0; i < copies; ++i) s.add_triangle({a, b, c}, m);
    const Bvh bvh = build_bvh_by_clustering(s);
    expect_valid_tree(s, bvh);
    EXPECT_LE(bvh.depth(), 64 + 2) << copies;  // at most 64 clustered + log2(n / 2048) median levels
    EXPECT_GT(expect_hits_equal_brute_force(s, bvh, 200), 50) << copies;
  }
}

TEST(BvhRobustness, AllTrianglesInOnePlane) {
  Scene s = soup(300, 1.0f);
  for (auto& t : s.triangles) t.p0.z = t.p1.z = t.p2.z = 0.5f;
  const Bvh bvh = build_bvh_by_clustering(s);
  expect_valid_tree(s, bvh);
  EXPECT_GT(expect_hits_equal_brute_force(s, bvh), 100);
}

TEST(BvhRobustness, MoreThanOneClusterGroupOfHugeTriangles) {
  // Above 2048 primitives the builder first splits at centroid medians: also at 1e30.
  const Scene s = soup(2500, 1e30f, 11);
  const Bvh bvh = build_bvh_by_clustering(s);
  expect_valid_tree(s, bvh);
  EXPECT_GT(expect_hits_equal_brute_force(s, bvh, 100), 30);
}

}  // namespace
}  // namespace gcsim::raytrace
