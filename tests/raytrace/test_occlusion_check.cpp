// OcclusionCheck keeps per tracer what A4's uniformity test used to work out per region: the
// planes through pixel centres, each primitive's hiding plane, a threshold instead of a square
// root per box. Its answers and its count of checks must be those of the per-region formulation
// (kept here as the reference), on the subtrees of real tiles of every paper scene, for every
// primitive of a subtree and pixel regions of many shapes.
#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "apps/common/rng.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/occlusion_check.hpp"
#include "apps/raytrace/plane_classification4.hpp"
#include "apps/raytrace/subtree.hpp"

namespace gcsim::raytrace {
namespace {

// Box of each node of the subtree, as its parent holds it (the root's: the tree's root box).
std::vector<Bounds3> subtree_node_boxes(const Subtree& s) {
  std::vector<Bounds3> boxes(s.packed.nodes.size());
  if (!is_primitive(s.root)) boxes[s.root] = s.packed.root_box;
  for (const PairNode& n : s.packed.nodes)
    for (int i = 0; i < 2; ++i)
      if (!is_primitive(n.child[i]))
        boxes[n.child[i]] = {{n.bounds[0][i], n.bounds[1][i], n.bounds[2][i]},
                             {n.bounds[0][2 + i], n.bounds[1][2 + i], n.bounds[2][2 + i]}};
  return boxes;
}

// The uniformity test's occlusion check as it was, everything derived for the one call.
bool reference_nothing_in_front(const Scene& scene, const Bvh& bvh, const Camera& camera, const Subtree& subtree,
                                int prim, float max_distance, int rx0, int ry0, int rx1, int ry1,
                                std::int64_t& checks) {
  if (is_primitive(subtree.root)) return primitive_of(subtree.root) == prim;
  const glm::vec3 eye = camera.eye();
  std::optional<Plane> behind;
  glm::dvec3 pn(0.0), p0(0.0);
  double eye_side = 0;
  if (!scene.is_sphere(prim)) {
    const Triangle& t = scene.triangle(prim);
    p0 = glm::dvec3(t.p0);
    pn = glm::cross(glm::dvec3(t.p1) - p0, glm::dvec3(t.p2) - p0);
    eye_side = glm::dot(pn, glm::dvec3(eye) - p0) > 0 ? 1.0 : -1.0;
    const glm::vec3 n = glm::vec3(-eye_side * pn);
    behind = Plane{n, glm::dot(n, t.p0)};
  } else {
    const Sphere& sp = scene.spheres[prim];
    const glm::vec3 to_eye = eye - sp.center;
    const float d = glm::length(to_eye);
    if (d > sp.radius) {
      const glm::vec3 u = to_eye / d;
      behind = Plane{-u, glm::dot(-u, sp.center + u * (sp.radius * sp.radius / d))};
    }
  }
  const FourPlanes region({camera.column_plane_at(rx0 + 0.5f), flipped(camera.column_plane_at(rx1 + 0.5f)),
                           camera.row_plane_at(ry0 + 0.5f), flipped(camera.row_plane_at(ry1 + 0.5f))});
  auto cannot_occlude = [&](const Bounds3& box) {
    if (box.distance_to(eye) > max_distance) return true;
    const BoxCentre b(box);
    const bool hidden = behind && classify(b, *behind, abs_components(behind->normal)) == Side::inside;
    return hidden || region.any_outside(b);
  };
  auto triangle_behind = [&](int q) {
    if (scene.is_sphere(q) || scene.is_sphere(prim)) return false;
    const Triangle& t = scene.triangle(q);
    const double scale = 1e-9 * glm::length(pn);
    for (const glm::vec3& v : {t.p0, t.p1, t.p2}) {
      const glm::dvec3 d = glm::dvec3(v) - p0;
      if (eye_side * glm::dot(pn, d) > scale * glm::length(d)) return false;
    }
    return true;
  };
  const std::vector<Bounds3> node_boxes = subtree_node_boxes(subtree);
  std::vector<NodeRef> stack{subtree.root};
  ++checks;
  while (!stack.empty()) {
    const PairNode n = subtree.packed.nodes[stack.back()];
    stack.pop_back();
    for (NodeRef c : n.child) {
      if (is_primitive(c) && primitive_of(c) == prim) continue;
      ++checks;
      if (is_primitive(c)) {
        if (!cannot_occlude(bvh.prim_bounds[primitive_of(c)]) && !triangle_behind(primitive_of(c))) return false;
      } else if (!cannot_occlude(node_boxes[c])) {
        if (stack.size() >= 256) return false;
        stack.push_back(c);
      }
    }
  }
  return true;
}

std::vector<int> primitives_of(const Subtree& s) {
  std::vector<int> out;
  if (is_primitive(s.root)) out.push_back(primitive_of(s.root));
  for (const PairNode& n : s.packed.nodes)
    for (NodeRef c : n.child)
      if (is_primitive(c)) out.push_back(primitive_of(c));
  return out;
}

TEST(OcclusionCheck, AnswersAndCountsAsThePerRegionCheck) {
  apps::Rng rng(12);
  for (const char* name : {"spheres-a", "spheres-b", "spheres-random", "teapot", "teapots"}) {
    const Scene scene = make_builtin_scene(name);
    const Bvh bvh = build_bvh_by_clustering(scene);
    const int size = 128, tile = 8;
    const Camera camera(scene.camera, size, size);
    OcclusionCheck check(scene, bvh, camera);
    int clear = 0, blocked = 0;
    for (int k = 0; k < 40; ++k) {
      const int x0 = tile * int(rng.uniform(0, size / tile - 0.01f));
      const int y0 = tile * int(rng.uniform(0, size / tile - 0.01f));
      Subtree sub;
      TraceCounters counters;
      build_subtree(bvh, pyramid_planes(camera, x0, y0, x0 + tile, y0 + tile), sub, counters);
      if (sub.empty) continue;
      for (int prim : primitives_of(sub)) {
        // Regions from single pixels to the whole tile; distances that keep everything, almost
        // nothing and something in between.
        const int rx0 = x0 + int(rng.uniform(0, tile - 0.01f)), ry0 = y0 + int(rng.uniform(0, tile - 0.01f));
        const int rx1 = std::min(x0 + tile - 1, rx0 + int(rng.uniform(0, tile)));
        const int ry1 = std::min(y0 + tile - 1, ry0 + int(rng.uniform(0, tile)));
        const float near = bvh.prim_bounds[prim].distance_to(camera.eye());
        const float bound = scene.is_sphere(prim) ? check.sphere_distance_bound(prim) : near;
        for (float max_distance : {near, near * 1.01f, near * 2.0f, 1e30f, bound}) {
          std::int64_t want_checks = 0, got_checks = 0;
          const bool want = reference_nothing_in_front(scene, bvh, camera, sub, prim, max_distance, rx0, ry0, rx1, ry1,
                                                       want_checks);
          const bool got = check.nothing_in_front(sub, prim, max_distance, rx0, ry0, rx1, ry1, got_checks);
          ASSERT_EQ(got, want) << name << " prim " << prim << " tile " << x0 << "," << y0 << " at " << max_distance;
          ASSERT_EQ(got_checks, want_checks) << name << " prim " << prim;
          (got ? clear : blocked) += 1;
        }
      }
    }
    EXPECT_GT(clear, 0) << name;
    EXPECT_GT(blocked, 0) << name;
  }
}

// The sphere bound is the per-region formula's, bit for bit.
TEST(OcclusionCheck, SphereBoundAsBefore) {
  const Scene scene = make_builtin_scene("spheres-random");
  const Bvh bvh = build_bvh_by_clustering(scene);
  const Camera camera(scene.camera, 64, 64);
  OcclusionCheck check(scene, bvh, camera);
  for (int p = 0; p < scene.sphere_count(); ++p) {
    const Sphere& s = scene.spheres[p];
    const float to_center = glm::length(s.center - camera.eye());
    const float d = to_center > s.radius ? to_center : to_center + s.radius;
    ASSERT_EQ(check.sphere_distance_bound(p), d * (1.0f + 1e-5f)) << p;
  }
}

}  // namespace
}  // namespace gcsim::raytrace
