#pragma once
// The view pass of the unified renderer: the ray tracer's parallel render (tiles over the nodes,
// pixels to node 0) of the view scene (view_scene.hpp), Whitted-shaded so that mirrors and glass
// are followed. It starts on each node when that node's radiosity pass ends.
#include <memory>
#include <vector>

#include "apps/common/geometry/bvh.hpp"
#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/raytrace/raytrace.hpp"
#include "apps/render/media_pass.hpp"
#include "apps/render/view_medium.hpp"

namespace gcsim::render {

// The view's rays and display. secondary and shadows: the plan's specular and shadows passes (or
// --force-pass).
struct ViewSettings {
  bool secondary = true;  // mirror and glass: reflected and refracted rays
  bool shadows = true;    // towards point and spot lights
  int max_depth = 5;      // reflection and refraction levels
  double exposure = 0;    // radiosity to displayed colour; 0: the Gouraud display's automatic one
  // false: the radiosity pass was forced on (--force-pass radiosity) where the plan skips it, so the
  // view shows the plan's scene without it (the run checks that the pass found no reflected light).
  bool shows_radiosity = true;
  int host_threads = 1;  // above 1: workers render the view's tiles ahead (raytrace/tile_prefetch.hpp)
};

struct ViewPass {
  raytrace::Scene scene;
  geometry::Bvh bvh;
  raytrace::RenderSettings settings;
  std::unique_ptr<raytrace::ParallelRenderJob> job;
  raytrace::ParallelRender result;  // node 0 assembles the image; per-node counters
  double exposure = 1.0;            // radiosity to displayed colour (the Gouraud display's automatic one)
  std::unique_ptr<ViewMedium> medium;  // the media every ray crosses (settings.media), or null
  std::unique_ptr<raytrace::TilePrefetch> prefetch;  // view.host_threads > 1: tiles rendered ahead
};

// With a radiosity solution (mesh and one radiosity per element): its elements lit by it; without
// (mesh == nullptr): the lowered scene lit by its point lights. Image size from the description,
// which holds no medium's bounding shape (split_media). With media: their regions and the photon
// pass's photons (empty lists without one) make the view's ViewMedium.
std::unique_ptr<ViewPass> make_view_pass(const scene::SceneDescription& description, const radiosity::Scene* mesh,
                                         const std::vector<radiosity::Rgb>* element_radiosity, ViewSettings view, int nodes,
                                         const MediaSetup* media = nullptr,
                                         std::vector<std::vector<media::Photon>> photons = {});

}  // namespace gcsim::render
