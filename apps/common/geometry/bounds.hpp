#pragma once
// Axis-aligned bounding boxes: the paper's bounding volumes (section 2.1.2 chooses boxes for
// their cheap intersection test over tighter but costlier shapes).
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "apps/common/geometry/float_util.hpp"
#include "apps/common/geometry/ray.hpp"

namespace gcsim::geometry {

struct Bounds3 {
  glm::vec3 lo{kInfinity};
  glm::vec3 hi{-kInfinity};

  static Bounds3 of_point(glm::vec3 p) { return {p, p}; }
  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void extend(glm::vec3 p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  void extend(const Bounds3& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
  glm::vec3 center() const { return 0.5f * (lo + hi); }
  glm::vec3 extent() const { return hi - lo; }
  float surface_area() const {
    if (empty()) return 0.0f;
    const glm::vec3 e = extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  bool contains(glm::vec3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  // Grown by a few float ulps of its own magnitude, so that a hit the primitive test reports can
  // never fall outside the box because of rounding.
  Bounds3 padded() const {
    const glm::vec3 mag = glm::max(abs_components(lo), abs_components(hi));
    const float pad = 4.0f * gamma(3) * std::max({mag.x, mag.y, mag.z, 1e-30f});
    return {lo - pad, hi + pad};
  }
  // Euclidean distance from p to the nearest point of the box (0 inside).
  float distance_to(glm::vec3 p) const { return std::sqrt(squared_distance_to(p)); }
  // Its square, without the square root: compare it with largest_with_sqrt_at_most(limit) to
  // learn whether distance_to(p) > limit (the uniformity test asks that of many boxes).
  float squared_distance_to(glm::vec3 p) const {
#if defined(__SSE2__)
    // max by maxss: written as glm::max, the compiler branches on each axis's sign (max(x, 0)^2
    // is 0 or x^2), which mispredicts in the uniformity test's loop. A tie between zeros may
    // keep the other sign; the square is +0 either way, so the distance is the same.
    const auto gap = [](float below, float above) {
      return _mm_cvtss_f32(_mm_max_ss(_mm_max_ss(_mm_set_ss(below), _mm_set_ss(above)), _mm_setzero_ps()));
    };
    const float dx = gap(lo.x - p.x, p.x - hi.x), dy = gap(lo.y - p.y, p.y - hi.y), dz = gap(lo.z - p.z, p.z - hi.z);
    return dx * dx + dy * dy + dz * dz;
#else
    const glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
#endif
  }
};

inline Bounds3 union_of(const Bounds3& a, const Bounds3& b) {
  Bounds3 r = a;
  r.extend(b);
  return r;
}

// Slab test over [ray.tmin, tmax]. On a hit, *entry is a lower bound of the distance at which the
// ray enters the box (used to sort children and prune, section 2.2.2).
// Conservative: the far distance is scaled up by 1 + 2*gamma(3) (the slab products round), and
// a NaN from 0 * inf (origin on a slab plane of an axis-parallel ray) is ignored, counting the
// plane as inside.
inline bool intersect_box(const Bounds3& b, const Ray& r, float tmax, float* entry) {
  float t0 = r.tmin, t1 = tmax;
  for (int a = 0; a < 3; ++a) {
    float tn = (b.lo[a] - r.origin[a]) * r.inv_direction[a];
    float tf = (b.hi[a] - r.origin[a]) * r.inv_direction[a];
    if (tn > tf) std::swap(tn, tf);
    tf *= 1.0f + 2.0f * gamma(3);
    t0 = tn > t0 ? tn : t0;
    t1 = tf < t1 ? tf : t1;
    if (t0 > t1) return false;
  }
  *entry = t0 * (1.0f - 2.0f * gamma(3));
  return true;
}

}  // namespace gcsim::geometry
