#pragma once
// A ray against one primitive (sphere or triangle) of PrimitiveArrays, counted: the nearest-hit
// update with the id tie-break of Hit, and the any-hit test of shadow rays.
#include <cstdint>

#include "apps/common/geometry/hit.hpp"
#include "apps/common/geometry/primitive_arrays.hpp"

namespace gcsim::geometry {

// Local tallies of a traversal, added to TraceCounters by the caller (primary or secondary).
struct TestTally {
  std::int64_t boxes = 0;
  std::int64_t spheres = 0;
  std::int64_t triangles = 0;
  std::int64_t sorts = 0;
  std::int64_t prims() const { return spheres + triangles; }
};

inline void test_primitive(const PrimitiveArrays& prims, int prim, const Ray& ray, Hit& hit, TestTally& tally) {
  float t, b1 = 0, b2 = 0;
  bool found;
  if (prims.is_sphere(prim)) {
    ++tally.spheres;
    found = intersect_sphere(prims.spheres[prim], ray, hit.t, &t);
  } else {
    ++tally.triangles;
    found = intersect_triangle(prims.triangle(prim), ray, hit.t, &t, &b1, &b2);
  }
  if (found) hit.offer(t, prim, b1, b2);
}

// Any hit closer than tmax (shadow rays).
inline bool occludes(const PrimitiveArrays& prims, int prim, const Ray& ray, float tmax, TestTally& tally) {
  float t, b1, b2;
  if (prims.is_sphere(prim)) {
    ++tally.spheres;
    return intersect_sphere(prims.spheres[prim], ray, tmax, &t) && t < tmax;
  }
  ++tally.triangles;
  return intersect_triangle(prims.triangle(prim), ray, tmax, &t, &b1, &b2) && t < tmax;
}

}  // namespace gcsim::geometry
