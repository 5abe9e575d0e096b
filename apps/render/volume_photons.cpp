#include "apps/render/volume_photons.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "apps/common/geometry/ray_offset.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/common/ordered_parallel.hpp"
#include "apps/common/rng.hpp"
#include "apps/common/media/sampling.hpp"
#include "apps/raytrace/raytrace.hpp"

namespace gcsim::render {

using geometry::Hit;
using geometry::Ray;
using geometry::SurfacePoint;

namespace {

constexpr int kMaxPhotonEvents = 64;  // scatterings plus surface events, as the media app

void add_emitter(PhotonLights& l, PhotonLights::Emitter e, const scene::Rgb& rgb_flux) {
  if (e.flux <= 0.0) return;
  e.chroma = rgb_flux / e.flux;
  l.emitters.push_back(e);
  l.total_flux += e.flux;
  l.cumulative.push_back(l.total_flux);
  l.chroma += rgb_flux;
}

// A polygon's triangles (a fan), each emitting to the side `normal`.
void add_polygon(PhotonLights& l, const scene::Polygon& poly, const scene::Rgb& exitance, glm::dvec3 normal) {
  for (int k = 1; k + 1 < poly.count; ++k) {
    const glm::dvec3 a = poly.vertex[0], b = poly.vertex[std::size_t(k)], c = poly.vertex[std::size_t(k) + 1];
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    add_emitter(l, {PhotonLights::Emitter::Kind::triangle, a, b, c, normal, -1.0, luminance(exitance) * area},
                exitance * area);
  }
}

}  // namespace

media::HomogeneousMedium luminance_medium(const scene::Medium& m) {
  media::HomogeneousMedium out;
  out.sigma_s = luminance(m.sigma_s);
  out.sigma_t = luminance(m.sigma_s + m.sigma_a);
  out.phase = m.phase == scene::PhaseKind::isotropic ? media::Phase::isotropic()
              : m.phase == scene::PhaseKind::schlick ? media::Phase::schlick(m.phase_g)
                                                      : media::Phase::henyey_greenstein(m.phase_g);
  return out;
}

PhotonLights photon_lights(const scene::SceneDescription& d) {
  PhotonLights l;
  l.chroma = glm::dvec3(0.0);
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const scene::Shape& s = d.shapes[i];
    const scene::Rgb front = d.materials.at(std::size_t(s.material)).emission;
    const scene::Rgb back = s.back_material >= 0 ? d.materials.at(std::size_t(s.back_material)).emission : scene::Rgb(0.0);
    if (front == scene::Rgb(0.0) && back == scene::Rgb(0.0)) continue;
    const auto* poly = std::get_if<scene::Polygon>(&s.geometry);
    if (!poly)
      throw std::invalid_argument(fmt::format("shape {} emits light but is not a polygon: the photon pass emits from "
                                              "polygons, point and spot lights only", i + 1));
    glm::dvec3 n = glm::normalize(glm::cross(poly->vertex[1] - poly->vertex[0], poly->vertex[2] - poly->vertex[0]));
    if (poly->facing && glm::dot(n, *poly->facing) < 0.0) n = -n;  // the front looks along `facing`
    add_polygon(l, *poly, front, n);
    add_polygon(l, *poly, back, -n);
  }
  for (const scene::Light& light : d.lights) {
    if (const auto* p = std::get_if<scene::PointLight>(&light)) {
      add_emitter(l, {PhotonLights::Emitter::Kind::point, p->position, {}, {}, {}, -1.0, 4 * media::kPi * luminance(p->intensity)},
                  4 * media::kPi * p->intensity);
    } else if (std::holds_alternative<scene::DiskLight>(light)) {
      throw std::invalid_argument("a disk light (the media renderer's): the photon pass emits from polygons, point and "
                                  "spot lights only");
    } else {
      const auto& s = std::get<scene::SpotLight>(light);
      const double cos_cone = std::cos(s.cone_degrees * media::kPi / 180.0);
      const double solid_angle = 2 * media::kPi * (1 - cos_cone);
      add_emitter(l, {PhotonLights::Emitter::Kind::spot, s.position, {}, {}, glm::normalize(s.direction), cos_cone,
                      solid_angle * luminance(s.intensity)},
                  solid_angle * s.intensity);
    }
  }
  l.chroma = l.total_flux > 0 ? l.chroma / l.total_flux : glm::dvec3(1.0);
  return l;
}

namespace {

struct PhotonRay {
  glm::dvec3 origin, direction;
  glm::dvec3 tint{1.0};  // RGB flux over luminance flux
};

PhotonRay emit(const PhotonLights& l, apps::Rng& rng) {
  const double pick = rng.uniform_double() * l.total_flux;
  const std::size_t i = std::min<std::size_t>(
      std::size_t(std::upper_bound(l.cumulative.begin(), l.cumulative.end(), pick) - l.cumulative.begin()), l.emitters.size() - 1);
  const PhotonLights::Emitter& e = l.emitters[i];
  const double u1 = rng.uniform_double(), u2 = rng.uniform_double();
  switch (e.kind) {
    case PhotonLights::Emitter::Kind::triangle: {
      const double su = std::sqrt(rng.uniform_double()), v = rng.uniform_double();
      const glm::dvec3 at = e.a + su * (1 - v) * (e.b - e.a) + su * v * (e.c - e.a);
      return {at, media::direction_around(e.axis, std::sqrt(u1), u2), e.chroma};  // cosine-weighted: Lambertian
    }
    case PhotonLights::Emitter::Kind::point: return {e.a, media::uniform_sphere(u1, u2), e.chroma};
    case PhotonLights::Emitter::Kind::spot:
      return {e.a, media::direction_around(e.axis, 1 - u1 * (1 - e.cos_cone), u2), e.chroma};
  }
  return {e.a, e.axis, e.chroma};
}

// The photon's next medium interaction along the ray before t_max: the region it is in and where,
// or nullopt when the photon reaches t_max.
struct Interaction {
  std::size_t region;
  double t;
};
// A medium as the flights sample it (luminance) and as the tint weighs it (RGB).
struct FlightMedium {
  media::HomogeneousMedium lum;
  glm::dvec3 sigma_s{0.0}, sigma_t{0.0};
};
// tint: times exp(-(sigma_t - luminance sigma_t) d) per channel over the distance d flown in each
// medium, the ratio of the channel's transmittance to the sampled one.
std::optional<Interaction> free_flight(const std::vector<MediumRegion>& media, const std::vector<FlightMedium>& fm,
                                       const PhotonRay& r, double t_max, apps::Rng& rng, glm::dvec3& tint) {
  // Each interval is in one medium; the free flight is memoryless, so each is sampled afresh in turn.
  for (const MediumInterval& part : medium_intervals(media, r.origin, r.direction, t_max)) {
    const FlightMedium& m = fm[part.region];
    const double sigma_t = m.lum.sigma_t;
    if (sigma_t <= 0.0) continue;
    const double t = part.t0 - std::log1p(-rng.uniform_double()) / sigma_t;
    const double flown = std::min(t, part.t1) - part.t0;
    tint *= glm::exp(-(m.sigma_t - sigma_t) * flown);
    if (t < part.t1) return Interaction{part.region, t};
  }
  return std::nullopt;
}

// Russian roulette at a surface: the continuing direction, or nullopt (absorbed). A diffuse
// bounce, chosen by the luminance of the colour, multiplies the tint by colour over luminance.
std::optional<glm::dvec3> bounce(const raytrace::Scene& scene, const Ray& ray, const Hit& hit, apps::Rng& rng,
                                 PhotonRay& r) {
  const raytrace::Material& m = scene.material_of(hit.prim);
  const SurfacePoint sp = scene.surface_point(ray, hit.prim, hit.t, hit.b1, hit.b2);
  const glm::vec3 d = glm::normalize(ray.direction), n = sp.shading_normal;
  const double xi = rng.uniform_double();
  std::optional<glm::vec3> out;
  if (m.transmittance > 0.0f) {
    const float eta = sp.entering ? 1.0f / m.ior : m.ior;
    const auto refracted = raytrace::refract_direction(d, n, eta);
    const float f = refracted ? raytrace::fresnel_dielectric(-glm::dot(d, n), eta) : 1.0f;
    if (xi < f * m.reflectance) out = raytrace::reflect_direction(d, n);
    else if (refracted && xi < f * m.reflectance + (1 - f) * m.transmittance) out = *refracted;
  } else if (xi < m.reflectance) {
    out = raytrace::reflect_direction(d, n);
  } else {
    const double diffuse = luminance(glm::dvec3(m.diffuse));
    if (xi < m.reflectance + (1 - m.reflectance) * diffuse) {
      out = glm::vec3(media::direction_around(glm::dvec3(sp.geometric_normal), std::sqrt(rng.uniform_double()), rng.uniform_double()));
      r.tint *= glm::dvec3(m.diffuse) / diffuse;
    }
  }
  if (!out) return std::nullopt;
  r.origin = glm::dvec3(offset_ray_origin(sp, *out));
  return glm::normalize(glm::dvec3(*out));
}

VolumePhotons trace_photon_range(const raytrace::Scene& surfaces, const geometry::Bvh& bvh, const PhotonLights& lights,
                                 const std::vector<MediumRegion>& media, std::size_t first, std::size_t last,
                                 std::size_t total, std::uint64_t seed, const WallHit& on_wall,
                                 const PhotonsTraced& on_traced) {
  VolumePhotons out;
  out.per_region.resize(media.size());
  if (lights.emitters.empty() || total == 0) return out;
  std::vector<FlightMedium> fm;
  for (const MediumRegion& r : media)
    fm.push_back({luminance_medium(r.medium), r.medium.sigma_s, r.medium.sigma_s + r.medium.sigma_a});
  const float power = float(lights.total_flux / double(total));
  for (std::size_t i = first; i < last; ++i) {
    if (on_traced && i > first && (i - first) % kPhotonsPerReport == 0) on_traced(kPhotonsPerReport);
    apps::Rng rng(seed, 0x70686f746f6eULL + i);
    PhotonRay r = emit(lights, rng);
    bool scattered = false;  // this flight began at a scattering (or at a mirror or glass after one)
    for (int event = 0; event < kMaxPhotonEvents; ++event) {
      // Leaving an emitter or a surface, the first hit beyond a small distance is the next surface.
      const Ray ray(glm::vec3(r.origin), glm::vec3(r.direction), 1e-5f * (1.0f + glm::length(glm::vec3(r.origin))));
      Hit hit;
      traverse_ordered(surfaces, bvh.packed, ray, hit, out.tests);
      const double t_hit = hit.valid() ? double(hit.t) : std::numeric_limits<double>::infinity();
      if (const auto at = free_flight(media, fm, r, t_hit, rng, r.tint)) {
        ++out.flights;
        const glm::dvec3 x = r.origin + at->t * r.direction;
        out.per_region[at->region].push_back({glm::vec3(x), glm::vec3(r.direction), power});
        const FlightMedium& m = fm[at->region];
        if (rng.uniform_double() >= m.lum.albedo()) {  // absorbed
          out.media_absorbed += power;
          break;
        }
        r.tint *= m.sigma_s / m.lum.sigma_s;
        r = {x, media::direction_around(r.direction, m.lum.phase.sample_cos(rng.uniform_double()), rng.uniform_double()), r.tint};
        scattered = true;
        continue;
      }
      if (!hit.valid()) break;  // left the scene
      ++out.surface_events;
      const bool specular = surfaces.material_of(hit.prim).spawns_secondary();
      if (scattered && !specular) {
        ++out.wall_hits;
        if (on_wall) on_wall(r.origin, r.direction, double(power) * r.tint);
      }
      scattered = scattered && specular;
      const auto next = bounce(surfaces, ray, hit, rng, r);
      if (!next) break;
      r.direction = *next;
    }
  }
  if (on_traced && last > first) on_traced((last - first - 1) % kPhotonsPerReport + 1);
  return out;
}

// A batch's photons and its wall hits, kept to be handed on in photon order.
struct PhotonBatch {
  VolumePhotons photons;
  std::vector<std::array<glm::dvec3, 3>> wall_hits;  // origin, direction, power
};

}  // namespace

VolumePhotons trace_volume_photons(const raytrace::Scene& surfaces, const geometry::Bvh& bvh, const PhotonLights& lights,
                                   const std::vector<MediumRegion>& media, std::size_t first, std::size_t last,
                                   std::size_t total, std::uint64_t seed, const WallHit& on_wall,
                                   const PhotonsTraced& on_traced, int jobs) {
  if (jobs <= 1 || last <= first)
    return trace_photon_range(surfaces, bvh, lights, media, first, last, total, seed, on_wall, on_traced);
  // Batches in photon order, each photon on its own stream; joined and their wall hits replayed in
  // order, they give one range's photons, sums and calls exactly.
  const std::size_t batches = std::min<std::size_t>(last - first, std::size_t(jobs) * kPhotonBatchesPerThread);
  VolumePhotons out;
  out.per_region.resize(media.size());
  apps::run_ordered<PhotonBatch>(
      int(batches), jobs,
      [&](int b) {
        PhotonBatch batch;
        WallHit record;
        if (on_wall)
          record = [&batch](const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& power) {
            batch.wall_hits.push_back({o, d, power});
          };
        batch.photons = trace_photon_range(surfaces, bvh, lights, media, first + (last - first) * std::size_t(b) / batches,
                                           first + (last - first) * std::size_t(b + 1) / batches, total, seed, record, {});
        return batch;
      },
      [&](int b, PhotonBatch& batch) {
        const VolumePhotons& part = batch.photons;
        for (std::size_t r = 0; r < part.per_region.size() && r < out.per_region.size(); ++r)
          out.per_region[r].insert(out.per_region[r].end(), part.per_region[r].begin(), part.per_region[r].end());
        out.flights += part.flights, out.surface_events += part.surface_events, out.wall_hits += part.wall_hits;
        out.media_absorbed += part.media_absorbed;  // sums of one float power: exact in double in any grouping
        out.tests.boxes += part.tests.boxes, out.tests.spheres += part.tests.spheres;
        out.tests.triangles += part.tests.triangles, out.tests.sorts += part.tests.sorts;
        for (const auto& hit : batch.wall_hits) on_wall(hit[0], hit[1], hit[2]);
        if (on_traced)
          on_traced((last - first) * std::size_t(b + 1) / batches - (last - first) * std::size_t(b) / batches);
      });
  return out;
}

}  // namespace gcsim::render
