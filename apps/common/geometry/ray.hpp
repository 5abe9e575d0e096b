#pragma once
// A ray with the per-ray constants every intersection test reuses: the reciprocal direction
// for the slab test and the permutation/shear of the watertight triangle test.
#include <cmath>
#include <utility>

#include <glm/glm.hpp>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "apps/common/geometry/float_util.hpp"

namespace gcsim::geometry {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, 1.0f};
  float tmin = 0.0f;  // hits at t <= tmin are ignored

  // Derived; call prepare() after setting origin and direction.
  glm::vec3 inv_direction{0.0f};
  int kx = 0, ky = 1, kz = 2;  // kz: the axis where |direction| is largest
  float shear_x = 0, shear_y = 0, shear_z = 1;

  Ray() = default;
  Ray(glm::vec3 o, glm::vec3 d, float t0 = 0.0f) : origin(o), direction(d), tmin(t0) { prepare(); }

  glm::vec3 at(float t) const { return origin + t * direction; }

  void prepare() {
    // 1/0 gives +-inf, which the slab test handles; the sign of zero is kept.
#if defined(__SSE2__)
    // One vector division instead of three dependent scalar ones (each lane rounds the same).
    alignas(16) float inv[4];
    _mm_store_ps(inv, _mm_div_ps(_mm_set1_ps(1.0f), _mm_set_ps(1.0f, direction.z, direction.y, direction.x)));
    inv_direction = glm::vec3(inv[0], inv[1], inv[2]);
#else
    inv_direction = glm::vec3(1.0f / direction.x, 1.0f / direction.y, 1.0f / direction.z);
#endif
    const glm::vec3 a = abs_components(direction);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = kz == 2 ? 0 : kz + 1;
    ky = kx == 2 ? 0 : kx + 1;
    // Swapping kx and ky when the dominant component is negative keeps the winding, so the
    // sign of the edge functions has a fixed meaning; the test accepts both sides anyway.
    if (direction[kz] < 0.0f) std::swap(kx, ky);
    shear_z = inv_direction[kz];
    shear_x = -direction[kx] * shear_z;
    shear_y = -direction[ky] * shear_z;
  }
};

}  // namespace gcsim::geometry
