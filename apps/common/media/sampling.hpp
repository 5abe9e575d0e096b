#pragma once
// Direction sampling helpers shared by the photon tracer and the renderer.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "apps/common/media/phase.hpp"

namespace gcsim::media {

inline glm::dvec3 uniform_sphere(double u1, double u2) {
  const double z = 1.0 - 2.0 * u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// An orthonormal frame around n (Duff et al. 2017).
inline void orthonormal_basis(const glm::dvec3& n, glm::dvec3& b1, glm::dvec3& b2) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  b1 = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  b2 = {b, sign + n.y * n.y * a, -n.y};
}

// A direction at cos θ = u from `axis`, azimuth 2π u2.
inline glm::dvec3 direction_around(const glm::dvec3& axis, double u, double u2) {
  glm::dvec3 b1, b2;
  orthonormal_basis(axis, b1, b2);
  const double s = std::sqrt(std::max(0.0, 1.0 - u * u)), phi = 2.0 * kPi * u2;
  return glm::normalize(u * axis + s * std::cos(phi) * b1 + s * std::sin(phi) * b2);
}

}  // namespace gcsim::media
