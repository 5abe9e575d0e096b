#include "apps/common/media/radiance_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>

#include <glm/common.hpp>

#include "apps/common/ordered_parallel.hpp"

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

UniformGrid grid_for_photons(const std::vector<Photon>& photons, std::size_t k) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const Photon& p : photons) {
    lo = glm::min(lo, glm::dvec3(p.position));
    hi = glm::max(hi, glm::dvec3(p.position));
  }
  const glm::dvec3 pad = 1e-6 * glm::max(hi - lo, glm::dvec3(1.0));
  lo -= pad, hi += pad;
  return {lo, hi, radiance_grid_dims(lo, hi, photons.size(), k)};
}

namespace {

// Voxels [first, last) on one thread, with its own cache of projected photons; `used` marks the
// photons it projected, so that a split range counts each photon once, as one range does.
std::vector<ShCoefficients> build_voxel_chunk(const UniformGrid& grid, const PhotonMap& map,
                                              const HomogeneousMedium& medium, std::size_t k, std::size_t first,
                                              std::size_t last, GridBuildCounts& counts, std::vector<std::uint8_t>& used) {
  std::vector<ShCoefficients> voxels(last > first ? last - first : 0);
  const std::vector<Photon>& photons = map.photons();
  // ΔΦ_p w'_l Y_lm(ω_p) / σt per photon, made on first use: a voxel then adds 16 products per photon.
  // Left uninitialized (`used` says which are made): a chunk touches only its voxels' photons, so
  // zeroing one projection per photon of the map for every chunk was mostly wasted.
  const std::unique_ptr<ShCoefficients[]> projected(new ShCoefficients[photons.size()]);
  used.assign(photons.size(), 0);
  const double voxel_width = grid.cell_size().x;
  double previous_radius = -1.0;  // r_k of the voxel before along x, or < 0: none
  for (std::size_t i = first; i < last; ++i) {
    const int x = static_cast<int>(i % grid.dims.x);
    const int y = static_cast<int>((i / grid.dims.x) % grid.dims.y);
    const int z = static_cast<int>(i / (static_cast<std::size_t>(grid.dims.x) * grid.dims.y));
    const glm::dvec3 centre = grid.cell_center({x, y, z});
    NearestPhotons n;
    if (x > 0 && i > first && previous_radius > 0.0) {
      std::size_t candidates = 0;
      n = map.nearest_within(centre, k, previous_radius + voxel_width, candidates);
      ++counts.range_queries, counts.range_candidates += candidates;
    } else {
      n = map.nearest(centre, k);
      ++counts.knn_queries, counts.knn_photons += n.indices.size();
    }
    previous_radius = n.radius_squared > 0.0 ? std::sqrt(n.radius_squared) : -1.0;
    if (n.radius_squared <= 0.0) continue;
    const double volume = 4.0 / 3.0 * kPi * n.radius_squared * std::sqrt(n.radius_squared);  // dV of eq. (4)
    const float inverse_volume = static_cast<float>(1.0 / volume);
    ShCoefficients& f = voxels[i - first];
    for (std::uint32_t p : n.indices) {
      if (!used[p]) {
        projected[p] = sh_project_photon(medium.phase, medium.sigma_t, photons[p].power, glm::dvec3(photons[p].direction));
        used[p] = 1;
      }
      for (int c = 0; c < kShCoefficients; ++c) f[c] += projected[p][c] * inverse_volume;
    }
    counts.photon_adds += n.indices.size();
  }
  return voxels;
}

// Where the range is cut for `jobs` threads: at row starts only (x = 0), where one thread would
// take a k-NN descent too, so the counted work is the same however the range is cut.
std::vector<std::size_t> chunk_bounds(const UniformGrid& grid, std::size_t first, std::size_t last, int jobs) {
  std::vector<std::size_t> bounds{first};
  const std::size_t row = static_cast<std::size_t>(grid.dims.x);
  const std::size_t chunks = jobs <= 1 ? 1 : std::size_t(jobs) * kGridChunksPerThread;
  for (std::size_t c = 1; c < chunks; ++c) {
    const std::size_t at = (first + (last - first) * c / chunks + row - 1) / row * row;  // the next row start
    if (at > bounds.back() && at < last) bounds.push_back(at);
  }
  bounds.push_back(last);
  return bounds;
}

}  // namespace

std::vector<ShCoefficients> build_voxel_range(const UniformGrid& grid, const PhotonMap& map,
                                              const HomogeneousMedium& medium, std::size_t k, std::size_t first,
                                              std::size_t last, GridBuildCounts& counts, int jobs) {
  last = std::min(last, grid.voxel_count());
  if (last <= first) return {};
  const std::vector<std::size_t> bounds = chunk_bounds(grid, first, last, jobs);
  const int chunks = static_cast<int>(bounds.size()) - 1;
  struct Chunk {
    std::vector<ShCoefficients> voxels;
    GridBuildCounts counts;
    std::vector<std::uint8_t> used;  // bytes, not bits: the merge below runs on the simulation's thread
  };
  std::vector<Chunk> parts(static_cast<std::size_t>(chunks));
  apps::parallel_for(chunks, jobs, [&](int c) {
    Chunk& part = parts[std::size_t(c)];
    part.voxels = build_voxel_chunk(grid, map, medium, k, bounds[std::size_t(c)], bounds[std::size_t(c) + 1],
                                    part.counts, part.used);
  });
  std::vector<ShCoefficients> voxels;
  voxels.reserve(last - first);
  std::vector<std::uint8_t> used(map.photons().size(), 0);
  for (Chunk& part : parts) {  // in range order: the same voxels and counts as one thread's
    voxels.insert(voxels.end(), part.voxels.begin(), part.voxels.end());
    counts.add(part.counts);
    for (std::size_t p = 0; p < used.size(); ++p) used[p] |= part.used[p];
  }
  counts.projections += static_cast<std::uint64_t>(std::count(used.begin(), used.end(), std::uint8_t{1}));
  return voxels;
}

RadianceGrid::RadianceGrid(const UniformGrid& grid, const PhotonMap& map, const HomogeneousMedium& medium,
                           std::size_t k, int jobs)
    : grid_(grid) {
  voxels_ = build_voxel_range(grid, map, medium, k, 0, grid.voxel_count(), counts_, jobs);  // after counts_ is made
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
