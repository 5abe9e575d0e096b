#include "apps/common/geometry/triangle.hpp"

#include <cmath>

#include "apps/common/geometry/float_util.hpp"

namespace gcsim::geometry {

namespace {

// The axes are template parameters so that the permutation costs nothing at run time.
template <int kx, int ky, int kz>
bool watertight(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  // Translate to the ray origin, permute so the dominant direction axis is z, then shear.
  const glm::vec3 a = tri.p0 - ray.origin, b = tri.p1 - ray.origin, c = tri.p2 - ray.origin;
  const float sx = ray.shear_x, sy = ray.shear_y, sz = ray.shear_z;
  const float az = a[kz], bz = b[kz], cz = c[kz];
  const float ax = a[kx] + sx * az, ay = a[ky] + sy * az;
  const float bx = b[kx] + sx * bz, by = b[ky] + sy * bz;
  const float cx = c[kx] + sx * cz, cy = c[ky] + sy * cz;

  // Edge functions: twice the signed areas of the sub-triangles seen from the ray.
  float e0 = bx * cy - by * cx;
  float e1 = cx * ay - cy * ax;
  float e2 = ax * by - ay * bx;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
    // Exactly on an edge in float: decide in double, so the shared edge is never skipped by both.
    e0 = static_cast<float>(double(bx) * cy - double(by) * cx);
    e1 = static_cast<float>(double(cx) * ay - double(cy) * ax);
    e2 = static_cast<float>(double(ax) * by - double(ay) * bx);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;  // degenerate, or seen exactly edge-on

  const float zs0 = az * sz, zs1 = bz * sz, zs2 = cz * sz;
  const float t_scaled = e0 * zs0 + e1 * zs1 + e2 * zs2;
  // Reject outside (tmin, tmax] without dividing.
  if (det < 0 && (t_scaled >= ray.tmin * det || t_scaled < tmax * det)) return false;
  if (det > 0 && (t_scaled <= ray.tmin * det || t_scaled > tmax * det)) return false;
  const float inv_det = 1.0f / det;
  const float t = t_scaled * inv_det;

  // t must exceed its own rounding error, or the "hit" may be the ray's own surface.
  const float max_z = std::max({std::abs(zs0), std::abs(zs1), std::abs(zs2)});
  const float dz = gamma(3) * max_z;
  const float max_x = std::max({std::abs(ax), std::abs(bx), std::abs(cx)});
  const float max_y = std::max({std::abs(ay), std::abs(by), std::abs(cy)});
  const float dx = gamma(5) * (max_x + max_z);
  const float dy = gamma(5) * (max_y + max_z);
  const float de = 2 * (gamma(2) * max_x * max_y + dy * max_x + dx * max_y);
  const float max_e = std::max({std::abs(e0), std::abs(e1), std::abs(e2)});
  const float dt = 3 * (gamma(3) * max_e * max_z + de * max_z + dz * max_e) * std::abs(inv_det);
  if (t <= dt) return false;
  if (!(t > ray.tmin && t <= tmax)) return false;

  *t_hit = t;
  *b1 = e1 * inv_det;
  *b2 = e2 * inv_det;
  return true;
}

}  // namespace

bool intersect_triangle(const Triangle& tri, const Ray& ray, float tmax, float* t_hit, float* b1, float* b2) {
  switch (ray.kz * 3 + ray.kx) {
    case 0 * 3 + 1: return watertight<1, 2, 0>(tri, ray, tmax, t_hit, b1, b2);
    case 0 * 3 + 2: return watertight<2, 1, 0>(tri, ray, tmax, t_hit, b1, b2);
    case 1 * 3 + 2: return watertight<2, 0, 1>(tri, ray, tmax, t_hit, b1, b2);
    case 1 * 3 + 0: return watertight<0, 2, 1>(tri, ray, tmax, t_hit, b1, b2);
    case 2 * 3 + 0: return watertight<0, 1, 2>(tri, ray, tmax, t_hit, b1, b2);
    default: return watertight<1, 0, 2>(tri, ray, tmax, t_hit, b1, b2);
  }
}

}  // namespace gcsim::geometry
