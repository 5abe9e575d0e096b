#pragma once
// The one camera every renderer and scene format uses: a pinhole at `eye` looking at `look_at`,
// `up` fixing the roll, `fov_y_degrees` the vertical field of view. Renderers build their ray or
// projection set-up from it (the ray tracer in float, radiosity's Gouraud view and the media
// renderer in double); the image size belongs to the image, not the camera.
#include <glm/glm.hpp>

namespace gcsim::scene {

struct Camera {
  glm::dvec3 eye{0.0, 0.0, 5.0}, look_at{0.0}, up{0.0, 1.0, 0.0};
  double fov_y_degrees = 40.0;
};

}  // namespace gcsim::scene
