#pragma once
// The TOML scene file (every key in apps/common/scene/README.md, a commented example in
// scenes/example.toml): camera, image, named materials (diffuse, emission, mirror, glass, media),
// polygons, boxes, spheres, OBJ meshes, the thesis's WORLD files, point and spot lights. It is read
// into the shared SceneDescription. Every mistake raises SceneFileError naming the file, the line
// and what was expected: unknown keys, wrong types, negative or non-finite numbers, a degenerate
// camera or polygon, a referenced file that is missing. Relative paths are resolved against the
// folder of the scene file.
#include <filesystem>
#include <string>
#include <string_view>

#include "apps/common/scene/scene_description.hpp"
#include "apps/common/scene/scene_error.hpp"

namespace gcsim::scene {

// what() reads "FILE:LINE: MESSAGE", or "FILE: MESSAGE" (line 0) when the mistake has no line, e.g.
// a missing scene file.
class SceneFileError : public SceneError {
 public:
  SceneFileError(std::string file, int line, const std::string& message);
};

SceneDescription load_scene_file(const std::filesystem::path& file);
// Parses text already in memory; referenced files are read relative to base_dir.
SceneDescription parse_scene_file(std::string_view text, const std::string& file_name,
                                  const std::filesystem::path& base_dir);

}  // namespace gcsim::scene
