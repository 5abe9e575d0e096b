#include "apps/media/radiance_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gcsim::media {

glm::ivec3 radiance_grid_dims(const glm::dvec3& lo, const glm::dvec3& hi, std::size_t photons, std::size_t k,
                              double a) {
  if (k == 0) throw std::invalid_argument("radiance grid: k must be positive");
  const glm::dvec3 w = hi - lo;
  if (!(w.x > 0 && w.y > 0 && w.z > 0)) throw std::invalid_argument("radiance grid: empty box");
  const double n = a * static_cast<double>(photons) / static_cast<double>(k);  // eq. (13)
  const double s = std::cbrt(n / (w.x * w.y * w.z));                           // eq. (12)
  glm::ivec3 dims;
  for (int i = 0; i < 3; ++i) dims[i] = std::max(1, static_cast<int>(std::lround(w[i] * s)));
  return dims;
}

RadianceGrid::RadianceGrid(const UniformGrid& grid, const PhotonMap& map, const HomogeneousMedium& medium,
                           std::size_t k)
    : RadianceGrid(grid, map, medium, k, 0, grid.voxel_count()) {}

RadianceGrid::RadianceGrid(const UniformGrid& grid, const PhotonMap& map, const HomogeneousMedium& medium,
                           std::size_t k, std::size_t first, std::size_t last)
    : grid_(grid), voxels_(grid.voxel_count()) {
  last = std::min(last, voxels_.size());
  for (std::size_t i = first; i < last; ++i) {
    const int x = static_cast<int>(i % grid.dims.x);
    const int y = static_cast<int>((i / grid.dims.x) % grid.dims.y);
    const int z = static_cast<int>(i / (static_cast<std::size_t>(grid.dims.x) * grid.dims.y));
    const glm::dvec3 centre = grid.cell_center({x, y, z});
    const NearestPhotons n = map.nearest(centre, k);
    if (n.radius_squared <= 0.0) continue;
    const double volume = 4.0 / 3.0 * kPi * n.radius_squared * std::sqrt(n.radius_squared);  // dV of eq. (4)
    for (std::uint32_t p : n.indices) {
      const Photon& ph = map.photons()[p];
      sh_add_photon(voxels_[i], medium.phase, medium.sigma_t, ph.power / volume, glm::dvec3(ph.direction));
    }
    photon_adds_ += n.indices.size();
  }
}

double RadianceGrid::eval(const glm::dvec3& x, const ShBasis& y_out) const {
  return sh_reconstruct(voxels_[grid_.linear_index(grid_.cell_of(x))], y_out);
}

RayHistogram RadianceGrid::histogram(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max) const {
  RayHistogram h;
  const ShBasis y = sh_basis(-d);
  for (const VoxelSpan& span : traverse_grid(grid_, o, d, t_min, t_max)) {
    if (h.edges.empty()) h.edges.push_back(span.t0);
    h.edges.push_back(span.t1);
    h.values.push_back(sh_reconstruct(voxels_[grid_.linear_index(span.cell)], y));
  }
  return h;
}

}  // namespace gcsim::media
