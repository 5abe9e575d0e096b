#pragma once
// Pencil bounding volumes for secondary rays (section 2.3). The reflected (or refracted) rays of
// a subregion's four corner pixels stand for the whole bundle. In a ray frame whose z axis is the
// mean of their directions (the axis ray) and whose origin puts the nearest start point at z = 0,
// each corner ray meets z = 0 at r_i and has slopes s_i = (dx/dz, dy/dz). With the extremes of
// r_i and the largest |s_i| the paraxial pencil is bounded by four planes:
//     x + s_xmax z = r_xmin,   x - s_xmax z = r_xmax,
//     y + s_ymax z = r_ymin,   y - s_ymax z = r_ymax,
// i.e. the region r_xmin - s_xmax z <= x <= r_xmax + s_xmax z (and likewise in y), which holds
// every ray that crosses z = 0 inside [r_min, r_max] with slopes no steeper than s_max.
// A subtree is built from these planes as from a pyramid (2.2.1); a secondary ray of the
// subregion that lies entirely inside the pencil is traced in that subtree, any other ray in the
// whole tree, so every ray still finds its nearest hit.
#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "apps/raytrace/camera.hpp"
#include "apps/common/geometry/ray.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/subtree.hpp"

namespace gcsim::raytrace {

struct Pencil {
  glm::vec3 origin{0.0f};  // ray frame origin
  glm::vec3 axis{0.0f}, x_axis{0.0f}, y_axis{0.0f};
  float rx_min = 0, rx_max = 0, ry_min = 0, ry_max = 0;
  float sx_max = 0, sy_max = 0;
  Subtree subtree;

  std::array<Plane, 4> planes() const;
  // The whole ray (from its origin on) stays inside the four planes.
  bool contains(const Ray& ray) const;
};

// Empty when a corner ray does not go forward along the axis ray (the bundle is too wide for the
// paraxial picture to mean anything).
std::optional<Pencil> make_pencil(const std::array<Ray, 4>& corner_rays);

}  // namespace gcsim::raytrace
