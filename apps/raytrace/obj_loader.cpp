#include "apps/raytrace/obj_loader.hpp"

#include "apps/raytrace/lower_scene.hpp"

namespace gcsim::raytrace {

Scene parse_obj_scene(std::istream& in, const std::string& source) {
  return lower_scene(scene::parse_obj_description(in, source));
}

Scene load_obj_scene(const std::filesystem::path& file) { return lower_scene(scene::load_obj_description(file)); }

}  // namespace gcsim::raytrace
