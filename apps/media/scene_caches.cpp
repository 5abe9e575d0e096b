#include "apps/media/scene_caches.hpp"

#include <algorithm>

namespace gcsim::media {

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

RegionCache build_region(std::vector<Photon> photons, const HomogeneousMedium& medium, std::size_t k,
                         bool with_grid, SceneCaches& totals) {
  RegionCache region;
  if (photons.empty()) return region;
  const UniformGrid grid = grid_for_photons(photons, k);
  region.map = std::make_unique<PhotonMap>(std::move(photons));
  if (!with_grid) return region;
  region.grid = std::make_unique<RadianceGrid>(grid, *region.map, medium, k);
  totals.grid_build.add(region.grid->build_counts());
  return region;
}

}  // namespace

SceneCaches build_caches(const MediaScene& scene, PhotonPassResult photons, bool with_grids) {
  SceneCaches caches;
  caches.outside = build_region(std::move(photons.outside), scene.outside, scene.k_nearest, with_grids, caches);
  caches.inside = build_region(std::move(photons.inside), scene.inside, scene.k_nearest, with_grids, caches);
  return caches;
}

}  // namespace gcsim::media
