// Secondary rays: no self-intersection after reflection and refraction, total internal
// reflection, and pencils (2.3) that change only the work, never the image.
#include <cmath>

#include <gtest/gtest.h>

#include "apps/common/rng.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/optics.hpp"
#include "apps/raytrace/pencil.hpp"
#include "apps/common/geometry/ray_offset.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {
namespace {

Hit nearest(const Scene& s, const Ray& r) {
  Hit h;
  TestTally t;
  intersect_brute_force(s, r, h, t);
  return h;
}

TEST(SelfIntersection, ReflectedRaysLeaveSpheresOfEveryScale) {
  apps::Rng rng(11);
  for (float radius : {1e-4f, 1.0f, 1e4f}) {
    Scene s;
    s.add_material({});
    s.add_sphere({{radius * 2.0f, -radius, radius * 0.5f}, radius}, 0);
    for (int i = 0; i < 300; ++i) {
      const glm::vec3 dir = glm::normalize(glm::vec3(rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f), 1.0f));
      const Ray r(s.spheres[0].center - 5.0f * radius * dir + radius * glm::vec3(rng.uniform(-0.5f, 0.5f), 0, 0), dir);
      const Hit h = nearest(s, r);
      ASSERT_TRUE(h.valid());
      const SurfacePoint sp = s.surface_point(r, h.prim, h.t, h.b1, h.b2);
      const glm::vec3 refl = reflect_direction(r.direction, sp.geometric_normal);
      EXPECT_FALSE(nearest(s, Ray(offset_ray_origin(sp, refl), refl)).valid()) << "reflection re-hit, r=" << radius;
      // Refracted into the sphere: the next hit is the far side, not the entry point.
      const auto t = refract_direction(r.direction, sp.geometric_normal, 1.0f / 1.5f);
      ASSERT_TRUE(t.has_value());
      const Ray inside(offset_ray_origin(sp, *t), *t);
      const Hit h2 = nearest(s, inside);
      ASSERT_TRUE(h2.valid()) << "refracted ray escaped, r=" << radius;
      EXPECT_GT(h2.t, 1e-3f * radius) << "refracted ray re-hit its entry point, r=" << radius;
    }
  }
}

TEST(SelfIntersection, ReflectedRaysLeaveTriangles) {
  Scene s;
  s.add_material({});
  s.add_triangle({{-1e3f, -1e3f, 0.3f}, {1e3f, -1e3f, 0.3f}, {0.0f, 1e3f, 0.3f}}, 0);
  apps::Rng rng(5);
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 o(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(1, 100));
    const glm::vec3 target(rng.uniform(-100, 100), rng.uniform(-100, 100), 0.3f);
    const Ray r(o, glm::normalize(target - o));
    const Hit h = nearest(s, r);
    ASSERT_TRUE(h.valid());
    const SurfacePoint sp = s.surface_point(r, h.prim, h.t, h.b1, h.b2);
    const glm::vec3 refl = reflect_direction(r.direction, sp.geometric_normal);
    EXPECT_FALSE(nearest(s, Ray(offset_ray_origin(sp, refl), refl)).valid());
    const glm::vec3 through = r.direction;  // a refracted ray continuing below
    EXPECT_FALSE(nearest(s, Ray(offset_ray_origin(sp, through), through)).valid());
  }
}

TEST(Optics, TotalInternalReflectionAndFresnel) {
  const glm::vec3 n(0, 0, 1);
  const float eta = 1.5f;  // glass to air
  const float critical = std::asin(1.0f / eta);
  for (float angle : {critical + 0.01f, 1.2f, 1.5f}) {
    const glm::vec3 d(std::sin(angle), 0, -std::cos(angle));
    EXPECT_FALSE(refract_direction(d, n, eta).has_value()) << angle;
    EXPECT_FLOAT_EQ(fresnel_dielectric(std::cos(angle), eta), 1.0f);
  }
  const glm::vec3 d(std::sin(critical - 0.05f), 0, -std::cos(critical - 0.05f));
  const auto t = refract_direction(d, n, eta);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(glm::length(*t), 1.0f, 1e-5f);
  EXPECT_NEAR(eta * std::sin(critical - 0.05f), std::sqrt(t->x * t->x + t->y * t->y), 1e-4f);  // Snell
  // Normal incidence: ((n1 - n2) / (n1 + n2))^2 = 0.04 for glass; reflectance in [0, 1] everywhere.
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f / 1.5f), 0.04f, 1e-4f);
  for (float c = 0.0f; c <= 1.0f; c += 0.05f) {
    const float f = fresnel_dielectric(c, 1.0f / 1.5f);
    EXPECT_GE(f, 0.0f);
    EXPECT_LE(f, 1.0f);
  }
}

TEST(Pencil, ContainsItsBundleAndBoundsItByFourPlanes) {
  // Four diverging rays from nearby points.
  std::array<Ray, 4> corners = {Ray({0, 0, 0}, glm::normalize(glm::vec3(-0.1f, -0.1f, 1))),
                                Ray({1, 0, 0}, glm::normalize(glm::vec3(0.1f, -0.1f, 1))),
                                Ray({0, 1, 0.2f}, glm::normalize(glm::vec3(-0.1f, 0.1f, 1))),
                                Ray({1, 1, 0.1f}, glm::normalize(glm::vec3(0.1f, 0.1f, 1)))};
  const auto p = make_pencil(corners);
  ASSERT_TRUE(p.has_value());
  // A ray in the middle of the bundle is inside, and stays inside the planes along its length.
  const Ray mid({0.5f, 0.5f, 0.1f}, {0, 0, 1});
  EXPECT_TRUE(p->contains(mid));
  for (float t : {0.0f, 1.0f, 10.0f, 1000.0f})
    for (const Plane& pl : p->planes()) EXPECT_GE(pl.signed_distance(mid.at(t)), 0.0f);
  // Leaving sideways: outside.
  EXPECT_FALSE(p->contains(Ray({0.5f, 0.5f, 0.1f}, glm::normalize(glm::vec3(1, 0, 1)))));
  EXPECT_FALSE(p->contains(Ray({5, 0.5f, 0.1f}, {0, 0, 1})));
  EXPECT_FALSE(p->contains(Ray({0.5f, 0.5f, 0.1f}, {0, 0, -1})));
}

TEST(Pencil, WhittedImagesAreIdenticalWithAndWithoutPencils) {
  const Scene s = make_builtin_scene("whitted");
  const Bvh bvh = build_bvh_by_clustering(s);
  RenderSettings rs;
  rs.width = rs.height = 96;
  rs.shading = Shading::whitted;
  rs.algorithm = Algorithm::A4;
  rs.pencils = true;
  const RenderOutput with = render_image(s, bvh, rs);
  rs.pencils = false;
  const RenderOutput without = render_image(s, bvh, rs);
  rs.algorithm = Algorithm::brute;
  const RenderOutput brute = render_image(s, bvh, rs);
  EXPECT_GT(with.counters.pencils, 0);
  EXPECT_GT(with.counters.secondary_in_pencil, 0);
  EXPECT_EQ(without.counters.secondary_in_pencil, 0);
  EXPECT_EQ(with.counters.secondary_rays, without.counters.secondary_rays);
  EXPECT_GT(with.counters.shadow_rays, 0);
  int differ = 0;
  for (std::size_t i = 0; i < with.image.pixels().size(); ++i) {
    differ += with.image.pixels()[i] != without.image.pixels()[i];
    differ += with.image.pixels()[i] != brute.image.pixels()[i];
    const glm::vec3 c = with.image.pixels()[i];
    EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0);
  }
  EXPECT_EQ(differ, 0);
  // The pencils save box tests on the first bounce.
  EXPECT_LT(with.counters.secondary_box_tests, without.counters.secondary_box_tests);
}

}  // namespace
}  // namespace gcsim::raytrace
