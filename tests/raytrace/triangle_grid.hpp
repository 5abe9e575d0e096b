#pragma once
// The unit square in the z = 0 plane cut into n x n quads of two triangles each, sharing every
// vertex and edge with their neighbours: the hard case of watertight ray-triangle tests.
#include <vector>

#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace::testing {

inline std::vector<Triangle> unit_square_grid(int n) {
  std::vector<Triangle> tris;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::vec3 p00(x / float(n), y / float(n), 0), p10((x + 1) / float(n), y / float(n), 0);
      const glm::vec3 p01(x / float(n), (y + 1) / float(n), 0), p11((x + 1) / float(n), (y + 1) / float(n), 0);
      tris.push_back({p00, p10, p11});
      tris.push_back({p00, p11, p01});
    }
  return tris;
}

}  // namespace gcsim::raytrace::testing
