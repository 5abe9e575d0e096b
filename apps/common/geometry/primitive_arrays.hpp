#pragma once
// The primitives a box tree is built over and traversed against: spheres and triangles in one id
// space, spheres first. The ray tracer's scene extends this with materials and lights; the BVH and
// the traversal kernels need only the geometry.
#include <vector>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/sphere.hpp"
#include "apps/common/geometry/triangle.hpp"

namespace gcsim::geometry {

struct PrimitiveArrays {
  std::vector<Sphere> spheres;
  std::vector<Triangle> triangles;

  int sphere_count() const { return static_cast<int>(spheres.size()); }
  int prim_count() const { return static_cast<int>(spheres.size() + triangles.size()); }
  bool is_sphere(int prim) const { return prim < sphere_count(); }
  const Triangle& triangle(int prim) const { return triangles[prim - sphere_count()]; }
  Bounds3 prim_bounds(int prim) const {
    return is_sphere(prim) ? spheres[prim].bounds() : triangle(prim).bounds();
  }
};

}  // namespace gcsim::geometry
