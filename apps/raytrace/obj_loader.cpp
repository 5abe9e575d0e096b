#include "apps/raytrace/obj_loader.hpp"

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/coordinate_limit.hpp"

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

Scene parse_obj_scene(std::istream& in, const std::string& source) {
  return lower_obj_mesh(scene::parse_obj_mesh(in, source), source);
}

Scene load_obj_scene(const std::filesystem::path& file) {
  return lower_obj_mesh(scene::load_obj_mesh(file), file.string());
}

}  // namespace gcsim::raytrace
