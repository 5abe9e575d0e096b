#include "apps/common/media/grid_dda.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gcsim::media {

glm::ivec3 UniformGrid::cell_of(const glm::dvec3& p) const {
  const glm::dvec3 rel = (p - lo) / cell_size();
  glm::ivec3 c;
  for (int a = 0; a < 3; ++a)
    c[a] = std::clamp(static_cast<int>(std::floor(rel[a])), 0, dims[a] - 1);
  return c;
}

bool clip_to_box(const UniformGrid& grid, const glm::dvec3& o, const glm::dvec3& d, double& t_min,
                 double& t_max) {
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {  // parallel to the slab: inside (faces included) or a miss
      if (o[a] < grid.lo[a] || o[a] > grid.hi[a]) return false;
      continue;
    }
    double t_near = (grid.lo[a] - o[a]) / d[a], t_far = (grid.hi[a] - o[a]) / d[a];
    if (t_near > t_far) std::swap(t_near, t_far);
    t_min = std::max(t_min, t_near);
    t_max = std::min(t_max, t_far);
  }
  return t_min < t_max;
}

std::vector<VoxelSpan> traverse_grid(const UniformGrid& grid, const glm::dvec3& o, const glm::dvec3& d,
                                     double t_min, double t_max) {
  std::vector<VoxelSpan> spans;
  if (!clip_to_box(grid, o, d, t_min, t_max)) return spans;
  const double inf = std::numeric_limits<double>::infinity();
  const glm::dvec3 size = grid.cell_size();
  // The entry cell from the midpoint of the first step is safer than the entry point itself, but the
  // entry point with clamping and zero-length spans skipped is exact and simpler.
  glm::ivec3 cell = grid.cell_of(o + t_min * d);
  glm::ivec3 step;
  glm::dvec3 t_next, t_delta;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      step[a] = 0, t_next[a] = inf, t_delta[a] = inf;
      continue;
    }
    step[a] = d[a] > 0.0 ? 1 : -1;
    const double boundary = grid.lo[a] + (cell[a] + (d[a] > 0.0 ? 1 : 0)) * size[a];
    t_next[a] = (boundary - o[a]) / d[a];
    t_delta[a] = size[a] / std::abs(d[a]);
  }
  double t = t_min;
  while (t < t_max) {
    int axis = 0;
    if (t_next[1] < t_next[axis]) axis = 1;
    if (t_next[2] < t_next[axis]) axis = 2;
    const double t_exit = std::min(t_next[axis], t_max);
    if (t_exit > t) spans.push_back({cell, t, t_exit});
    t = std::max(t, t_exit);
    if (t >= t_max) break;
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= grid.dims[axis]) break;
    t_next[axis] += t_delta[axis];
  }
  // Rounding can stop the walk a hair before t_max: extend the last span to the exit.
  if (!spans.empty()) spans.back().t1 = std::max(spans.back().t1, t_max);
  return spans;
}

}  // namespace gcsim::media
