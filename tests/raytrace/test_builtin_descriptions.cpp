// The built-in scenes as scene descriptions: their numbers are floats held exactly in doubles (so
// lowering reproduces the ray tracer's scenes bit for bit), a TOML transcription of whitted lowers
// to the built-in's primitives, and the one loading path takes built-ins, OBJ and TOML files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "apps/common/scene/scene_file.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/framing.hpp"
#include "apps/raytrace/lower_scene.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::raytrace {
namespace {

namespace fs = std::filesystem;

bool float_exact(double x) { return double(static_cast<float>(x)) == x; }
bool float_exact(const glm::dvec3& v) { return float_exact(v.x) && float_exact(v.y) && float_exact(v.z); }

void expect_float_exact_shapes(const scene::SceneDescription& d) {
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const auto& g = d.shapes[i].geometry;
    if (const auto* s = std::get_if<scene::Sphere>(&g)) {
      EXPECT_TRUE(float_exact(s->center) && float_exact(s->radius)) << "sphere " << i;
    } else if (const auto* p = std::get_if<scene::Polygon>(&g)) {
      for (int k = 0; k < p->count; ++k) EXPECT_TRUE(float_exact(p->vertex[k])) << "polygon " << i;
    } else if (const auto* m = std::get_if<scene::Mesh>(&g)) {
      for (const auto& v : m->mesh.positions) ASSERT_TRUE(float_exact(v)) << "mesh " << i;
      for (const auto& n : m->vertex_normals)
        ASSERT_TRUE(float_exact(n[0]) && float_exact(n[1]) && float_exact(n[2])) << "mesh normal " << i;
    }
  }
}

// Every number a built-in chooses is a float, so float -> double -> float is the identity and the
// lowered scene is the float scene the builder computed.
TEST(BuiltinDescriptions, HoldFloatsExactly) {
  for (auto name : builtin_scene_names()) {
    SCOPED_TRACE(std::string(name));
    const scene::SceneDescription d = builtin_scene_description(name);
    EXPECT_EQ(d.name, name);
    expect_float_exact_shapes(d);
    for (const auto& m : d.materials)
      EXPECT_TRUE(float_exact(m.diffuse) && float_exact(m.specular) && float_exact(m.shininess) && float_exact(m.mirror) &&
                  float_exact(m.transmittance) && float_exact(m.ior))
          << m.name;
    for (const auto& light : d.lights) {
      const auto& p = std::get<scene::PointLight>(light);
      EXPECT_TRUE(float_exact(p.position) && float_exact(p.intensity));
    }
    ASSERT_TRUE(d.camera);
    EXPECT_TRUE(float_exact(d.camera->eye) && float_exact(d.camera->look_at) && float_exact(d.camera->up) &&
                float_exact(d.camera->fov_y_degrees));
  }
}

// The description's defaults (background, ambient) lower to the ray tracer's own defaults.
TEST(BuiltinDescriptions, DescriptionDefaultsAreTheRayTracersDefaults) {
  const Scene lowered = make_builtin_scene("teapot"), plain;
  EXPECT_EQ(lowered.background, plain.background);
  EXPECT_EQ(lowered.ambient, plain.ambient);
}

// frame_scene: the camera looks at the bounds' centre from d = margin r / sin(fov / 2), so the
// bounding sphere (through the corners) subtends sin(half angle) = sin(fov / 2) / margin: with
// margin 1 it fits the vertical field of view exactly, every corner inside; smaller margins overfill.
TEST(BuiltinDescriptions, FramingFitsTheBoundingSphereInTheView) {
  Bounds3 b;
  b.extend(glm::vec3(-1.0f, 2.0f, 0.5f));
  b.extend(glm::vec3(3.0f, 2.5f, 4.0f));
  const double half_fov = glm::radians(20.0);
  for (const float margin : {1.0f, 0.72f}) {
    const scene::Camera c = frame_scene(b, {0.6f, 0.5f, 1.0f}, {0, 1, 0}, 40.0f, margin);
    EXPECT_EQ(c.look_at, glm::dvec3(b.center()));
    const glm::dvec3 forward = glm::normalize(c.look_at - c.eye);
    const double r = 0.5 * glm::length(glm::dvec3(b.extent()));
    EXPECT_NEAR(r / glm::length(c.look_at - c.eye), std::sin(half_fov) / margin, 1e-6);
    double widest = 0.0;
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 corner(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
      widest = std::max(widest, std::acos(glm::dot(forward, glm::normalize(corner - c.eye))));
    }
    if (margin == 1.0f) EXPECT_LE(widest, half_fov + 1e-6);
    else EXPECT_GT(widest, half_fov);
  }
}

// whitted without its teapot, written as a scene file by hand.
const char* kWhittedToml = R"(
name = "whitted"
[camera]
eye = [-1, -10.5, 4.2]
target = [0.3, 0.4, 0.9]
up = [0, 0, 1]
fov = 45
[image]
background = [0.35, 0.5, 0.75]
[materials.floor]
reflectance = [0.85, 0.85, 0.8]
checker = [0.15, 0.15, 0.2]
[materials.mirror]
reflectance = 0.05
specular = 0.6
shininess = 96
mirror = 0.9
[materials.glass]
specular = 0.6
shininess = 128
glass = 1
ior = 1.5
[materials.red]
reflectance = [0.8, 0.15, 0.1]
specular = 0.3
[materials.teal]
reflectance = [0.1, 0.6, 0.55]
specular = 0.3
[[sphere]]
material = "mirror"
center = [-1.6, 1.2, 1.2]
radius = 1.2
[[sphere]]
material = "glass"
center = [1.3, -1.0, 1.0]
radius = 1.0
[[sphere]]
material = "red"
center = [3.2, 2.2, 0.6]
radius = 0.6
[[sphere]]
material = "teal"
center = [-3.4, -1.6, 0.5]
radius = 0.5
[[sphere]]
material = "red"
center = [0.2, -3.0, 0.35]
radius = 0.35
[[polygon]]
material = "floor"
vertices = [[-12, -12, 0], [12, -12, 0], [12, 12, 0], [-12, 12, 0]]
[[point_light]]
position = [-6, -7, 10]
intensity = 180
[[point_light]]
position = [7, -3, 6]
intensity = 50
)";

bool same_bits(const auto& a, const auto& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(BuiltinDescriptions, WhittedFromATomlFileIsTheBuiltInBarItsTeapot) {
  const Scene file = lower_scene(scene::parse_scene_file(kWhittedToml, "whitted.toml", fs::temp_directory_path()));
  const Scene builtin = make_builtin_scene("whitted");
  ASSERT_EQ(file.spheres.size(), builtin.spheres.size());
  for (int i = 0; i < file.sphere_count(); ++i) {
    EXPECT_TRUE(same_bits(file.spheres[i], builtin.spheres[i])) << "sphere " << i;
    EXPECT_EQ(file.material_of(i), builtin.material_of(i)) << "material of sphere " << i;
  }
  ASSERT_EQ(file.triangles.size(), 2u);  // the floor; the built-in's teapot follows it
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(same_bits(file.triangles[i], builtin.triangles[i])) << "triangle " << i;
    EXPECT_EQ(file.material_of(file.sphere_count() + i), builtin.material_of(builtin.sphere_count() + i));
  }
  ASSERT_EQ(file.lights.size(), builtin.lights.size());
  for (std::size_t i = 0; i < file.lights.size(); ++i) EXPECT_TRUE(same_bits(file.lights[i], builtin.lights[i])) << i;
  EXPECT_TRUE(same_bits(file.background, builtin.background));
  EXPECT_TRUE(same_bits(file.ambient, builtin.ambient));
  // The file's decimals are not the built-in's floats, but the ray tracer's camera rounds both to
  // the same floats, so every ray agrees.
  const Camera a(file.camera, 17, 13), b(builtin.camera, 17, 13);
  for (int y = 0; y < 13; y += 4)
    for (int x = 0; x < 17; x += 4) {
      EXPECT_TRUE(same_bits(a.pixel_ray(x, y).origin, b.pixel_ray(x, y).origin));
      EXPECT_TRUE(same_bits(a.pixel_ray(x, y).direction, b.pixel_ray(x, y).direction));
    }
}

// One path: a .toml or .obj path given to load_scene is the description lowered.
TEST(BuiltinDescriptions, LoadSceneTakesBuiltInsObjAndTomlFiles) {
  const fs::path dir = test_support::scratch_path("gcsim-raytrace-load-scene");
  fs::create_directories(dir);
  std::ofstream(dir / "w.toml") << kWhittedToml;
  std::ofstream(dir / "tri.OBJ") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const Scene toml = load_scene((dir / "w.toml").string());
  EXPECT_EQ(toml.prim_count(), 7);
  EXPECT_EQ(toml.material_of(1).reflectance, 1.0f);  // glass = 1: the Fresnel-split reflected ray
  EXPECT_EQ(toml.material_of(1).transmittance, 1.0f);
  const Scene obj = load_scene((dir / "tri.OBJ").string());
  EXPECT_EQ(obj.triangles.size(), 1u);
  EXPECT_EQ(obj.lights.size(), 1u);
  const Scene by_name = load_scene("teapot"), built_in = make_builtin_scene("teapot");
  ASSERT_EQ(by_name.triangles.size(), built_in.triangles.size());
  EXPECT_EQ(std::memcmp(by_name.triangles.data(), built_in.triangles.data(), sizeof(Triangle) * by_name.triangles.size()), 0);
  fs::remove_all(dir);
  EXPECT_THROW(load_scene("teapot2"), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::raytrace
