#include "apps/media/scene_caches.hpp"

#include <algorithm>

namespace gcsim::media {

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
