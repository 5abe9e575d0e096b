#pragma once
// Wavefront OBJ files for the ray tracer: the shared scene layer's OBJ description (one grey
// material, apps/common/scene/obj_mesh.hpp, which documents the statements and the errors) lowered,
// framed and lit from above the camera (lower_scene).
#include <filesystem>
#include <istream>
#include <string>

#include "apps/common/scene/obj_mesh.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

using scene::ObjError;

Scene load_obj_scene(const std::filesystem::path& file);
Scene parse_obj_scene(std::istream& in, const std::string& source_name);

}  // namespace gcsim::raytrace
