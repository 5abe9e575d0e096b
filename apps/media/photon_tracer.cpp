#include "apps/media/photon_tracer.hpp"

#include <cmath>

#include "apps/common/rng.hpp"
#include "apps/media/sampling.hpp"

namespace gcsim::media {
namespace {

constexpr double kSurfaceOffset = 1e-7;  // leaves the surface along the new direction

// Reflects or refracts at the boundary; returns the new direction.
glm::dvec3 cross_boundary(const BoundaryHit& hit, const glm::dvec3& d, double ior, apps::Rng& rng) {
  const double eta_i = hit.entering ? 1.0 : ior, eta_t = hit.entering ? ior : 1.0;
  const double reflectance = fresnel_dielectric(-glm::dot(d, hit.normal), eta_i, eta_t);
  if (rng.uniform_double() < reflectance) return reflect_direction(d, hit.normal);
  auto refracted = refract_direction(d, hit.normal, eta_i, eta_t);
  return refracted ? *refracted : reflect_direction(d, hit.normal);
}

}  // namespace

PhotonPassResult trace_photons(const MediaScene& scene, std::size_t first, std::size_t last) {
  PhotonPassResult out;
  const auto power = static_cast<float>(4.0 * kPi * scene.light.intensity / double(scene.photons_emitted));
  for (std::size_t i = first; i < last; ++i) {
    apps::Rng rng(scene.seed, 0x70686f746f6eULL + i);
    glm::dvec3 x = scene.light.position;
    glm::dvec3 w = uniform_sphere(rng.uniform_double(), rng.uniform_double());
    bool inside = scene.object && scene.object->inside(x);
    int events = 0;
    for (; events < scene.max_photon_events; ++events) {
      const HomogeneousMedium& m = inside ? scene.inside : scene.outside;
      const double flight = m.sigma_t > 0 ? -std::log1p(-rng.uniform_double()) / m.sigma_t : 1e30;
      ++out.flights;
      auto hit = scene.object ? scene.object->intersect(x, w, 0.0, flight) : std::nullopt;
      if (hit) {
        ++out.surface_events;
        x += hit->t * w;
        const glm::dvec3 nw = cross_boundary(*hit, w, scene.ior, rng);
        if (glm::dot(nw, hit->normal) < 0.0) inside = !inside;  // went through
        w = nw;
        x += kSurfaceOffset * w;
        continue;
      }
      double t_lo = 0.0, t_hi = flight;
      if (!inside && (!clip_to_box(scene.fog_box, x, w, t_lo, t_hi) || t_hi < flight)) {
        ++out.escaped;
        break;
      }
      x += flight * w;
      (inside ? out.inside : out.outside).push_back({glm::vec3(x), glm::vec3(w), power});
      if (rng.uniform_double() >= m.albedo()) {
        ++out.absorbed;
        break;
      }
      w = direction_around(w, m.phase.sample_cos(rng.uniform_double()), rng.uniform_double());
    }
    if (events == scene.max_photon_events) ++out.capped;
  }
  return out;
}

}  // namespace gcsim::media
