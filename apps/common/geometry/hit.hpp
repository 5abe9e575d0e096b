#pragma once
// The nearest hit along a ray. Ties (two primitives at exactly the same distance, as along a
// shared mesh edge) go to the lower primitive id, so that every traversal order, and brute
// force, report the same primitive.
#include <cstdint>

#include "apps/common/geometry/float_util.hpp"

namespace gcsim::geometry {

struct Hit {
  float t = kInfinity;
  std::int32_t prim = -1;  // -1: no hit
  float b1 = 0, b2 = 0;    // barycentric coordinates (triangles)

  bool valid() const { return prim >= 0; }
  // Would a hit at distance t on primitive id replace this one?
  bool improved_by(float t_new, std::int32_t id) const { return t_new < t || (t_new == t && id < prim); }
  // Takes the hit at t_new on primitive id if it improves this one.
  void offer(float t_new, std::int32_t id, float b1_new = 0, float b2_new = 0) {
    if (!improved_by(t_new, id)) return;
    t = t_new, prim = id, b1 = b1_new, b2 = b2_new;
  }
};

}  // namespace gcsim::geometry
