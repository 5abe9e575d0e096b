#pragma once
// The hard rays of a tree's child boxes: at their corners and edges from points all around the
// scene, axis-parallel in their slab planes and, with `inside`, from inside a box along its edge
// and diagonally within a slab plane (one direction component exactly 0).
#include <vector>

#include "apps/common/rng.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace::testing {

// edge_axis: the axis along which the edge ray's target moves from the corner to the edge's middle.
inline std::vector<Ray> box_corner_rays(const geometry::PackedTree& tree, const Bounds3& scene, apps::Rng& rng,
                                        int edge_axis, bool inside) {
  const glm::vec3 c = 0.5f * (scene.lo + scene.hi), reach = 2.0f * (scene.hi - scene.lo);
  std::vector<Ray> rays;
  for (const geometry::PairNode& n : tree.nodes)
    for (int child = 0; child < 2; ++child) {
      const glm::vec3 lo(n.bounds[0][child], n.bounds[1][child], n.bounds[2][child]);
      const glm::vec3 hi(n.bounds[0][2 + child], n.bounds[1][2 + child], n.bounds[2][2 + child]);
      const glm::vec3 corner(rng.uniform() < 0.5f ? lo.x : hi.x, rng.uniform() < 0.5f ? lo.y : hi.y,
                             rng.uniform() < 0.5f ? lo.z : hi.z);
      const glm::vec3 from = c + reach * glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      rays.emplace_back(from, glm::normalize(corner - from));
      glm::vec3 edge = corner;
      edge[edge_axis] = 0.5f * (lo[edge_axis] + hi[edge_axis]);
      rays.emplace_back(from, glm::normalize(edge - from));
      const int axis = int(rng.next_u32() % 3);
      glm::vec3 d(0.0f), o = corner;
      d[axis] = rng.uniform() < 0.5f ? 1.0f : -1.0f;
      o[axis] = c[axis] - d[axis] * reach[axis];  // in the box's other two slab planes
      rays.emplace_back(o, d);
      if (!inside) continue;
      o[axis] = 0.5f * (lo[axis] + hi[axis]);  // from inside the box, along its edge
      rays.emplace_back(o, -d);
      glm::vec3 e(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      e[axis] = 0.0f;
      if (glm::length(e) > 0.1f) rays.emplace_back(corner - reach * e, glm::normalize(e));
    }
  return rays;
}

}  // namespace gcsim::raytrace::testing
