#pragma once
// What a render does: which primary-ray algorithm, subregion size, image size and shading.
#include <cstdint>
#include <string>
#include <string_view>

#include "apps/raytrace/algorithm.hpp"

namespace gcsim::raytrace {

class RayMedia;

enum class Shading {
  local,    // primary rays only: Lambert and Phong from the lights, no shadows (the paper's table)
  whitted,  // shadow rays, mirror reflection and refraction with Fresnel, recursively
};

struct RenderSettings {
  Algorithm algorithm = Algorithm::A4;
  int tile = 8;            // subregion size m (m x m pixels)
  int width = 512;
  int height = 512;
  Shading shading = Shading::local;
  bool pencils = true;     // whitted: first-generation secondary rays through pencil subtrees (2.3)
  int max_depth = 5;       // whitted: reflection/refraction levels
  // whitted: which of its rays are cast at all (the unified renderer turns off what the scene's
  // plan says cannot contribute: a scene without mirrors or glass, or nothing that can shadow).
  bool shadow_rays = true;
  bool secondary_rays = true;
  // whitted: the participating media every ray segment crosses (null: none). Not owned.
  const RayMedia* media = nullptr;
  std::uint64_t media_seed = 1;  // the pixels' random streams for the media's distance samples
};

}  // namespace gcsim::raytrace
