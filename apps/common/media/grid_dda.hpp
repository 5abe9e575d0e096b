#pragma once
// 3D-DDA over a uniform grid (Amanatides & Woo 1987; paper section 3.1): the voxels a ray crosses, in
// order, each with the parametric interval [t0, t1) it spends there.
#include <vector>

#include <glm/vec3.hpp>

namespace gcsim::media {

struct UniformGrid {
  glm::dvec3 lo{0.0}, hi{1.0};
  glm::ivec3 dims{1};

  glm::dvec3 cell_size() const { return (hi - lo) / glm::dvec3(dims); }
  std::size_t voxel_count() const {
    return static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) * static_cast<std::size_t>(dims.z);
  }
  std::size_t linear_index(const glm::ivec3& c) const {
    return (static_cast<std::size_t>(c.z) * dims.y + c.y) * dims.x + c.x;
  }
  // The cell holding p, clamped into the grid.
  glm::ivec3 cell_of(const glm::dvec3& p) const;
  glm::dvec3 cell_center(const glm::ivec3& c) const { return lo + (glm::dvec3(c) + 0.5) * cell_size(); }
};

struct VoxelSpan {
  glm::ivec3 cell;
  double t0, t1;
};

// Clips the ray o + t d, t in [t_min, t_max], to the grid box; false when it misses.
bool clip_to_box(const UniformGrid& grid, const glm::dvec3& o, const glm::dvec3& d, double& t_min,
                 double& t_max);

// Every voxel crossed with a span of positive length, in ray order; the spans tile the clipped interval.
std::vector<VoxelSpan> traverse_grid(const UniformGrid& grid, const glm::dvec3& o, const glm::dvec3& d,
                                     double t_min, double t_max);

}  // namespace gcsim::media
