#include "apps/raytrace/obj_loader.hpp"

#include "apps/raytrace/framing.hpp"
#include "apps/raytrace/lower_scene.hpp"

namespace gcsim::raytrace {

scene::SceneDescription obj_scene_description(scene::TriangleMesh mesh, const std::string& source) {
  scene::SceneDescription d;
  d.name = source;
  scene::Material grey;
  grey.name = "obj grey";
  grey.diffuse = glm::dvec3(glm::vec3(0.75f, 0.75f, 0.72f));
  grey.specular = 0.3f;
  const int material = d.add_material(grey);
  scene::Shape& shape = d.shapes.emplace_back();
  shape.geometry = scene::Mesh{std::move(mesh), {}};
  shape.material = material;
  // Framed and lit in float from the float triangles' bounds, as the ray tracer will hold them.
  const Bounds3 b = lowered_bounds(d);
  d.camera = frame_scene(b, {0.6f, 0.5f, 1.0f}, {0, 1, 0}, 40.0f);
  const float r = 0.5f * glm::length(b.extent());
  const glm::vec3 light = glm::vec3(d.camera->eye) + glm::vec3(0, 2.0f * r, 0);  // above the eye
  d.lights.push_back(scene::PointLight{glm::dvec3(light), glm::dvec3(glm::vec3(9.0f * r * r))});
  return d;
}

scene::SceneDescription parse_obj_description(std::istream& in, const std::string& source) {
  return obj_scene_description(scene::parse_obj_mesh(in, source), source);
}

scene::SceneDescription load_obj_description(const std::filesystem::path& file) {
  return obj_scene_description(scene::load_obj_mesh(file), file.string());
}

Scene parse_obj_scene(std::istream& in, const std::string& source) { return lower_scene(parse_obj_description(in, source)); }

Scene load_obj_scene(const std::filesystem::path& file) { return lower_scene(load_obj_description(file)); }

}  // namespace gcsim::raytrace
