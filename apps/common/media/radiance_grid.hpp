#pragma once
// The incident-radiance grid of section 3.1–3.2: a uniform grid over a box whose voxel centres store
// the SH coefficients (16, luminance [A8]) of the k-NN estimate (4) via Funk–Hecke (eqs. 23–30).
// Its size is n = a·N/k voxels (eq. 13), split as s = (n / (w_x w_y w_z))^{1/3}, n_i = w_i s (eq. 12).
// Along a ray it gives the piecewise-constant histogram h of eqs. (17–20).
#include <cstdint>
#include <vector>

#include "apps/common/media/grid_dda.hpp"
#include "apps/common/media/medium.hpp"
#include "apps/common/media/photon_map.hpp"
#include "apps/common/media/spherical_harmonics.hpp"

namespace gcsim::media {

inline constexpr double kPaperVoxelsPerPhotonSphere = 125.0;  // a of eq. (13)

// Grid dimensions for n = a N / k voxels over the box [lo, hi] (eqs. 12–13), each at least 1.
glm::ivec3 radiance_grid_dims(const glm::dvec3& lo, const glm::dvec3& hi, std::size_t photons, std::size_t k,
                              double a = kPaperVoxelsPerPhotonSphere);

// The grid geometry for a photon set: its bounding box (slightly padded) and eq. (12–13) dimensions.
UniformGrid grid_for_photons(const std::vector<Photon>& photons, std::size_t k);

struct RayHistogram {
  std::vector<double> edges;   // t_1 < ... < t_{n+1}: the ray's voxel boundaries
  std::vector<double> values;  // h_i = Σ f_lm Y_lm(−d) of the voxel crossed on [t_i, t_{i+1})
};

// What building (a slice of) the grid did, for the cost model. A voxel that starts a row of the slice
// takes a k-NN descent; the next one along x takes a radius search bounded by its neighbour's r_k plus
// the voxel width, which holds all its k nearest (triangle inequality), and a linear selection. Each
// photon's SH vector (eqs. 23–30) is projected once and accumulated into every voxel that counts it.
struct GridBuildCounts {
  std::uint64_t knn_queries = 0, knn_photons = 0;         // k-NN descents and the photons they return
  std::uint64_t range_queries = 0, range_candidates = 0;  // bounded radius searches and what they return
  std::uint64_t projections = 0;                          // photons projected onto the 16 SH coefficients
  std::uint64_t photon_adds = 0;                          // (voxel, photon) accumulations of 16 coefficients
  std::uint64_t voxels() const { return knn_queries + range_queries; }
  void add(const GridBuildCounts& o) {
    knn_queries += o.knn_queries, knn_photons += o.knn_photons, range_queries += o.range_queries;
    range_candidates += o.range_candidates, projections += o.projections, photon_adds += o.photon_adds;
  }
};

// The voxels [first, last) of the grid in linear order (one node's share, or all of them), each the SH
// projection of the k-NN estimate at its centre; adds the work done to `counts`. jobs > 1: on that
// many host threads, the range cut at row starts and joined in order, so the voxels and the counts
// are the same byte for byte as on one.
std::vector<ShCoefficients> build_voxel_range(const UniformGrid& grid, const PhotonMap& map,
                                              const HomogeneousMedium& medium, std::size_t k, std::size_t first,
                                              std::size_t last, GridBuildCounts& counts, int jobs = 1);
inline constexpr std::size_t kGridChunksPerThread = 4;  // pieces per host thread, for balance

class RadianceGrid {
 public:
  // Builds every voxel from the photon map (the k nearest photons of each voxel centre); counts the work.
  RadianceGrid(const UniformGrid& grid, const PhotonMap& map, const HomogeneousMedium& medium, std::size_t k,
               int jobs = 1);
  // Built elsewhere (the voxels of a parallel build, gathered): grid.voxel_count() of them.
  RadianceGrid(const UniformGrid& grid, std::vector<ShCoefficients> voxels) : grid_(grid), voxels_(std::move(voxels)) {}

  const UniformGrid& grid() const { return grid_; }
  const ShCoefficients& voxel(std::size_t i) const { return voxels_[i]; }
  std::vector<ShCoefficients>& voxels() { return voxels_; }
  const std::vector<ShCoefficients>& voxels() const { return voxels_; }
  const GridBuildCounts& build_counts() const { return counts_; }

  // Li(x, ω_o) from the voxel holding x (no interpolation, as in the paper).
  double eval(const glm::dvec3& x, const ShBasis& y_out) const;
  // h along o + t d over [t_min, t_max] with the basis of ω_o = −d evaluated once per ray.
  RayHistogram histogram(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max) const;

 private:
  UniformGrid grid_;
  std::vector<ShCoefficients> voxels_;
  GridBuildCounts counts_;
};

}  // namespace gcsim::media
