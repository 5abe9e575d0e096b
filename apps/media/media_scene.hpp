#pragma once
// A scene of the media renderer: fog in a box (outside medium), a closed dielectric object filled with
// the inside medium, a point light, a pinhole camera, and the photon-pass settings.
#include <cstdint>
#include <memory>
#include <string>

#include "apps/media/boundary.hpp"
#include "apps/media/fresnel.hpp"
#include "apps/media/grid_dda.hpp"
#include "apps/media/medium.hpp"
#include "apps/media/single_scattering.hpp"

namespace gcsim::media {

struct PinholeCamera {
  glm::dvec3 eye{0, 0, -3}, look_at{0, 0, 0}, up{0, 1, 0};
  double vertical_fov_degrees = 40.0;
  int width = 64, height = 48;
};

struct MediaScene {
  std::string name;
  UniformGrid fog_box;  // the outside medium fills this box; photons leaving it are lost
  HomogeneousMedium outside, inside;
  std::shared_ptr<const Boundary> object;  // may be null: fog only
  double ior = kDefaultIor;
  PointLight light;
  PinholeCamera camera;
  std::size_t photons_emitted = 20000;
  std::size_t k_nearest = 50;
  int max_photon_events = 64;     // scatterings plus surface events per photon
  int max_specular_depth = 6;     // camera-path surface events [notes: "split at Fresnel surfaces to depth 6"]
  std::uint64_t seed = 1;
};

// The small fast scene for tests and the README: a Schlick sphere in isotropic fog lit by a point light.
MediaScene small_scene();

}  // namespace gcsim::media
