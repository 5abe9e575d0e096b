#include "apps/media/media_scene.hpp"

#include <stdexcept>

#include <glm/geometric.hpp>

#include "apps/media/mesh_boundary.hpp"
#include "apps/media/scene_data.hpp"

namespace gcsim::media {

MediaScene small_scene() {
  MediaScene s;
  s.name = "small";
  s.fog_box = {{-2, -1.5, -2}, {2, 1.5, 2}, {1, 1, 1}};
  s.outside = {1.0, 0.3, 0.0, Phase::isotropic()};          // experiment 1's outside medium
  s.inside = {8.0, 6.4, 0.0, Phase::schlick(0.5)};         // a thinner, bright version of its inside
  s.object = std::make_shared<SphereBoundary>(glm::dvec3(0.0, -0.2, 0.3), 0.8);
  s.light = {{-0.9, 0.8, -0.5}, 1.0};  // out of the frame, lighting the side the camera sees
  s.camera = {{0, 0.1, -1.4}, {0, -0.1, 0.3}, {0, 1, 0}, 70.0};
  s.image = {192, 144};  // big enough to look at; a couple of seconds of host time on 16 nodes
  return s;
}

namespace {
constexpr double kLuminanceOfExp1Sigma = 0.2126 * 0.8 + 0.7152 * 0.9 + 0.0722 * 0.8;  // 0.87152
}

MediaScene experiment1_scene(Exp1Reading reading) {
  MediaScene s;
  s.name = reading == Exp1Reading::albedo ? "exp1" : "exp1-literal";
  s.fog_box = {{-3, -2, -3}, {3, 2, 4}, {1, 1, 1}};
  s.outside = {1.0, 0.3, 0.0, Phase::isotropic()};
  const double sigma_s = reading == Exp1Reading::albedo ? kLuminanceOfExp1Sigma * 50.0 : kLuminanceOfExp1Sigma;
  s.inside = {50.0, sigma_s, 0.0, Phase::schlick(0.5)};
  s.object = std::make_shared<SphereBoundary>(glm::dvec3(0.0, -0.3, 0.5), 0.9);
  // Above, left and a little in front of the object (out of the frame), so the camera sees its lit
  // side: the object is optically thick (σt = 50 per unit, radius 0.9), so its glow is light scattered
  // just below that side. The camera stands one mean free path of fog away from it.
  s.light = {{-0.9, 0.9, -0.3}, 1.0};
  s.camera = {{0, 0.1, -1.3}, {0, -0.2, 0.5}, {0, 1, 0}, 70.0};
  s.image = {640, 480};
  s.photons_emitted = 100000;
  s.k_nearest = 100;
  return s;
}

MediaScene experiment2_scene() {
  MediaScene s;
  s.name = "exp2";
  s.fog_box = {{-3, -2, -3}, {3, 2, 4}, {1, 1, 1}};
  s.outside = {1.0, 1.0, 0.0, Phase::isotropic()};
  s.inside = {200.0, 120.0, 0.0, Phase::schlick(0.6)};
  s.object = std::make_shared<SphereBoundary>(glm::dvec3(0.0, -0.3, 0.5), 0.9);
  // A disk above, left of and in front of the object aimed at it: emission ∝ cos^50 (half power at
  // 9.5° off axis), a beam about as wide as the object by the time it gets there.
  const glm::dvec3 centre(-1.0, 1.1, -0.5), target(0.0, -0.3, 0.5);
  s.area_light = DirectionalAreaLight{centre, glm::normalize(target - centre), 0.5, 50.0, 40.0};
  s.camera = {{0, 0.1, -1.3}, {0, -0.2, 0.5}, {0, 1, 0}, 70.0};
  s.image = {640, 480};
  // The outside albedo is 1, so a photon scatters until it leaves the box (about 5 times here): we
  // read the paper's 10^5 photons as stored ones, as experiment 1's 10^5 emitted nearly are.
  s.photons_emitted = 20000;
  s.k_nearest = 100;
  return s;
}

MediaScene uniform_fog_scene() {
  MediaScene s;
  s.name = "fog";
  s.fog_box = {{-2, -1.5, -2}, {2, 1.5, 2}, {1, 1, 1}};
  s.outside = {0.5, 0.4, 0.0, Phase::isotropic()};
  // A Lambertian disk as wide as the box above it (exponent 1: radiance constant over directions).
  s.area_light = DirectionalAreaLight{{0.0, 1.49, 0.0}, {0.0, -1.0, 0.0}, 2.0, 1.0, 20.0};
  s.camera = {{0, 0, -1.95}, {0, 0, 0}, {0, 1, 0}, 50.0};
  s.image = {128, 96};
  s.photons_emitted = 50000;
  s.k_nearest = 100;
  return s;
}

MediaScene with_bunny(MediaScene s) {
  s.name += "-bunny";
  s.object = load_mesh_boundary(find_scene_data("meshes/bunny.obj"), kBunnyPlacement);
  return s;
}

MediaScene scene_by_name(const std::string& name) {
  if (name == "small") return small_scene();
  if (name == "exp1") return experiment1_scene(Exp1Reading::albedo);
  if (name == "exp1-literal") return experiment1_scene(Exp1Reading::literal);
  if (name == "exp2") return experiment2_scene();
  if (name == "fog") return uniform_fog_scene();
  if (name == "exp1-bunny") return with_bunny(experiment1_scene(Exp1Reading::albedo));
  if (name == "exp2-bunny") return with_bunny(experiment2_scene());
  throw std::invalid_argument("media scene '" + name +
                              "': expected small, exp1, exp1-literal, exp2, fog, exp1-bunny or exp2-bunny");
}

}  // namespace gcsim::media
