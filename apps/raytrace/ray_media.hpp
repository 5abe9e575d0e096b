#pragma once
// What participating media do to the rays of a Whitted render: the ray tracer knows surfaces only,
// and asks this interface, when one is given (RenderSettings::media), what happens between a ray's
// origin and the surface it meets. The unified renderer implements it with the media app's photon
// map and distance sampling (apps/render/view_medium.hpp); the ray tracer itself knows no medium.
#include <glm/vec3.hpp>

#include "apps/common/geometry/ray.hpp"
#include "apps/common/rng.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/counters.hpp"

namespace gcsim::raytrace {

class RayMedia {
 public:
  virtual ~RayMedia() = default;
  // The radiance arriving at the ray's origin from [0, t_end) (t_end infinite: the ray left the
  // scene): `behind`, the radiance at t_end, attenuated by the transmittance, plus the light the
  // media scatter into the ray. rng: the pixel's own stream, so the image does not depend on how
  // tiles are spread over nodes. t is in units of the ray's direction vector.
  virtual glm::vec3 along(const Ray& ray, float t_end, glm::vec3 behind, apps::Rng& rng,
                          TraceCounters& counters) const = 0;
  // The fraction of light that crosses [0, t_end) of the ray (shadow rays towards point lights).
  virtual glm::vec3 transmittance(const Ray& ray, float t_end) const = 0;
};

}  // namespace gcsim::raytrace
