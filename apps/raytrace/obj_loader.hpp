#pragma once
// A ray-tracing scene from a Wavefront OBJ file: the mesh comes from the shared scene layer
// (apps/common/scene/obj_mesh.hpp, which documents the accepted statements and the errors), lowered
// to float triangles with one grey material, a light and a camera framing them.
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
