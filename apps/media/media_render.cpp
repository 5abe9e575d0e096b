#include "apps/media/media_render.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

namespace gcsim::media {
namespace {

glm::dvec3 camera_direction(const scene::Camera& c, const ImageSize& image, double px, double py) {
  const glm::dvec3 forward = glm::normalize(c.look_at - c.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double half = std::tan(0.5 * c.fov_y_degrees * kPi / 180.0);
  const double sx = (2.0 * px / image.width - 1.0) * half * image.width / image.height;
  const double sy = (1.0 - 2.0 * py / image.height) * half;
  return glm::normalize(forward + sx * right + sy * up);
}

// One branch of a camera path: a ray in one region, carrying the product of Fresnel weights and
// transmittances so far.
struct PathBranch {
  glm::dvec3 origin, direction;
  bool inside;
  double throughput;
  int depth;
};

// The in-scattered radiance of one region's segment along a branch.
double segment_radiance(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                        const PathBranch& b, double t0, double t1, apps::Rng& rng, RenderCounters& counters) {
  const HomogeneousMedium& m = b.inside ? scene.inside : scene.outside;
  const RegionCache& region = b.inside ? caches.inside : caches.outside;
  if (!region.map || t1 <= t0) return 0.0;
  const glm::dvec3 d = b.direction;
  auto li = [&](const glm::dvec3& p) { return region.map->in_scattered(p, -d, m, scene.k_nearest); };
  SegmentQuery q{b.origin + t0 * d, d, t1 - t0, &m, region.grid.get(), std::nullopt};
  if (!b.inside && !scene.area_light) q.light = scene.light;  // equiangular needs a point light
  return march_segment_in_scatter(q, settings, li, rng, counters.march);
}

}  // namespace

double render_pixel(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                    std::uint64_t seed, int x, int y, RenderCounters& counters) {
  const std::uint64_t pixel = static_cast<std::uint64_t>(y) * scene.image.width + x;
  apps::Rng rng(seed, 0x706978656cULL + pixel);
  ++counters.pixels;
  // The ray through the pixel centre, and at each Fresnel surface both the reflected and the refracted
  // branch: the camera path is deterministic, so all the pixel's noise is the distance estimator's
  // (what the paper compares) and a high-sample reference converges to the same value.
  const glm::dvec3 eye = scene.camera.eye;
  std::vector<PathBranch> stack{{eye, camera_direction(scene.camera, scene.image, x + 0.5, y + 0.5),
                                 scene.object && scene.object->inside(eye, &counters.boundary), 1.0, 0}};
  double radiance = 0.0;
  const double inf = std::numeric_limits<double>::infinity();
  while (!stack.empty()) {
    const PathBranch b = stack.back();
    stack.pop_back();
    auto hit = scene.object ? scene.object->intersect(b.origin, b.direction, 0.0, inf, &counters.boundary) : std::nullopt;
    double t0 = 0.0, t1 = hit ? hit->t : inf;
    if (!b.inside && !clip_to_box(scene.fog_box, b.origin, b.direction, t0, t1)) continue;
    if (b.inside) t1 = hit ? hit->t : 0.0;
    radiance += b.throughput * segment_radiance(scene, caches, settings, b, t0, t1, rng, counters);
    const HomogeneousMedium& m = b.inside ? scene.inside : scene.outside;
    const double throughput = b.throughput * transmittance(m.sigma_t, std::max(0.0, t1 - t0));
    if (!hit || (!b.inside && hit->t > t1 + 1e-12) || b.depth >= scene.max_specular_depth) continue;
    ++counters.surface_events;
    const glm::dvec3 at = b.origin + hit->t * b.direction;
    const double eta_i = hit->entering ? 1.0 : scene.ior, eta_t = hit->entering ? scene.ior : 1.0;
    auto refracted = refract_direction(b.direction, hit->normal, eta_i, eta_t);
    const double reflectance = refracted ? fresnel_dielectric(-glm::dot(b.direction, hit->normal), eta_i, eta_t) : 1.0;
    const glm::dvec3 reflected = reflect_direction(b.direction, hit->normal);
    // Branches whose weight falls below kMinBranchWeight end there (a small bias every estimator and
    // the reference share).
    if (throughput * reflectance >= kMinBranchWeight)
      stack.push_back({scene.object->leave_surface(at, *hit, reflected), reflected, b.inside, throughput * reflectance, b.depth + 1});
    if (refracted && throughput * (1.0 - reflectance) >= kMinBranchWeight)
      stack.push_back({scene.object->leave_surface(at, *hit, *refracted), *refracted, !b.inside, throughput * (1.0 - reflectance), b.depth + 1});
  }
  return radiance;
}

void render_rows(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                 std::uint64_t seed, int y0, int y1, apps::Image& image, RenderCounters& counters) {
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < scene.image.width; ++x)
      image.at(x, y) = glm::vec3(static_cast<float>(render_pixel(scene, caches, settings, seed, x, y, counters)));
}

}  // namespace gcsim::media
