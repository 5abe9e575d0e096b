#include "apps/media/builtin_scenes.hpp"

#include <glm/geometric.hpp>

#include "apps/common/scene/obj_mesh.hpp"
#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/media/fresnel.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/media/scene_data.hpp"

namespace gcsim::media {
namespace {

// A grey medium of extinction sigma_t and scattering sigma_s (σa = σt − σs, which lowering adds
// back to exactly σt for every scene here).
scene::Medium grey_medium(double sigma_t, double sigma_s, scene::PhaseKind phase, double g, double ior) {
  return {scene::Rgb(sigma_s), scene::Rgb(sigma_t - sigma_s), phase, g, ior};
}
scene::Medium isotropic(double sigma_t, double sigma_s) { return grey_medium(sigma_t, sigma_s, scene::PhaseKind::isotropic, 0.0, 1.0); }
scene::Medium schlick(double sigma_t, double sigma_s, double k) {
  return grey_medium(sigma_t, sigma_s, scene::PhaseKind::schlick, k, kDefaultIor);
}

// Media only: the materials reflect nothing (the unified renderer then skips radiosity).
int add_medium(scene::SceneDescription& d, const char* name, const scene::Medium& m) {
  return d.add_material({.name = name, .diffuse = scene::Rgb(0.0), .medium = m});
}

// The fog filling [lo, hi] and, when given, a sphere of the inside medium.
scene::SceneDescription fog_scene(const char* name, glm::dvec3 lo, glm::dvec3 hi, const scene::Medium& fog) {
  scene::SceneDescription d;
  d.name = name;
  d.image.background = d.image.ambient = scene::Rgb(0.0);
  d.shapes.push_back({.geometry = scene::Box{lo, hi}, .material = add_medium(d, "fog", fog)});
  return d;
}
void add_sphere(scene::SceneDescription& d, const scene::Medium& inside, glm::dvec3 centre, double radius) {
  d.shapes.push_back({.geometry = scene::Sphere{centre, radius}, .material = add_medium(d, "inside", inside)});
}

constexpr double kLuminanceOfExp1Sigma = 0.2126 * 0.8 + 0.7152 * 0.9 + 0.0722 * 0.8;  // 0.87152

}  // namespace

scene::SceneDescription small_description() {
  scene::SceneDescription d = fog_scene("small", {-2, -1.5, -2}, {2, 1.5, 2}, isotropic(1.0, 0.3));  // experiment 1's outside
  add_sphere(d, schlick(8.0, 6.4, 0.5), {0.0, -0.2, 0.3}, 0.8);  // a thinner, bright version of its inside
  d.lights.push_back(scene::PointLight{{-0.9, 0.8, -0.5}, scene::Rgb(1.0)});  // out of the frame, lighting the side the camera sees
  d.camera = scene::Camera{{0, 0.1, -1.4}, {0, -0.1, 0.3}, {0, 1, 0}, 70.0};
  d.image.width = 192, d.image.height = 144;  // big enough to look at; a couple of seconds of host time on 16 nodes
  d.media = scene::MediaSettings{};
  return d;
}

scene::SceneDescription experiment1_description(Exp1Reading reading) {
  const bool albedo = reading == Exp1Reading::albedo;
  scene::SceneDescription d = fog_scene(albedo ? "exp1" : "exp1-literal", {-3, -2, -3}, {3, 2, 4}, isotropic(1.0, 0.3));
  add_sphere(d, schlick(50.0, albedo ? kLuminanceOfExp1Sigma * 50.0 : kLuminanceOfExp1Sigma, 0.5), {0.0, -0.3, 0.5}, 0.9);
  // Above, left and a little in front of the object (out of the frame), so the camera sees its lit
  // side: the object is optically thick (σt = 50 per unit, radius 0.9), so its glow is light scattered
  // just below that side. The camera stands one mean free path of fog away from it.
  d.lights.push_back(scene::PointLight{{-0.9, 0.9, -0.3}, scene::Rgb(1.0)});
  d.camera = scene::Camera{{0, 0.1, -1.3}, {0, -0.2, 0.5}, {0, 1, 0}, 70.0};
  d.image.width = 640, d.image.height = 480;
  d.media = scene::MediaSettings{.photons_emitted = 100000, .k_nearest = 100};
  return d;
}

scene::SceneDescription experiment2_description() {
  scene::SceneDescription d = fog_scene("exp2", {-3, -2, -3}, {3, 2, 4}, isotropic(1.0, 1.0));
  add_sphere(d, schlick(200.0, 120.0, 0.6), {0.0, -0.3, 0.5}, 0.9);
  // A disk above, left of and in front of the object aimed at it: emission ∝ cos^50 (half power at
  // 9.5° off axis), a beam about as wide as the object by the time it gets there.
  const glm::dvec3 centre(-1.0, 1.1, -0.5), target(0.0, -0.3, 0.5);
  d.lights.push_back(scene::DiskLight{centre, glm::normalize(target - centre), 0.5, 50.0, scene::Rgb(40.0)});
  d.camera = scene::Camera{{0, 0.1, -1.3}, {0, -0.2, 0.5}, {0, 1, 0}, 70.0};
  d.image.width = 640, d.image.height = 480;
  // The outside albedo is 1, so a photon scatters until it leaves the box (about 5 times here): we
  // read the paper's 10^5 photons as stored ones, as experiment 1's 10^5 emitted nearly are.
  d.media = scene::MediaSettings{.photons_emitted = 20000, .k_nearest = 100};
  return d;
}

scene::SceneDescription uniform_fog_description() {
  scene::SceneDescription d = fog_scene("fog", {-2, -1.5, -2}, {2, 1.5, 2}, isotropic(0.5, 0.4));
  // A Lambertian disk as wide as the box above it (exponent 1: radiance constant over directions).
  d.lights.push_back(scene::DiskLight{{0.0, 1.49, 0.0}, {0.0, -1.0, 0.0}, 2.0, 1.0, scene::Rgb(20.0)});
  d.camera = scene::Camera{{0, 0, -1.95}, {0, 0, 0}, {0, 1, 0}, 50.0};
  d.image.width = 128, d.image.height = 96;
  d.media = scene::MediaSettings{.photons_emitted = 50000, .k_nearest = 100};
  return d;
}

scene::SceneDescription with_bunny(scene::SceneDescription d) {
  d.name += "-bunny";
  for (scene::Shape& s : d.shapes)
    if (std::holds_alternative<scene::Sphere>(s.geometry))
      s.geometry = scene::Mesh{place_mesh(scene::load_obj_mesh(find_scene_data("meshes/bunny.obj")), kBunnyPlacement), {}};
  return d;
}

// Defined here, beside the registrars, so that whatever loads a media scene links them.
MediaScene load_media_scene(const std::string& name_or_path) { return lower_media_scene(scene::load_scene(name_or_path)); }

namespace {

using scene::BuiltinSceneRegistrar;
const BuiltinSceneRegistrar kSmall({"small", "media", small_description});
const BuiltinSceneRegistrar kExp1({"exp1", "media", [] { return experiment1_description(Exp1Reading::albedo); }});
const BuiltinSceneRegistrar kExp1Literal({"exp1-literal", "media", [] { return experiment1_description(Exp1Reading::literal); }});
const BuiltinSceneRegistrar kExp2({"exp2", "media", experiment2_description});
const BuiltinSceneRegistrar kFog({"fog", "media", uniform_fog_description});
const BuiltinSceneRegistrar kExp1Bunny({"exp1-bunny", "media", [] { return with_bunny(experiment1_description(Exp1Reading::albedo)); }});
const BuiltinSceneRegistrar kExp2Bunny({"exp2-bunny", "media", [] { return with_bunny(experiment2_description()); }});

}  // namespace

}  // namespace gcsim::media
