#include "apps/raytrace/builtin_scenes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "apps/common/rng.hpp"
#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/raytrace/framing.hpp"
#include "apps/raytrace/lower_scene.hpp"
#include "apps/raytrace/teapot.hpp"

namespace gcsim::raytrace {
namespace {

constexpr std::array<std::string_view, 6> kNames{"spheres-a", "spheres-b", "spheres-random", "teapot", "teapots", "whitted"};

glm::vec3 palette(int i) {
  // Distinct, not too dark colours cycling through hue.
  const float h = std::fmod(0.61803398875f * float(i), 1.0f) * 6.0f;
  const float x = 1.0f - std::abs(std::fmod(h, 2.0f) - 1.0f);
  glm::vec3 c = h < 1 ? glm::vec3(1, x, 0) : h < 2 ? glm::vec3(x, 1, 0) : h < 3 ? glm::vec3(0, 1, x)
              : h < 4 ? glm::vec3(0, x, 1) : h < 5 ? glm::vec3(x, 0, 1) : glm::vec3(1, 0, x);
  return 0.25f + 0.6f * c;
}

// Every coordinate below is computed in float, as the ray tracer holds it, and stored in the
// description's doubles, so that lowering gives back exactly those floats: the paper's figures and
// every simulated time depend on them bit for bit.

scene::Material phong(std::string name, glm::vec3 diffuse, float specular, float shininess = 32.0f) {
  scene::Material m;
  m.name = std::move(name);
  m.diffuse = glm::dvec3(diffuse);
  m.specular = specular;
  m.shininess = shininess;
  return m;
}

template <class Geometry>
void add_shape(scene::SceneDescription& d, Geometry geometry, int material) {
  scene::Shape& shape = d.shapes.emplace_back();
  shape.geometry = std::move(geometry);
  shape.material = material;
}

void add_sphere(scene::SceneDescription& d, glm::vec3 center, float radius, int material) {
  add_shape(d, scene::Sphere{glm::dvec3(center), radius}, material);
}

// Frames the scene from `direction` (40 degrees, `margin` of its bounding sphere) and adds the key
// light, both from the float scene's bounds, as the ray tracer will hold them.
void frame_and_light(scene::SceneDescription& d, glm::vec3 direction, glm::vec3 up, float margin = 1.0f) {
  const Bounds3 b = lowered_bounds(d);
  d.camera = frame_scene(b, direction, up, 40.0f, margin);
  const glm::vec3 c = b.center();
  const float r = 0.5f * glm::length(b.extent());
  const glm::vec3 eye(d.camera->eye), camera_up(d.camera->up);
  const glm::vec3 to_eye = glm::normalize(eye - c);
  // Above and to the left of the eye, so shapes read in relief.
  const glm::vec3 side = glm::normalize(glm::cross(camera_up, to_eye));
  const glm::vec3 position = c + 3.0f * r * glm::normalize(to_eye + 0.8f * camera_up - 0.6f * side);
  d.lights.push_back(scene::PointLight{glm::dvec3(position), glm::dvec3(glm::vec3(9.0f * r * r))});
}

scene::SceneDescription sphere_grid_description(std::string name, float radius) {
  scene::SceneDescription d;
  d.name = std::move(name);
  for (int i = 0; i < 8; ++i) d.add_material(phong("palette " + std::to_string(i), palette(i), 0.3f));
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) add_sphere(d, glm::vec3(x, y, z), radius, (x + y + z) % 8);
  // Close enough that the grid fills the frame: every ray crosses the lattice.
  frame_and_light(d, {1.0f, 0.75f, 1.35f}, {0, 1, 0}, 0.72f);
  return d;
}

scene::SceneDescription spheres_random_description() {
  scene::SceneDescription d;
  d.name = "spheres-random";
  apps::Rng rng(20260101u, 3u);
  for (int i = 0; i < 8; ++i) d.add_material(phong("palette " + std::to_string(i + 3), palette(i + 3), 0.3f));
  for (int i = 0; i < 512; ++i) {
    const glm::vec3 c(rng.uniform(0.0f, 8.0f), rng.uniform(0.0f, 8.0f), rng.uniform(0.0f, 8.0f));
    const float r = rng.uniform(0.1f, 0.5f);
    add_sphere(d, c, r, i % 8);
  }
  frame_and_light(d, {1.0f, 0.75f, 1.35f}, {0, 1, 0});
  return d;
}

// A teapot, turned by `angle` about its (z) axis and moved to `offset`: one mesh with its smooth
// normals, three positions of its own per triangle.
void add_teapot(scene::SceneDescription& d, const TeapotMesh& teapot, float angle, glm::vec3 offset, int material) {
  const float c = std::cos(angle), sn = std::sin(angle);
  auto turn = [&](glm::vec3 p) { return glm::vec3(c * p.x - sn * p.y, sn * p.x + c * p.y, p.z); };
  scene::Mesh out;
  for (std::size_t i = 0; i < teapot.triangles.size(); ++i) {
    const Triangle& t = teapot.triangles[i];
    const auto& n = teapot.normals[i];
    const int first = static_cast<int>(out.mesh.positions.size());
    for (const glm::vec3& p : {t.p0, t.p1, t.p2}) out.mesh.positions.push_back(glm::dvec3(turn(p) + offset));
    out.mesh.triangles.push_back({first, first + 1, first + 2});
    out.vertex_normals.push_back({glm::dvec3(turn(n.n0)), glm::dvec3(turn(n.n1)), glm::dvec3(turn(n.n2))});
  }
  add_shape(d, std::move(out), material);
}

scene::SceneDescription teapot_description() {
  scene::SceneDescription d;
  d.name = "teapot";
  const int m = d.add_material(phong("teapot", {0.8f, 0.55f, 0.3f}, 0.4f, 48.0f));
  add_teapot(d, make_teapot(), 0.0f, glm::vec3(0), m);
  frame_and_light(d, {-0.45f, -1.0f, 0.55f}, {0, 0, 1}, 0.85f);
  return d;
}

scene::SceneDescription teapots_description() {
  scene::SceneDescription d;
  d.name = "teapots";
  const TeapotMesh mesh = make_teapot();
  for (int i = 0; i < 8; ++i) {
    const int m = d.add_material(phong("teapot " + std::to_string(i), palette(i + 1), 0.4f, 48.0f));
    const int x = i % 2, y = (i / 2) % 2, z = i / 4;
    add_teapot(d, mesh, 0.7f * float(i), glm::vec3(7.0f * x + 1.5f * z, 5.5f * y, 4.0f * z), m);
  }
  frame_and_light(d, {-0.5f, -1.0f, 0.6f}, {0, 0, 1}, 0.8f);
  return d;
}

// Whitted's materials: a checkerboard floor, a mirror, glass (Fresnel-split, weight 1), two plain
// colours and a brass that mirrors a little.
void add_whitted_materials(scene::SceneDescription& d) {
  scene::Material floor = phong("floor", {0.85f, 0.85f, 0.8f}, 0.0f);
  floor.checker_other = glm::dvec3(glm::vec3(0.15f, 0.15f, 0.2f));
  scene::Material mirror = phong("mirror", glm::vec3(0.05f), 0.6f, 96.0f);
  mirror.mirror = 0.9f;
  scene::Material glass = phong("glass", glm::vec3(0.0f), 0.6f, 128.0f);
  glass.transmittance = 1.0;
  glass.ior = 1.5;
  scene::Material brass = phong("brass", {0.55f, 0.42f, 0.15f}, 0.5f, 64.0f);
  brass.mirror = 0.3f;
  for (const auto& m : {floor, mirror, glass, phong("red", {0.8f, 0.15f, 0.1f}, 0.3f),
                        phong("teal", {0.1f, 0.6f, 0.55f}, 0.3f), brass})
    d.add_material(m);
}

scene::SceneDescription whitted_description() {
  scene::SceneDescription d;
  d.name = "whitted";
  d.image.background = glm::dvec3(glm::vec3(0.35f, 0.5f, 0.75f));
  add_whitted_materials(d);
  enum { floor, mirror, glass, red, teal, brass };
  add_sphere(d, {-1.6f, 1.2f, 1.2f}, 1.2f, mirror);
  add_sphere(d, {1.3f, -1.0f, 1.0f}, 1.0f, glass);
  add_sphere(d, {3.2f, 2.2f, 0.6f}, 0.6f, red);
  add_sphere(d, {-3.4f, -1.6f, 0.5f}, 0.5f, teal);
  add_sphere(d, {0.2f, -3.0f, 0.35f}, 0.35f, red);
  // The checkerboard floor: one quad, two triangles.
  const double e = 12.0;
  scene::Polygon quad;
  quad.vertex = {glm::dvec3(-e, -e, 0), glm::dvec3(e, -e, 0), glm::dvec3(e, e, 0), glm::dvec3(-e, e, 0)};
  add_shape(d, quad, floor);
  TeapotMesh small = make_teapot();
  for (auto& t : small.triangles) {
    t.p0 *= 0.5f;
    t.p1 *= 0.5f;
    t.p2 *= 0.5f;
  }
  add_teapot(d, small, 2.2f, glm::vec3(2.0f, 3.5f, 0.0f), brass);
  d.camera = scene::Camera{.eye = glm::vec3(-1.0f, -10.5f, 4.2f), .look_at = glm::vec3(0.3f, 0.4f, 0.9f), .up = {0, 0, 1},
                           .fov_y_degrees = 45.0};
  d.lights.push_back(scene::PointLight{{-6.0, -7.0, 10.0}, glm::dvec3(180.0)});
  d.lights.push_back(scene::PointLight{{7.0, -3.0, 6.0}, glm::dvec3(50.0)});
  return d;
}

}  // namespace

scene::SceneDescription builtin_scene_description(std::string_view name) {
  if (name == "spheres-a") return sphere_grid_description("spheres-a", 0.4f);
  if (name == "spheres-b") return sphere_grid_description("spheres-b", 0.12f);
  if (name == "spheres-random") return spheres_random_description();
  if (name == "teapot") return teapot_description();
  if (name == "teapots") return teapots_description();
  if (name == "whitted") return whitted_description();
  std::string known;
  for (auto n : kNames) known += (known.empty() ? "" : ", ") + std::string(n);
  throw std::invalid_argument("unknown scene '" + std::string(name) + "' (built-in scenes: " + known +
                              "; or give the path of a .obj or .toml file)");
}

std::span<const std::string_view> builtin_scene_names() { return kNames; }
std::span<const std::string_view> paper_scene_names() { return std::span(kNames).first(5); }

Scene make_builtin_scene(std::string_view name) { return lower_scene(builtin_scene_description(name)); }

Scene load_scene(const std::string& name_or_path) { return lower_scene(scene::load_scene(name_or_path)); }

namespace {

// The six in the scene catalogue, so that every application and the one scene entry know them.
struct CatalogueEntries {
  CatalogueEntries() {
    for (std::string_view name : kNames)
      scene::BuiltinSceneRegistrar({std::string(name), "raytrace", [name] { return builtin_scene_description(name); }});
  }
} const kCatalogueEntries;

}  // namespace

}  // namespace gcsim::raytrace
