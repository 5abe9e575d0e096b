#pragma once
// A scene description from a Wavefront OBJ file: the mesh comes from the shared scene layer
// (apps/common/scene/obj_mesh.hpp, which documents the accepted statements and the errors), with one
// grey material, a camera framing it and a light; the *_scene forms lower it (lower_scene).
#include <filesystem>
#include <istream>
#include <string>

#include "apps/common/scene/obj_mesh.hpp"
#include "apps/common/scene/scene_description.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

using scene::ObjError;

// The mesh with one grey material, a camera framing it and a light above the camera.
scene::SceneDescription obj_scene_description(scene::TriangleMesh mesh, const std::string& source);
scene::SceneDescription load_obj_description(const std::filesystem::path& file);
scene::SceneDescription parse_obj_description(std::istream& in, const std::string& source);
Scene load_obj_scene(const std::filesystem::path& file);
Scene parse_obj_scene(std::istream& in, const std::string& source_name);

}  // namespace gcsim::raytrace
