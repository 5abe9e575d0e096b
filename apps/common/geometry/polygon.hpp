#pragma once
// Small geometry vocabulary for radiosity: double-precision points, planar polygons of three or
// four vertices (the thesis's PATCH and ELEMENT records), and an orthonormal frame.
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace gcsim::geometry {

using Vec3 = glm::dvec3;
using Rgb = glm::dvec3;

// A convex planar polygon; count is 3 or 4.
struct Polygon {
  std::array<Vec3, 4> v{};
  int count = 0;
};

// Newell's method: robust for slightly non-planar quads; length is twice the area.
inline Vec3 newell_normal(const Polygon& p) {
  Vec3 n(0.0);
  for (int i = 0; i < p.count; ++i) {
    const Vec3& a = p.v[i];
    const Vec3& b = p.v[(i + 1) % p.count];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}
inline double polygon_area(const Polygon& p) { return 0.5 * glm::length(newell_normal(p)); }
inline Vec3 polygon_normal(const Polygon& p) {
  Vec3 n = newell_normal(p);
  double l = glm::length(n);
  return l > 0 ? n / l : Vec3(0, 0, 1);
}
// Area-weighted centroid (for a triangle or a convex quad).
inline Vec3 polygon_centroid(const Polygon& p) {
  if (p.count == 3) return (p.v[0] + p.v[1] + p.v[2]) / 3.0;
  Vec3 c1 = (p.v[0] + p.v[1] + p.v[2]) / 3.0, c2 = (p.v[0] + p.v[2] + p.v[3]) / 3.0;
  double a1 = 0.5 * glm::length(glm::cross(p.v[1] - p.v[0], p.v[2] - p.v[0]));
  double a2 = 0.5 * glm::length(glm::cross(p.v[2] - p.v[0], p.v[3] - p.v[0]));
  if (a1 + a2 <= 0) return (p.v[0] + p.v[1] + p.v[2] + p.v[3]) / 4.0;
  return (c1 * a1 + c2 * a2) / (a1 + a2);
}

// Right-handed orthonormal frame (u, v, n) around a unit normal n.
struct Frame {
  Vec3 u, v, n;
  static Frame from_normal(const Vec3& n) {
    // Pick the world axis least aligned with n so that u is well conditioned.
    Vec3 a = std::abs(n.x) < 0.57 ? Vec3(1, 0, 0) : (std::abs(n.y) < 0.57 ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
    Vec3 u = glm::normalize(glm::cross(a, n));
    return {u, glm::cross(n, u), n};
  }
  Vec3 to_local(const Vec3& w) const { return {glm::dot(w, u), glm::dot(w, v), glm::dot(w, n)}; }
};

inline double channel_sum(const Rgb& c) { return c.r + c.g + c.b; }

}  // namespace gcsim::geometry
