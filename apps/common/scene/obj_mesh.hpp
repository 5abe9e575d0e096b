#pragma once
// Wavefront OBJ through tinyobjloader: `v x y z` and `f i j k ...` (polygons become a fan of
// triangles; indices may be negative, relative to the end, and may carry /vt/vn parts, which are
// ignored). Comments, vt, vn, vp, o, g, s, usemtl, mtllib and l lines are skipped. tinyobjloader is
// lenient, so each line is first checked here: an unknown statement, a malformed, non-finite or
// huge (|x| > 1e15) coordinate, an index out of range or a face with fewer than three vertices
// raises ObjError naming the file, the line and what was expected.
#include <filesystem>
#include <istream>
#include <string>

#include "apps/common/scene/scene_description.hpp"
#include "apps/common/scene/scene_error.hpp"
#include "apps/common/scene/triangle_mesh.hpp"

namespace gcsim::scene {

class ObjError : public SceneError {
 public:
  ObjError(const std::string& file, int line, const std::string& message);
};

constexpr double kMaxObjCoordinate = 1e15;

TriangleMesh load_obj_mesh(const std::filesystem::path& file);
TriangleMesh parse_obj_mesh(std::istream& in, const std::string& source_name);

// An OBJ file as a scene (named after the source): the mesh with one grey material, no camera and
// no lights, so light_above_camera: the renderer that frames it lights it from above its camera.
SceneDescription obj_description(TriangleMesh mesh, const std::string& source);
SceneDescription load_obj_description(const std::filesystem::path& file);
SceneDescription parse_obj_description(std::istream& in, const std::string& source);

}  // namespace gcsim::scene
