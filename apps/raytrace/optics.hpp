#pragma once
// Mirror reflection, Snell refraction and the Fresnel reflectance of a dielectric.
#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

namespace gcsim::raytrace {

// d: incoming direction (unit); n: unit normal on the side d comes from (dot(d, n) < 0).
inline glm::vec3 reflect_direction(glm::vec3 d, glm::vec3 n) { return d - 2.0f * glm::dot(d, n) * n; }

// eta = n_incident / n_transmitted. Empty on total internal reflection.
inline std::optional<glm::vec3> refract_direction(glm::vec3 d, glm::vec3 n, float eta) {
  const float cos_i = std::clamp(-glm::dot(d, n), 0.0f, 1.0f);
  const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  if (sin2_t >= 1.0f) return std::nullopt;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

// Unpolarised Fresnel reflectance for light arriving at cos_i through eta = n_i / n_t;
// 1 under total internal reflection.
inline float fresnel_dielectric(float cos_i, float eta) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  if (sin2_t >= 1.0f) return 1.0f;
  const float cos_t = std::sqrt(1.0f - sin2_t);
  const float r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const float r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return std::clamp(0.5f * (r_par * r_par + r_perp * r_perp), 0.0f, 1.0f);
}

}  // namespace gcsim::raytrace
