#pragma once
// Wavefront OBJ: `v x y z` and `f i j k ...` (polygons are split into a fan of triangles;
// indices may be negative, relative to the end, and may carry /vt/vn parts, which are ignored).
// Comments, vt, vn, o, g, s, usemtl, mtllib and l lines are skipped. Anything else, a malformed
// number, an index out of range or a face with fewer than three vertices raises ObjError naming
// the file, the line and what was expected.
#include <filesystem>
#include <istream>
#include <stdexcept>
#include <string>

#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

class ObjError : public std::runtime_error {
 public:
  ObjError(const std::string& file, int line, const std::string& what);
  std::string file;
  int line;
};

// Triangles with one grey material, a light and a camera framing them.
Scene load_obj_scene(const std::filesystem::path& file);
Scene parse_obj_scene(std::istream& in, const std::string& source_name);

}  // namespace gcsim::raytrace
