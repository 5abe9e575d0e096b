#pragma once
// The participating media of a scene as the unified renderer holds them: each medium is the inside
// of a box or a sphere. A bound whose material only bounds it (index 1, nothing reflected or
// emitted: `invisible_boundary`) is no surface and is taken out of what radiosity and the view see;
// a refracting bound (index != 1, nothing else) stays as a dielectric (Fresnel glass of that index),
// as the media paper's objects. Media may nest (the paper's object in its fog): a point belongs to
// the smallest medium that holds it. What the renderer cannot show yet (a bound that also reflects
// or emits, a polygon or mesh bound, partly overlapping media) is refused, naming the scene file.
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
  std::string where{};   // "FILE:LINE: [[sphere]]" (or "FILE: shape N"): the bound's place, for messages
  bool changes_nothing() const;  // sigma_s = sigma_a = 0 in every channel
  // The part [t0, t1] of the ray origin + t direction, t in [t_min, t_max], inside the region.
  bool clip(const glm::dvec3& origin, const glm::dvec3& direction, double t_min, double t_max, double& t0,
            double& t1) const;
  bool contains(const glm::dvec3& p) const;
  bool contains(const MediumRegion& inner) const;  // inner's whole bound lies inside this one's
  double volume() const;
};

// The media along the ray origin + t direction, t in [0, t_max): consecutive intervals, each in the
// one medium that holds it (the smallest where they nest), in order along the ray.
struct MediumInterval {
  std::size_t region;
  double t0, t1;
};
std::vector<MediumInterval> medium_intervals(const std::vector<MediumRegion>& regions, const glm::dvec3& origin,
                                             const glm::dvec3& direction, double t_max);

// exp(-sigma_t length) per channel: what one medium of extinction sigma_t lets through.
glm::dvec3 channel_transmittance(const glm::dvec3& sigma_t, double length);
// The transmittance of the segment origin + t direction (unit), t in [0, length), through the media.
glm::dvec3 segment_transmittance(const std::vector<MediumRegion>& regions, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double length);

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
