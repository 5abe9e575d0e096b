#include "apps/media/photon_tracer.hpp"

#include <algorithm>
#include <cmath>

#include "apps/common/ordered_parallel.hpp"
#include "apps/common/rng.hpp"
#include "apps/common/media/sampling.hpp"

namespace gcsim::media {
namespace {

// Reflects or refracts at the boundary; returns the new direction.
glm::dvec3 cross_boundary(const BoundaryHit& hit, const glm::dvec3& d, double ior, apps::Rng& rng) {
  const double eta_i = hit.entering ? 1.0 : ior, eta_t = hit.entering ? ior : 1.0;
  const double reflectance = fresnel_dielectric(-glm::dot(d, hit.normal), eta_i, eta_t);
  if (rng.uniform_double() < reflectance) return reflect_direction(d, hit.normal);
  auto refracted = refract_direction(d, hit.normal, eta_i, eta_t);
  return refracted ? *refracted : reflect_direction(d, hit.normal);
}

// A photon leaving the point light (uniform directions) or the directional disk light: a uniform point
// on the disk, a direction with density ∝ cos^n θ (inverse CDF: cos θ = ξ^{1/(n+1)}) [radiance ∝ cos^{n−1}].
void emit_photon(const MediaScene& scene, apps::Rng& rng, glm::dvec3& x, glm::dvec3& w) {
  if (!scene.area_light) {
    x = scene.light.position;
    w = uniform_sphere(rng.uniform_double(), rng.uniform_double());
    return;
  }
  const DirectionalAreaLight& l = *scene.area_light;
  glm::dvec3 b1, b2;
  orthonormal_basis(l.normal, b1, b2);
  const double r = l.radius * std::sqrt(rng.uniform_double()), phi = 2.0 * kPi * rng.uniform_double();
  x = l.centre + r * std::cos(phi) * b1 + r * std::sin(phi) * b2;
  w = direction_around(l.normal, std::pow(rng.uniform_double(), 1.0 / (l.exponent + 1.0)), rng.uniform_double());
}

}  // namespace

namespace {

PhotonPassResult trace_photon_range(const MediaScene& scene, std::size_t first, std::size_t last) {
  PhotonPassResult out;
  const double flux = scene.area_light ? scene.area_light->power : 4.0 * kPi * scene.light.intensity;
  const auto power = static_cast<float>(flux / double(scene.photons_emitted));
  for (std::size_t i = first; i < last; ++i) {
    apps::Rng rng(scene.seed, 0x70686f746f6eULL + i);
    glm::dvec3 x, w;
    emit_photon(scene, rng, x, w);
    bool inside = scene.object && scene.object->inside(x, &out.boundary);
    int events = 0;
    for (; events < scene.max_photon_events; ++events) {
      const HomogeneousMedium& m = inside ? scene.inside : scene.outside;
      const double flight = m.sigma_t > 0 ? -std::log1p(-rng.uniform_double()) / m.sigma_t : 1e30;
      ++out.flights;
      auto hit = scene.object ? scene.object->intersect(x, w, 0.0, flight, &out.boundary) : std::nullopt;
      if (hit) {
        ++out.surface_events;
        const glm::dvec3 at = x + hit->t * w;
        const glm::dvec3 nw = cross_boundary(*hit, w, scene.ior, rng);
        if (glm::dot(nw, hit->normal) < 0.0) {  // went through
          inside = !inside;
          if (inside) ++out.entered;
        }
        w = nw;
        x = scene.object->leave_surface(at, *hit, w);
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

}  // namespace

PhotonPassResult trace_photons(const MediaScene& scene, std::size_t first, std::size_t last, int jobs) {
  if (jobs <= 1 || last <= first) return trace_photon_range(scene, first, last);
  // Batches in photon order, each photon on its own stream: joined in order, they are one range's photons.
  const std::size_t batches = std::min<std::size_t>(last - first, std::size_t(jobs) * kPhotonBatchesPerThread);
  PhotonPassResult out;
  apps::run_ordered<PhotonPassResult>(
      int(batches), jobs,
      [&](int b) {
        return trace_photon_range(scene, first + (last - first) * std::size_t(b) / batches,
                                  first + (last - first) * std::size_t(b + 1) / batches);
      },
      [&](int, PhotonPassResult& part) {
        out.outside.insert(out.outside.end(), part.outside.begin(), part.outside.end());
        out.inside.insert(out.inside.end(), part.inside.begin(), part.inside.end());
        out.flights += part.flights, out.surface_events += part.surface_events, out.escaped += part.escaped;
        out.absorbed += part.absorbed, out.capped += part.capped, out.entered += part.entered;
        out.boundary.add(part.boundary);
      });
  return out;
}

}  // namespace gcsim::media
