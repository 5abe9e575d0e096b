#pragma once
// The specular dielectric boundary of the object (paper: "Fresnel specular surface"; IOR not given,
// 1.5 by default): unpolarized Fresnel reflectance, reflection and refraction with total internal
// reflection. Directions point along travel; n faces the side the ray comes from (dot(d, n) < 0).
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace gcsim::media {

inline constexpr double kDefaultIor = 1.5;

// Fresnel reflectance for cos θi (≥ 0) going from index eta_i into eta_t; 1 under total internal reflection.
inline double fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
  cos_i = std::min(1.0, std::max(0.0, cos_i));
  const double sin_t2 = (eta_i / eta_t) * (eta_i / eta_t) * (1.0 - cos_i * cos_i);
  if (sin_t2 >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin_t2);
  const double rs = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  const double rp = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

inline glm::dvec3 reflect_direction(const glm::dvec3& d, const glm::dvec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

// Snell refraction of d through n (dot(d, n) < 0) from eta_i into eta_t; nothing under TIR.
inline std::optional<glm::dvec3> refract_direction(const glm::dvec3& d, const glm::dvec3& n, double eta_i,
                                                   double eta_t) {
  const double eta = eta_i / eta_t, cos_i = -glm::dot(d, n);
  const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
  if (k < 0.0) return std::nullopt;
  return glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
}

}  // namespace gcsim::media
