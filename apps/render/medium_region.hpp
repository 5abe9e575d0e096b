#pragma once
// The participating media of a scene as the unified renderer holds them: each medium is the inside
// of a box or a sphere whose material only bounds it (index 1, nothing reflected or emitted:
// `invisible_boundary`), so the bounding shape is no surface and is taken out of what radiosity and
// the view see. What the renderer cannot show yet (a refracting boundary, a polygon or mesh boundary,
// overlapping media) is refused with the reason, naming the scene file.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "apps/common/scene/scene_description.hpp"

namespace gcsim::render {

struct MediumRegion {
  std::string material;  // the bounding material's name, for messages
  std::variant<scene::Box, scene::Sphere> shape;
  scene::Medium medium;
  bool changes_nothing() const;  // sigma_s = sigma_a = 0 in every channel
  // The part [t0, t1] of the ray origin + t direction, t in [t_min, t_max], inside the region.
  bool clip(const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max, double& t0,
            double& t1) const;
  bool contains(const glm::dvec3& p) const;
};

struct SplitScene {
  scene::SceneDescription surfaces;  // the description without the media's bounding shapes
  std::vector<MediumRegion> media;
};

// The description without the shapes that only bound a medium (they are no surface).
scene::SceneDescription without_invisible_boundaries(const scene::SceneDescription& d);

// Throws std::invalid_argument "FILE: ..." for media the renderer cannot show.
SplitScene split_media(const scene::SceneDescription& d, const std::string& file);

// Luminance of an RGB triple (Rec. 709 weights, as the media app's [A8]).
double luminance(const scene::Rgb& c);

}  // namespace gcsim::render
