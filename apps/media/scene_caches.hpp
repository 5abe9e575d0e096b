#pragma once
// What the photon pass leaves for rendering: a photon map and an SH radiance grid per medium region
// (inside and outside are separate, paper section 3.1), each grid over its photons' bounding box with
// n = a N / k voxels (eqs. 12–13).
#include <memory>

#include "apps/media/media_scene.hpp"
#include "apps/media/photon_tracer.hpp"
#include "apps/common/media/radiance_grid.hpp"

namespace gcsim::media {

struct RegionCache {
  std::shared_ptr<const PhotonMap> map;  // null when no photon was stored; read-only, so nodes may share one
  std::shared_ptr<const RadianceGrid> grid;  // read-only too
};

struct SceneCaches {
  RegionCache outside, inside;
  GridBuildCounts grid_build;  // the work of building both grids
};

// The photon maps and, with_grids, the SH grids (only the radiance, mis and grid estimators need them).
SceneCaches build_caches(const MediaScene& scene, PhotonPassResult photons, bool with_grids = true);

}  // namespace gcsim::media
