#include "apps/common/geometry/triangle.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "apps/common/geometry/float_util.hpp"

namespace gcsim::geometry {

namespace {

// Float keeps edge products (about m^2) and t_scaled (about m^3) normal and finite while the
// triangle's coordinates relative to the ray origin, m, stay within these bounds; outside them
// (coordinates of 1e30 or 1e-30) the test runs in double, whose range covers any finite float.
constexpr float kFloatSafeLargest = 1e12f;
constexpr float kFloatSafeSmallest = 1e-12f;

// The second half of the test, from the sheared vertices (a, b, c in the ray's frame) and the
// edge functions. T is the arithmetic (float, or double for geometry outside float's safe range);
// the rounding bounds are T's.
template <class T>
inline bool watertight_finish(T ax, T ay, T az, T bx, T by, T bz, T cx, T cy, T cz, T e0, T e1, T e2, const Ray& ray,
                              float tmax, float* t_hit, float* b1, float* b2) {
  auto gamma = [](int n) { return gamma_of<T>(n); };
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
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

// The axes are template parameters so that the permutation costs nothing at run time; T is the
// arithmetic (the float inputs convert to double exactly).
template <class T, int kx, int ky, int kz>
bool watertight(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  using V = glm::vec<3, T>;
  // Translate to the ray origin, permute so the dominant direction axis is z, then shear.
  const V o(ray.origin);
  const V a = V(tri.p0) - o, b = V(tri.p1) - o, c = V(tri.p2) - o;
  const T sx = ray.shear_x, sy = ray.shear_y;
  const T az = a[kz], bz = b[kz], cz = c[kz];
  const T ax = a[kx] + sx * az, ay = a[ky] + sy * az;
  const T bx = b[kx] + sx * bz, by = b[ky] + sy * bz;
  const T cx = c[kx] + sx * cz, cy = c[ky] + sy * cz;

  // Edge functions: twice the signed areas of the sub-triangles seen from the ray.
  T e0 = bx * cy - by * cx;
  T e1 = cx * ay - cy * ax;
  T e2 = ax * by - ay * bx;
  if (std::is_same_v<T, float> && (e0 == 0 || e1 == 0 || e2 == 0)) {
    // Exactly on an edge in float: decide in double, so the shared edge is never skipped by both.
    e0 = static_cast<T>(double(bx) * cy - double(by) * cx);
    e1 = static_cast<T>(double(cx) * ay - double(cy) * ax);
    e2 = static_cast<T>(double(ax) * by - double(ay) * bx);
  }
  return watertight_finish<T>(ax, ay, az, bx, by, bz, cx, cy, cz, e0, e1, e2, ray, tmax, t_hit, b1, b2);
}

template <class T>
bool intersect_in(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  switch (ray.kz * 3 + ray.kx) {
    case 0 * 3 + 1: return watertight<T, 1, 2, 0>(tri, ray, tmax, t_hit, b1, b2);
    case 0 * 3 + 2: return watertight<T, 2, 1, 0>(tri, ray, tmax, t_hit, b1, b2);
    case 1 * 3 + 2: return watertight<T, 2, 0, 1>(tri, ray, tmax, t_hit, b1, b2);
    case 1 * 3 + 0: return watertight<T, 0, 2, 1>(tri, ray, tmax, t_hit, b1, b2);
    case 2 * 3 + 0: return watertight<T, 0, 1, 2>(tri, ray, tmax, t_hit, b1, b2);
    default: return watertight<T, 1, 0, 2>(tri, ray, tmax, t_hit, b1, b2);
  }
}

}  // namespace

bool finish_triangle_test(const ShearedTriangle& s, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  return watertight_finish<float>(s.x[0], s.y[0], s.z[0], s.x[1], s.y[1], s.z[1], s.x[2], s.y[2], s.z[2], s.e[0],
                                  s.e[1], s.e[2], ray, tmax, t_hit, b1, b2);
}

bool intersect_triangle(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  const glm::vec3 m = glm::max(glm::max(abs_components(tri.p0 - ray.origin), abs_components(tri.p1 - ray.origin)),
                               abs_components(tri.p2 - ray.origin));
  const float largest = std::max({m.x, m.y, m.z});
  if (largest <= kFloatSafeLargest && largest >= kFloatSafeSmallest)
    return intersect_in<float>(tri, ray, tmax, t_hit, b1, b2);
  return intersect_in<double>(tri, ray, tmax, t_hit, b1, b2);
}

}  // namespace gcsim::geometry
