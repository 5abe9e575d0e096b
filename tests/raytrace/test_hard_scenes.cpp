// The whole pipeline (subtrees, uniformity test, ray classification) on hard scenes: every
// algorithm must still find the brute-force hit at every pixel.
#include <gtest/gtest.h>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/primary_tracer.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {
namespace {

void expect_every_algorithm_matches_brute_force(const Scene& s, int size) {
  const Bvh bvh = build_bvh_by_clustering(s);
  const Camera cam(s.camera, size, size);
  std::vector<Hit> ref(std::size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      TestTally t;
      intersect_brute_force(s, cam.pixel_ray(x, y), ref[std::size_t(y) * size + x], t);
    }
  int hits = 0;
  for (const Hit& h : ref) hits += h.valid();
  EXPECT_GT(hits, 0) << s.name;
  for (Algorithm a : paper_algorithms())
    for (int tile : {4, 8}) {
      PrimaryTracer tracer(s, bvh, cam, a);
      TraceCounters c;
      std::vector<Hit> out;
      const Tiling tiling{size, size, tile};
      int mismatches = 0;
      for (int i = 0; i < tiling.count(); ++i) {
        const auto r = tiling.rect(i);
        tracer.trace_tile(r.x0, r.y0, r.x1, r.y1, out, c);
        for (int y = r.y0; y < r.y1; ++y)
          for (int x = r.x0; x < r.x1; ++x) {
            const Hit& h = out[std::size_t(y - r.y0) * (r.x1 - r.x0) + (x - r.x0)];
            const Hit& e = ref[std::size_t(y) * size + x];
            if (h.prim != e.prim || h.t != e.t) ++mismatches;
          }
      }
      EXPECT_EQ(mismatches, 0) << s.name << " " << name_of(a) << " tile " << tile;
    }
}

Scene scaled(Scene s, float k) {
  for (auto& sp : s.spheres) {
    sp.center *= k;
    sp.radius *= k;
  }
  for (auto& t : s.triangles) {
    t.p0 *= k;
    t.p1 *= k;
    t.p2 *= k;
  }
  s.camera.eye *= k;
  s.camera.look_at *= k;
  s.name += " x" + std::to_string(k);
  return s;
}

TEST(HardScenes, TinyAndHugeScales) {
  for (float k : {1e-4f, 1e4f}) {
    expect_every_algorithm_matches_brute_force(scaled(make_builtin_scene("spheres-random"), k), 48);
    expect_every_algorithm_matches_brute_force(scaled(make_builtin_scene("teapot"), k), 48);
  }
}

TEST(HardScenes, SpheresOfRadius1e4And1e4Together) {
  Scene s;
  s.name = "mixed radii";
  const int m = s.add_material({});
  s.add_sphere({{0, 0, -1e4f}, 1e4f}, m);  // a huge ground sphere, top at z = 0
  for (int i = 0; i < 20; ++i) s.add_sphere({{-0.5f + 0.05f * i, 0.0f, 1e-4f}, 1e-4f}, m);  // tiny spheres on it
  s.add_sphere({{0.2f, 0.3f, 0.1f}, 0.1f}, m);
  s.camera = {.eye = {0.0f, -0.3f, 0.05f}, .look_at = {0.0f, 0.0f, 0.0f}, .up = {0, 0, 1}, .fov_y_degrees = 60.0f};
  expect_every_algorithm_matches_brute_force(s, 40);
}

TEST(HardScenes, AxisParallelRaysOnAnAxisAlignedGrid) {
  // Looking straight down -z at flat, axis-aligned triangles (boxes of zero thickness); with an
  // odd image size the centre row and column of rays have zero x or y components.
  Scene s;
  s.name = "axis grid";
  const int m = s.add_material({});
  const int n = 8;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::vec3 p00(x - 4.0f, y - 4.0f, 0), p10(x - 3.0f, y - 4.0f, 0), p01(x - 4.0f, y - 3.0f, 0), p11(x - 3.0f, y - 3.0f, 0);
      s.add_triangle({p00, p10, p11}, m);
      s.add_triangle({p00, p11, p01}, m);
    }
  for (int i = 0; i < 5; ++i) s.add_sphere({{i - 2.0f, 0.0f, 1.0f}, 0.4f}, m);
  s.camera = {.eye = {0.0f, 0.0f, 10.0f}, .look_at = {0.0f, 0.0f, 0.0f}, .up = {0, 1, 0}, .fov_y_degrees = 50.0f};
  const Camera cam(s.camera, 33, 33);
  const Ray centre = cam.pixel_ray(16, 16);
  EXPECT_EQ(centre.direction.x, 0.0f);
  EXPECT_EQ(centre.direction.y, 0.0f);
  expect_every_algorithm_matches_brute_force(s, 33);
}

TEST(HardScenes, DegenerateTrianglesAmongGoodOnes) {
  Scene s = make_builtin_scene("teapot");
  const int m = 0;
  // Zero-area triangles across the teapot: points, slivers on lines, repeated vertices.
  for (int i = 0; i < 40; ++i) {
    const glm::vec3 a(-2.0f + 0.1f * i, -1.0f, 1.5f), b = a + glm::vec3(0.5f, 1.0f, 0.2f);
    s.add_triangle({a, a, a}, m);
    s.add_triangle({a, b, 0.5f * (a + b)}, m);
    s.add_triangle({a, b, b}, m);
  }
  expect_every_algorithm_matches_brute_force(s, 48);
}

}  // namespace
}  // namespace gcsim::raytrace
