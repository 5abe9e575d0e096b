#pragma once
// Single scattering from a point light along one ray segment in a homogeneous medium (the shadow-ray
// direct term of J&C98, option [A5]; notes test 6):
//   L = σs ∫_0^{T} e^{−σt t} p(ω_l(t)·ω_o) I e^{−σt d(t)} / d(t)² dt,
// with ω_l the light's travel direction at x(t), ω_o = −d, I the radiant intensity and d(t) = |x(t) − light|.
#include <cmath>
#include <span>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "apps/common/media/distance_sampling.hpp"
#include "apps/common/media/medium.hpp"
#include "apps/common/media/phase.hpp"
#include "apps/common/media/segment_estimator.hpp"

namespace gcsim::media {

struct PointLight {
  glm::dvec3 position;
  double intensity;  // W/sr (luminance)
};

// Li(t)·σs-free integrand part: p(ω_l·ω_o) I e^{−σt d}/d² at x(t) (no occluders in this test case).
inline double point_light_in_scatter(const HomogeneousMedium& m, const PointLight& light, const glm::dvec3& o,
                                     const glm::dvec3& dir, double t) {
  const glm::dvec3 to_x = o + t * dir - light.position;
  const double d2 = glm::dot(to_x, to_x);
  if (d2 <= 0.0) return 0.0;
  const double d = std::sqrt(d2);
  return m.phase.eval(glm::dot(to_x / d, -dir)) * light.intensity * std::exp(-m.sigma_t * d) / d2;
}

// An equiangular sampler set up for `light` on the segment o + t dir, t in [0, length].
inline EquiangularDistance equiangular_for(const PointLight& light, const glm::dvec3& o, const glm::dvec3& dir,
                                           Segment segment) {
  const double along = glm::dot(light.position - o, dir);
  const double off = glm::length(light.position - (o + along * dir));
  return EquiangularDistance(segment, along, off);
}

template <class Sampler>
double single_scatter(const HomogeneousMedium& m, const PointLight& light, const glm::dvec3& o, const glm::dvec3& dir,
                      const Sampler& sampler, std::span<const double> u) {
  return m.sigma_s *
         estimate_in_scatter(sampler, u, [&](double t) { return point_light_in_scatter(m, light, o, dir, t); });
}

}  // namespace gcsim::media
