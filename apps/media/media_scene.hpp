#pragma once
// A scene of the media renderer: fog in a box (outside medium), a closed dielectric object filled with
// the inside medium, a point light, a pinhole camera, and the photon-pass settings.
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

// Which reading of experiment 1's inside σs = (0.8, 0.9, 0.8) [A14]: literally (albedo ≈ 0.017) or as
// the albedo (σs = albedo · σt). Luminance of the RGB triple: 0.2126 R + 0.7152 G + 0.0722 B.
enum class Exp1Reading { literal, albedo };

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

// The small fast scene for tests and the README: a Schlick sphere in isotropic fog lit by a point light.
MediaScene small_scene();
// The paper's experiments recreated with a dielectric sphere (the scanned model is not named): media
// parameters from the paper; light, camera, k and IOR chosen (unstated in the paper).
MediaScene experiment1_scene(Exp1Reading reading);
MediaScene experiment2_scene();
// Uniformly lit fog: no object, a box of thin fog under a Lambertian disk as wide as the
// box, so the in-scattered radiance varies little along a ray and transmittance sampling is near ideal.
MediaScene uniform_fog_scene();
// The scanned model of the paper's experiments: the Stanford bunny (scenes/meshes/bunny.obj) where the
// sphere of experiments 1 and 2 is, fitted into that sphere (centre (0, −0.3, 0.5), radius 0.9).
inline const MeshPlacement kBunnyPlacement{{0.0, -0.3, 0.5}, 0.9, 180.0};
// Scene s with the bunny in place of its object, named s.name + "-bunny"; the mesh is found with
// find_scene_data (scene_data.hpp), and a missing file is an error naming the paths tried.
MediaScene with_bunny(MediaScene s);
// "small", "exp1" (albedo reading), "exp1-literal", "exp2", "fog", "exp1-bunny", "exp2-bunny"; throws
// naming the choices otherwise.
MediaScene scene_by_name(const std::string& name);

}  // namespace gcsim::media
