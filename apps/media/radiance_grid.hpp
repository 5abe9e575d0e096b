#pragma once
// The incident-radiance grid of section 3.1–3.2: a uniform grid over a box whose voxel centres store
// the SH coefficients (16, luminance [A8]) of the k-NN estimate (4) via Funk–Hecke (eqs. 23–30).
// Its size is n = a·N/k voxels (eq. 13), split as s = (n / (w_x w_y w_z))^{1/3}, n_i = w_i s (eq. 12).
// Along a ray it gives the piecewise-constant histogram h of eqs. (17–20).
#include <cstdint>
#include <vector>

#include "apps/media/grid_dda.hpp"
#include "apps/media/medium.hpp"
#include "apps/media/photon_map.hpp"
#include "apps/media/spherical_harmonics.hpp"

namespace gcsim::media {

inline constexpr double kPaperVoxelsPerPhotonSphere = 125.0;  // a of eq. (13)

// Grid dimensions for n = a N / k voxels over the box [lo, hi] (eqs. 12–13), each at least 1.
glm::ivec3 radiance_grid_dims(const glm::dvec3& lo, const glm::dvec3& hi, std::size_t photons, std::size_t k,
                              double a = kPaperVoxelsPerPhotonSphere);

struct RayHistogram {
  std::vector<double> edges;   // t_1 < ... < t_{n+1}: the ray's voxel boundaries
  std::vector<double> values;  // h_i = Σ f_lm Y_lm(−d) of the voxel crossed on [t_i, t_{i+1})
};

class RadianceGrid {
 public:
  // Builds every voxel from the photon map (one k-NN query per voxel centre); counts the SH photon adds.
  RadianceGrid(const UniformGrid& grid, const PhotonMap& map, const HomogeneousMedium& medium, std::size_t k);
  // The same with only the voxels [first, last) filled (one node's share); the rest stay zero.
  RadianceGrid(const UniformGrid& grid, const PhotonMap& map, const HomogeneousMedium& medium, std::size_t k,
               std::size_t first, std::size_t last);
  explicit RadianceGrid(const UniformGrid& grid) : grid_(grid), voxels_(grid.voxel_count()) {}

  const UniformGrid& grid() const { return grid_; }
  const ShCoefficients& voxel(std::size_t i) const { return voxels_[i]; }
  std::vector<ShCoefficients>& voxels() { return voxels_; }
  std::uint64_t photon_adds() const { return photon_adds_; }

  // Li(x, ω_o) from the voxel holding x (no interpolation, as in the paper).
  double eval(const glm::dvec3& x, const ShBasis& y_out) const;
  // h along o + t d over [t_min, t_max] with the basis of ω_o = −d evaluated once per ray.
  RayHistogram histogram(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max) const;

 private:
  UniformGrid grid_;
  std::vector<ShCoefficients> voxels_;
  std::uint64_t photon_adds_ = 0;
};

}  // namespace gcsim::media
