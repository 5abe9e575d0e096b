#pragma once
// A scene as the media renderer draws it: fog in a box (outside medium), a closed dielectric object
// filled with the inside medium, a point light, a pinhole camera, and the photon-pass settings. Built
// only by lower_media_scene (lower_media_scene.hpp) from a scene description: the built-in scenes
// (builtin_scenes.hpp) and scene files come through the scene catalogue.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "apps/common/scene/camera.hpp"
#include "apps/media/boundary.hpp"
#include "apps/media/fresnel.hpp"
#include "apps/common/media/grid_dda.hpp"
#include "apps/common/media/medium.hpp"
#include "apps/media/mesh_boundary.hpp"
#include "apps/common/media/single_scattering.hpp"

namespace gcsim::media {

// The rendered image's size in pixels (the camera, scene::Camera, leaves it to the image).
struct ImageSize {
  int width = 64, height = 48;
};

// A disk light with strongly directional emission (experiment 2): radiance ∝ cos^n θ about `normal`.
struct DirectionalAreaLight {
  glm::dvec3 centre, normal;
  double radius, exponent, power;  // power: total flux Φ (luminance)
};

struct MediaScene {
  std::string name;
  UniformGrid fog_box;  // the outside medium fills this box; photons leaving it are lost
  HomogeneousMedium outside, inside;
  std::shared_ptr<const Boundary> object;  // may be null: fog only
  double ior = kDefaultIor;
  PointLight light;                              // used when area_light is empty
  std::optional<DirectionalAreaLight> area_light;
  scene::Camera camera;  // the scene layer's pinhole camera
  ImageSize image;
  std::size_t photons_emitted = 20000;
  std::size_t k_nearest = 50;
  int max_photon_events = 64;     // scatterings plus surface events per photon
  int max_specular_depth = 6;     // camera-path surface events [notes: "split at Fresnel surfaces to depth 6"]
  std::uint64_t seed = 1;
};

}  // namespace gcsim::media
