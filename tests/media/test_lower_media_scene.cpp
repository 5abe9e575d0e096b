// The media renderer's scenes through the one scene catalogue: its built-in descriptions are
// registered there and lower to the figures the paper's experiments state, the bunny lowers to the
// same float triangles as the mesh loaded directly, a scene file with a box of fog renders, and a
// scene the renderer cannot draw is refused with its name and what it lacks.
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/media/builtin_scenes.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/media/scene_data.hpp"

namespace gcsim::media {
namespace {

TEST(MediaBuiltinScenes, AreInTheCatalogueProvidedByTheMediaApp) {
  int found = 0;
  for (const scene::BuiltinScene& s : scene::builtin_scenes()) {
    if (s.provider != "media") continue;
    ++found;
    const MediaScene lowered = load_media_scene(s.name);
    EXPECT_EQ(lowered.name, s.name);
    EXPECT_GT(lowered.outside.sigma_t, 0.0) << s.name;
    EXPECT_TRUE(lowered.area_light || lowered.light.intensity > 0.0) << s.name;
  }
  EXPECT_EQ(found, 7);  // small, exp1, exp1-literal, exp2, fog, exp1-bunny, exp2-bunny
  EXPECT_TRUE(scene::is_builtin_scene("EXP2-Bunny"));
}

TEST(MediaBuiltinScenes, LowerToThePapersMediaExactly) {
  const MediaScene exp2 = load_media_scene("exp2");
  EXPECT_EQ(exp2.outside.sigma_t, 1.0);  // σa = σt − σs added back: no rounding
  EXPECT_EQ(exp2.outside.sigma_s, 1.0);
  EXPECT_EQ(exp2.inside.sigma_t, 200.0);
  EXPECT_EQ(exp2.inside.sigma_s, 120.0);
  EXPECT_EQ(exp2.inside.phase.kind(), PhaseKind::schlick);
  EXPECT_EQ(exp2.inside.phase.parameter(), 0.6);
  EXPECT_EQ(exp2.ior, kDefaultIor);
  ASSERT_TRUE(exp2.area_light);
  EXPECT_EQ(exp2.area_light->exponent, 50.0);
  EXPECT_EQ(exp2.area_light->power, 40.0);
  EXPECT_NEAR(glm::length(exp2.area_light->normal), 1.0, 1e-15);
  EXPECT_EQ(exp2.photons_emitted, 20000u);
  EXPECT_EQ(exp2.k_nearest, 100u);
  const MediaScene small = load_media_scene("small");
  EXPECT_EQ(small.inside.sigma_t, 8.0);
  EXPECT_EQ(small.inside.sigma_s, 6.4);
  EXPECT_FALSE(small.area_light);
  EXPECT_EQ(small.photons_emitted, 20000u);
  EXPECT_EQ(small.k_nearest, 50u);
  EXPECT_EQ(small.max_specular_depth, 6);
}

bool same_bits(const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(MediaBuiltinScenes, TheBunnyLowersToTheTrianglesOfTheMeshLoadedDirectly) {
  const MediaScene s = load_media_scene("exp1-bunny");
  const auto* lowered = dynamic_cast<const MeshBoundary*>(s.object.get());
  ASSERT_NE(lowered, nullptr);
  const auto direct = load_mesh_boundary(find_scene_data("meshes/bunny.obj"), kBunnyPlacement);
  ASSERT_EQ(lowered->primitives().triangles.size(), direct->primitives().triangles.size());
  for (std::size_t i = 0; i < direct->primitives().triangles.size(); ++i)
    ASSERT_TRUE(same_bits(lowered->primitives().triangles[i], direct->primitives().triangles[i])) << "triangle " << i;
  EXPECT_EQ(lowered->surface_offset(), direct->surface_offset());
}

TEST(LowerMediaScene, ReadsAFileWithABoxOfFog) {
  const std::filesystem::path file = find_scene_data("media-small.toml");
  const MediaScene s = load_media_scene(file.string());
  EXPECT_EQ(s.name, "MEDIA-SMALL");
  EXPECT_EQ(s.fog_box.lo, glm::dvec3(-2, -1.5, -2));
  EXPECT_EQ(s.outside.sigma_t, 1.0);
  EXPECT_EQ(s.outside.sigma_s, 0.3);
  EXPECT_EQ(s.inside.phase.kind(), PhaseKind::schlick);
  EXPECT_EQ(s.ior, 1.5);
  EXPECT_NE(dynamic_cast<const SphereBoundary*>(s.object.get()), nullptr);
  EXPECT_EQ(s.light.intensity, 3.0);
  EXPECT_EQ(s.photons_emitted, scene::MediaSettings{}.photons_emitted);  // a file has no photon settings
}

// The small scene with one edit, lowered; the error's text.
std::string refusal(void (*edit)(scene::SceneDescription&)) {
  scene::SceneDescription d = small_description();
  edit(d);
  try {
    (void)lower_media_scene(d);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

bool has(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }

TEST(LowerMediaScene, RefusesWhatTheRendererCannotDrawNamingTheSceneAndWhy) {
  EXPECT_EQ(refusal([](scene::SceneDescription&) {}), "accepted");
  const std::string no_medium = refusal([](scene::SceneDescription& d) { for (auto& m : d.materials) m.medium.reset(); });
  EXPECT_TRUE(has(no_medium, "media scene 'small': no participating medium")) << no_medium;
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.shapes.erase(d.shapes.begin()); }), "no box of fog"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.camera.reset(); }), "no camera"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.lights.clear(); }), "0 lights"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.lights = {scene::SpotLight{}}; }), "a spot light"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.shapes.push_back(d.shapes[1]); }), "shape 3, material 'inside' is a second medium object"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.shapes[1].geometry = scene::Polygon{}; }), "is a polygon"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.materials[0].medium->boundary_ior = 1.3; }), "must not refract"));
  EXPECT_TRUE(has(refusal([](scene::SceneDescription& d) { d.materials[1].emission = scene::Rgb(1.0); }), "emits"));
  const std::string plain = refusal([](scene::SceneDescription& d) { d.add_material({.name = "wall"}); d.shapes.push_back({scene::Box{}, 2}); });
  EXPECT_TRUE(has(plain, "shape 3, material 'wall' has no medium")) << plain;
}

TEST(LowerMediaScene, AColouredMediumBecomesItsLuminance) {
  scene::SceneDescription d = small_description();
  d.materials[0].medium->sigma_s = scene::Rgb(0.1, 0.2, 0.3);
  d.materials[0].medium->sigma_a = scene::Rgb(0.0);
  const MediaScene s = lower_media_scene(d);
  EXPECT_NEAR(s.outside.sigma_s, 0.2126 * 0.1 + 0.7152 * 0.2 + 0.0722 * 0.3, 1e-15);
  EXPECT_EQ(s.outside.sigma_t, s.outside.sigma_s);
}

}  // namespace
}  // namespace gcsim::media
