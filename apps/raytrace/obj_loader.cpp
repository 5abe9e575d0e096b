#include "apps/raytrace/obj_loader.hpp"

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/coordinate_limit.hpp"
#include "apps/raytrace/lower_scene.hpp"

namespace gcsim::raytrace {

namespace {

Scene lower_obj_mesh(const scene::TriangleMesh& mesh, const std::string& source) {
  Scene out;
  out.name = source;
  const int material = out.add_material({.diffuse = {0.75f, 0.75f, 0.72f}, .specular = 0.3f});
  for (const auto& t : mesh.triangles) {
    out.add_triangle({glm::vec3(mesh.positions[t[0]]), glm::vec3(mesh.positions[t[1]]), glm::vec3(mesh.positions[t[2]])},
                     material);
  }
  out.camera = frame_scene(out.bounds(), {0.6f, 0.5f, 1.0f}, {0, 1, 0}, 40.0f);
  const Bounds3 b = out.bounds();
  const float r = 0.5f * glm::length(b.extent());
  out.lights.push_back({glm::vec3(out.camera.eye) + glm::vec3(0, 2.0f * r, 0), glm::vec3(9.0f * r * r)});
  return out;
}

}  // namespace

scene::SceneDescription obj_scene_description(scene::TriangleMesh mesh, const std::string& source) {
  scene::SceneDescription d;
  d.name = source;
  scene::Material grey;
  grey.name = "obj grey";
  grey.diffuse = glm::dvec3(glm::vec3(0.75f, 0.75f, 0.72f));
  grey.specular = 0.3f;
  const int material = d.add_material(grey);
  d.shapes.push_back({scene::Mesh{std::move(mesh), {}}, material});
  const Bounds3 b = lowered_bounds(d);
  d.camera = frame_scene(b, {0.6f, 0.5f, 1.0f}, {0, 1, 0}, 40.0f);
  // Above the eye, so the mesh reads in relief.
  const float r = 0.5f * glm::length(b.extent());
  const glm::vec3 light = glm::vec3(d.camera->eye) + glm::vec3(0, 2.0f * r, 0);
  d.lights.push_back(scene::PointLight{glm::dvec3(light), glm::dvec3(glm::vec3(9.0f * r * r))});
  return d;
}

scene::SceneDescription parse_obj_description(std::istream& in, const std::string& source) {
  return obj_scene_description(scene::parse_obj_mesh(in, source), source);
}

scene::SceneDescription load_obj_description(const std::filesystem::path& file) {
  return obj_scene_description(scene::load_obj_mesh(file), file.string());
}

Scene parse_obj_scene(std::istream& in, const std::string& source) {
  return lower_obj_mesh(scene::parse_obj_mesh(in, source), source);
}

Scene load_obj_scene(const std::filesystem::path& file) {
  return lower_obj_mesh(scene::load_obj_mesh(file), file.string());
}

}  // namespace gcsim::raytrace
