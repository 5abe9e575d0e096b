#pragma once
// The ray-marching renderer (paper section 3): camera paths through the outside fog and, via Fresnel
// reflection/refraction chosen by Russian roulette, through the object; each homogeneous segment is
// one call of march_segment_in_scatter. The camera ray goes through the pixel centre and splits at
// every Fresnel surface into its reflected and refracted branches (to max_specular_depth, while a
// branch weighs at least kMinBranchWeight), so only the distance samples are random. Pixel p draws from
// its own random stream (seed, p), so the image does not depend on how pixels are split over tiles or nodes.
#include <cstdint>

#include "apps/common/image.hpp"
#include "apps/media/boundary.hpp"
#include "apps/media/scene_caches.hpp"
#include "apps/common/media/segment_march.hpp"

namespace gcsim::media {

inline constexpr double kMinBranchWeight = 1e-3;

struct RenderCounters {
  MarchCounters march;
  std::uint64_t surface_events = 0, pixels = 0;
  BoundaryTally boundary;  // a mesh object's tree nodes and triangles tested
  // What the parallel program charged (a host render builds no grid and charges nothing): its share of
  // the SH grids, and the simulated compute seconds of the grids and of the tiles.
  GridBuildCounts grid_build;
  double grid_seconds = 0.0, tile_seconds = 0.0;
  void add(const RenderCounters& o) {
    march.add(o.march), surface_events += o.surface_events, pixels += o.pixels, boundary.add(o.boundary);
    grid_build.add(o.grid_build), grid_seconds += o.grid_seconds, tile_seconds += o.tile_seconds;
  }
};

// Radiance (luminance) of pixel (x, y), row 0 at the top.
double render_pixel(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                    std::uint64_t seed, int x, int y, RenderCounters& counters);

// Rows [y0, y1) of the image into `image` (already sized).
void render_rows(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                 std::uint64_t seed, int y0, int y1, apps::Image& image, RenderCounters& counters);

}  // namespace gcsim::media
