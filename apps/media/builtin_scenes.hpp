#pragma once
// The media renderer's built-in scenes as scene descriptions, registered in the scene catalogue
// (small, exp1, exp1-literal, exp2, fog, exp1-bunny, exp2-bunny): fog filling a box, a closed
// dielectric object filled with a second medium, one light, a pinhole camera and the photon-pass
// settings (SceneDescription::media). lower_media_scene turns each into what the renderer draws.
#include <string>

#include "apps/common/scene/scene_description.hpp"
#include "apps/media/mesh_boundary.hpp"

namespace gcsim::media {

// Which reading of experiment 1's inside σs = (0.8, 0.9, 0.8) [A14]: literally (albedo ≈ 0.017) or as
// the albedo (σs = albedo · σt). Luminance of the RGB triple: 0.2126 R + 0.7152 G + 0.0722 B.
enum class Exp1Reading { literal, albedo };

// The small fast scene for tests and the README: a Schlick sphere in isotropic fog lit by a point light.
scene::SceneDescription small_description();
// The paper's experiments recreated with a dielectric sphere (the scanned model is not named): media
// parameters from the paper; light, camera, k and IOR chosen (unstated in the paper).
scene::SceneDescription experiment1_description(Exp1Reading reading);
scene::SceneDescription experiment2_description();
// Uniformly lit fog: no object, a box of thin fog under a Lambertian disk as wide as the box, so the
// in-scattered radiance varies little along a ray and transmittance sampling is near ideal.
scene::SceneDescription uniform_fog_description();
// The scanned model of the paper's experiments: the Stanford bunny (scenes/meshes/bunny.obj) where the
// sphere of experiments 1 and 2 is, fitted into that sphere (centre (0, −0.3, 0.5), radius 0.9).
inline const MeshPlacement kBunnyPlacement{{0.0, -0.3, 0.5}, 0.9, 180.0};
// Scene d with the bunny, placed, in place of its sphere, named d.name + "-bunny"; the mesh is found
// with find_scene_data (scene_data.hpp), and a missing file is an error naming the paths tried.
scene::SceneDescription with_bunny(scene::SceneDescription d);

}  // namespace gcsim::media
