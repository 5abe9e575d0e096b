#pragma once
// The second half of the watertight triangle test (triangle.cpp), from the triangle already in the
// ray's frame: in a header so that a caller holding the sheared vertices and edge functions in
// registers (the single-ray walk, after the SSE rejection) runs it without a trip through memory.
#include <algorithm>
#include <cmath>
#include <limits>

#include "apps/common/geometry/float_util.hpp"
#include "apps/common/geometry/ray.hpp"

namespace gcsim::geometry {

// The second half of the test, from the sheared vertices (a, b, c in the ray's frame) and the
// edge functions. T is the arithmetic (float, or double for geometry outside float's safe range);
// the rounding bounds are T's. kSignsAgree: the caller knows the three edge functions are nonzero
// and of one sign (the SSE rejection's "inside" verdict), so the first check could never fail.
template <class T, bool kSignsAgree = false>
inline bool watertight_finish(T ax, T ay, T az, T bx, T by, T bz, T cx, T cy, T cz, T e0, T e1, T e2, const Ray& ray,
                              float tmax, float* t_hit, float* b1, float* b2) {
  auto gamma = [](int n) { return gamma_of<T>(n); };
  if constexpr (!kSignsAgree) {
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
  }
  const T det = e0 + e1 + e2;
  if (det == 0) return false;  // degenerate, or seen exactly edge-on

  const T sz = ray.shear_z;
  const T zs0 = az * sz, zs1 = bz * sz, zs2 = cz * sz;
  const T t_scaled = e0 * zs0 + e1 * zs1 + e2 * zs2;
  // Reject outside (tmin, tmax] without dividing, widened by the products' rounding so that a
  // hit at exactly tmax (a coincident triangle: the id tie-break of Hit decides) is not lost here;
  // the exact test on t follows.
  const T t0 = ray.tmin, t1 = T(tmax) * (1 + T(4) * std::numeric_limits<T>::epsilon());
  if (det < 0 && (t_scaled >= t0 * det || t_scaled < t1 * det)) return false;
  if (det > 0 && (t_scaled <= t0 * det || t_scaled > t1 * det)) return false;
  const T inv_det = T(1) / det;
  const T t = t_scaled * inv_det;

  // t must exceed its own rounding error, or the "hit" may be the ray's own surface.
  const T max_z = std::max({std::abs(zs0), std::abs(zs1), std::abs(zs2)});
  const T dz = gamma(3) * max_z;
  const T max_x = std::max({std::abs(ax), std::abs(bx), std::abs(cx)});
  const T max_y = std::max({std::abs(ay), std::abs(by), std::abs(cy)});
  const T dx = gamma(5) * (max_x + max_z);
  const T dy = gamma(5) * (max_y + max_z);
  const T de = 2 * (gamma(2) * max_x * max_y + dy * max_x + dx * max_y);
  const T max_e = std::max({std::abs(e0), std::abs(e1), std::abs(e2)});
  const T dt = 3 * (gamma(3) * max_e * max_z + de * max_z + dz * max_e) * std::abs(inv_det);
  if (t <= dt) return false;
  const float tf = static_cast<float>(t);
  if (!(tf > ray.tmin && tf <= tmax)) return false;

  *t_hit = tf;
  *b1 = static_cast<float>(e1 * inv_det);
  *b2 = static_cast<float>(e2 * inv_det);
  return true;
}

}  // namespace gcsim::geometry
