#include "apps/raytrace/tile_renderer.hpp"

#include <cmath>

#include "apps/raytrace/optics.hpp"
#include "apps/raytrace/ray_media.hpp"
#include "apps/common/geometry/ray_offset.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {

TileRenderer::TileRenderer(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                           const PreparedChildPairs* shared_pairs)
    : scene_(scene), bvh_(bvh), settings_(settings), camera_(scene.camera, settings.width, settings.height),
      primary_(scene, bvh, camera_, settings.algorithm, shared_pairs) {}

void TileRenderer::render_tile(int x0, int y0, int x1, int y1, std::span<glm::vec3> colors, std::span<std::int32_t> prims,
                               TraceCounters& counters, TraceCounters* row_counters) {
  primary_.trace_tile(x0, y0, x1, y1, hits_, counters, row_counters);
  const int w = x1 - x0, h = y1 - y0;
  const bool whitted = settings_.shading == Shading::whitted;

  std::optional<Pencil> pencils[2];
  if (whitted && settings_.secondary_rays && settings_.pencils && w >= 2 && h >= 2) {
    const int cx[4] = {x0, x1 - 1, x0, x1 - 1}, cy[4] = {y0, y0, y1 - 1, y1 - 1};
    Ray rays[4];
    Hit corner[4];
    for (int i = 0; i < 4; ++i) {
      rays[i] = camera_.pixel_ray(cx[i], cy[i]);
      corner[i] = hits_[std::size_t(cy[i] - y0) * w + (cx[i] - x0)];
    }
    pencils[0] = tile_pencil(rays, corner, Bounce::reflection, counters);
    pencils[1] = tile_pencil(rays, corner, Bounce::refraction, counters);
  }
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = std::size_t(y - y0) * w + (x - x0);
      const Hit& hit = hits_[i];
      prims[i] = hit.prim;
      if (settings_.media) pixel_rng_ = apps::Rng(settings_.media_seed, std::uint64_t(y) * settings_.width + x);
      colors[i] = shade(camera_.pixel_ray(x, y), hit, 0, pencils[0] ? &*pencils[0] : nullptr,
                        pencils[1] ? &*pencils[1] : nullptr, counters);
    }
}

// The pencil of the tile's reflected (or refracted) corner rays, with its subtree; empty unless
// all four corners hit surfaces that spawn that kind of ray.
std::optional<Pencil> TileRenderer::tile_pencil(const Ray corner_primary[4], const Hit corner_hits[4], Bounce kind,
                                                TraceCounters& counters) const {
  std::array<Ray, 4> rays;
  for (int i = 0; i < 4; ++i) {
    const SecondaryRay s = secondary_ray(corner_primary[i], corner_hits[i], kind);
    if (!s.valid) return std::nullopt;
    rays[i] = s.ray;
  }
  std::optional<Pencil> p = make_pencil(rays);
  if (!p) return p;
  ++counters.pencils;
  build_subtree(bvh_, p->planes(), p->subtree, counters);
  return p;
}

TileRenderer::SecondaryRay TileRenderer::secondary_ray(const Ray& ray, const Hit& hit, Bounce kind) const {
  SecondaryRay out;
  if (!hit.valid()) return out;
  const Material& m = scene_.material_of(hit.prim);
  if (!m.spawns_secondary()) return out;
  const SurfacePoint sp = scene_.surface_point(ray, hit.prim, hit.t, hit.b1, hit.b2);
  const glm::vec3 d = glm::normalize(ray.direction);
  const glm::vec3 n = sp.shading_normal;
  if (m.transmittance > 0.0f) {
    const float eta = sp.entering ? 1.0f / m.ior : m.ior;
    const float cos_i = -glm::dot(d, n);
    const float f = fresnel_dielectric(cos_i, eta);
    if (kind == Bounce::reflection) {
      const glm::vec3 r = reflect_direction(d, n);
      out = {Ray(offset_ray_origin(sp, r), r), f * m.reflectance, true};
    } else {
      const auto t = refract_direction(d, n, eta);
      if (!t) return out;  // total internal reflection: all of it went to the reflected ray
      out = {Ray(offset_ray_origin(sp, *t), *t), (1.0f - f) * m.transmittance, true};
    }
  } else if (kind == Bounce::reflection && m.reflectance > 0.0f) {
    const glm::vec3 r = reflect_direction(d, n);
    out = {Ray(offset_ray_origin(sp, r), r), m.reflectance, true};
  }
  // A shading normal may turn a ray into the surface; such a ray is dropped.
  if (out.valid && glm::dot(out.ray.direction, sp.geometric_normal) * (kind == Bounce::reflection ? 1.0f : -1.0f) <= 0.0f)
    out.valid = false;
  return out;
}

Hit TileRenderer::trace_secondary(const Ray& ray, const Pencil* pencil, TraceCounters& counters) {
  Hit hit;
  TestTally tally;
  ++counters.secondary_rays;
  if (pencil && pencil->contains(ray)) {
    // Every primitive the ray can reach meets the pencil, so it is in the pencil's subtree.
    ++counters.secondary_in_pencil;
    traverse_ordered(scene_, pencil->subtree.packed, ray, hit, tally);
  } else {
    traverse_ordered(scene_, bvh_.packed, ray, hit, tally);
  }
  counters.secondary_box_tests += tally.boxes;
  counters.secondary_prim_tests += tally.prims();
  counters.sphere_tests += tally.spheres;
  counters.triangle_tests += tally.triangles;
  counters.child_sorts += tally.sorts;
  return hit;
}

glm::vec3 TileRenderer::local_light(const Ray& ray, const Hit& hit, const SurfacePoint& sp, bool shadows,
                                    TraceCounters& counters) {
  const Material& m = scene_.material_of(hit.prim);
  glm::vec3 albedo = m.diffuse;
  glm::vec3 color(0.0f);
  if (m.given_radiance) {  // radiosity's light, then the point and spot lights' direct light
    color = scene_.given_radiance(ray, hit.prim, hit.b1, hit.b2);
    albedo = sp.entering ? m.diffuse : m.back_diffuse;
    if (scene_.lights.empty() || albedo == glm::vec3(0.0f)) return color;
  }
  if (m.checker_other.x >= 0.0f) {
    // Squares in the two axes closest to the surface's plane (x and y on a floor facing z).
    const glm::vec3 an = glm::abs(sp.geometric_normal);
    const int drop = an.x > an.y && an.x > an.z ? 0 : an.y > an.z ? 1 : 2;
    const float u = sp.position[drop == 0 ? 1 : 0], v = sp.position[drop == 2 ? 1 : 2];
    const int parity = int(std::floor(u / m.checker_size)) + int(std::floor(v / m.checker_size));
    if (parity & 1) albedo = m.checker_other;
  }
  if (!m.given_radiance) {
    color = scene_.ambient * albedo;
    if (sp.entering) color += m.emission;
  }
  const glm::vec3 n = sp.shading_normal;
  const glm::vec3 to_eye = -glm::normalize(ray.direction);
  for (const PointLight& light : scene_.lights) {
    glm::vec3 l = light.position - sp.position;
    const float dist2 = glm::dot(l, l);
    const float dist = std::sqrt(dist2);
    l /= dist;
    const float cos_l = glm::dot(n, l);
    if (cos_l <= 0.0f || glm::dot(sp.geometric_normal, l) <= 0.0f || !light.lights_direction(-l)) continue;
    if (shadows) {
      const Ray shadow(offset_ray_origin(sp, l), l);
      ++counters.shadow_rays;
      TestTally tally;
      const float tmax = glm::length(light.position - shadow.origin) * (1.0f - 1e-4f);
      const bool blocked = traverse_any_hit(scene_, bvh_.packed, shadow, tmax, tally);
      counters.secondary_box_tests += tally.boxes;
      counters.secondary_prim_tests += tally.prims();
      counters.sphere_tests += tally.spheres;
      counters.triangle_tests += tally.triangles;
      if (blocked) continue;
    }
    glm::vec3 e = light.intensity / dist2;
    if (settings_.media) e *= settings_.media->transmittance(Ray(offset_ray_origin(sp, l), l), dist);
    color += e * albedo * cos_l;
    if (m.specular > 0.0f) {
      const glm::vec3 half = glm::normalize(l + to_eye);
      color += e * m.specular * std::pow(std::max(0.0f, glm::dot(n, half)), m.shininess);
    }
  }
  return color;
}

glm::vec3 TileRenderer::shade(const Ray& ray, const Hit& hit, int depth, const Pencil* reflection_pencil,
                              const Pencil* refraction_pencil, TraceCounters& counters) {
  const glm::vec3 surface = shade_surface(ray, hit, depth, reflection_pencil, refraction_pencil, counters);
  if (!settings_.media) return surface;
  return settings_.media->along(ray, hit.valid() ? hit.t : kInfinity, surface, pixel_rng_, counters);
}

// The radiance leaving the hit point towards the ray's origin (the background when it hit nothing).
glm::vec3 TileRenderer::shade_surface(const Ray& ray, const Hit& hit, int depth, const Pencil* reflection_pencil,
                                      const Pencil* refraction_pencil, TraceCounters& counters) {
  if (!hit.valid()) return scene_.background;
  ++counters.shades;
  const SurfacePoint sp = scene_.surface_point(ray, hit.prim, hit.t, hit.b1, hit.b2);
  const bool whitted = settings_.shading == Shading::whitted;
  glm::vec3 color = local_light(ray, hit, sp, whitted && settings_.shadow_rays, counters);
  if (!whitted || !settings_.secondary_rays || depth >= settings_.max_depth) return color;
  for (Bounce kind : {Bounce::reflection, Bounce::refraction}) {
    const SecondaryRay s = secondary_ray(ray, hit, kind);
    if (!s.valid || s.weight <= 0.0f) continue;
    const Pencil* pencil = kind == Bounce::reflection ? reflection_pencil : refraction_pencil;
    const std::int64_t boxes = counters.secondary_box_tests, prims = counters.secondary_prim_tests;
    const Hit next = trace_secondary(s.ray, pencil, counters);
    if (depth == 0) {
      ++counters.first_bounce_rays;
      counters.first_bounce_in_pencil_tiles += pencil != nullptr;
      counters.first_bounce_box_tests += counters.secondary_box_tests - boxes;
      counters.first_bounce_prim_tests += counters.secondary_prim_tests - prims;
    }
    color += s.weight * shade(s.ray, next, depth + 1, nullptr, nullptr, counters);
  }
  return color;
}

}  // namespace gcsim::raytrace
