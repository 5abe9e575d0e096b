#include "apps/common/geometry/triangle.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "apps/common/geometry/float_util.hpp"
#include "apps/common/geometry/triangle_finish.hpp"

namespace gcsim::geometry {

namespace {

// Float keeps edge products (about m^2) and t_scaled (about m^3) normal and finite while the
// triangle's coordinates relative to the ray origin, m, stay within these bounds; outside them
// (coordinates of 1e30 or 1e-30) the test runs in double, whose range covers any finite float.
constexpr float kFloatSafeLargest = 1e12f;
constexpr float kFloatSafeSmallest = 1e-12f;

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

bool intersect_triangle(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  const glm::vec3 m = glm::max(glm::max(abs_components(tri.p0 - ray.origin), abs_components(tri.p1 - ray.origin)),
                               abs_components(tri.p2 - ray.origin));
  const float largest = std::max({m.x, m.y, m.z});
  if (largest <= kFloatSafeLargest && largest >= kFloatSafeSmallest)
    return intersect_in<float>(tri, ray, tmax, t_hit, b1, b2);
  return intersect_in<double>(tri, ray, tmax, t_hit, b1, b2);
}

}  // namespace gcsim::geometry
