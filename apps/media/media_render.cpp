#include "apps/media/media_render.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace gcsim::media {
namespace {

glm::dvec3 camera_direction(const PinholeCamera& c, double px, double py) {
  const glm::dvec3 forward = glm::normalize(c.look_at - c.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double half = std::tan(0.5 * c.vertical_fov_degrees * kPi / 180.0);
  const double sx = (2.0 * px / c.width - 1.0) * half * c.width / c.height;
  const double sy = (1.0 - 2.0 * py / c.height) * half;
  return glm::normalize(forward + sx * right + sy * up);
}

}  // namespace

double render_pixel(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                    std::uint64_t seed, int x, int y, RenderCounters& counters) {
  const std::uint64_t pixel = static_cast<std::uint64_t>(y) * scene.camera.width + x;
  apps::Rng rng(seed, 0x706978656cULL + pixel);
  ++counters.pixels;
  glm::dvec3 o = scene.camera.eye;
  glm::dvec3 d = camera_direction(scene.camera, x + rng.uniform_double(), y + rng.uniform_double());
  bool inside = scene.object && scene.object->inside(o);
  double radiance = 0.0, throughput = 1.0;
  const double inf = std::numeric_limits<double>::infinity();
  for (int depth = 0; depth <= scene.max_specular_depth; ++depth) {
    auto hit = scene.object ? scene.object->intersect(o, d, 0.0, inf) : std::nullopt;
    double t0 = 0.0, t1 = hit ? hit->t : inf;
    if (!inside && !clip_to_box(scene.fog_box, o, d, t0, t1)) break;
    if (inside) t1 = hit ? hit->t : 0.0;
    const HomogeneousMedium& m = inside ? scene.inside : scene.outside;
    const RegionCache& region = inside ? caches.inside : caches.outside;
    if (region.map && t1 > t0) {
      const glm::dvec3 start = o + t0 * d;
      auto li = [&](const glm::dvec3& p) { return region.map->in_scattered(p, -d, m, scene.k_nearest); };
      SegmentQuery q{start, d, t1 - t0, &m, region.grid.get(), std::nullopt};
      if (!inside && !scene.area_light) q.light = scene.light;  // equiangular needs a point light
      radiance += throughput * march_segment_in_scatter(q, settings, li, rng, counters.march);
    }
    throughput *= transmittance(m.sigma_t, std::max(0.0, t1 - t0));
    if (!hit || (!inside && hit->t > t1 + 1e-12)) break;
    ++counters.surface_events;
    o = o + hit->t * d;
    const double eta_i = hit->entering ? 1.0 : scene.ior, eta_t = hit->entering ? scene.ior : 1.0;
    const double reflectance = fresnel_dielectric(-glm::dot(d, hit->normal), eta_i, eta_t);
    auto refracted = refract_direction(d, hit->normal, eta_i, eta_t);
    if (rng.uniform_double() < reflectance || !refracted) {
      d = reflect_direction(d, hit->normal);
    } else {
      d = *refracted;
      inside = !inside;
    }
    o += 1e-7 * d;
  }
  return radiance;
}

void render_rows(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                 std::uint64_t seed, int y0, int y1, apps::Image& image, RenderCounters& counters) {
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < scene.camera.width; ++x)
      image.at(x, y) = glm::vec3(static_cast<float>(render_pixel(scene, caches, settings, seed, x, y, counters)));
}

}  // namespace gcsim::media
