#pragma once
// Where the media scenes' data files (scenes/meshes/*.obj) are at run time: $GCSIM_SCENES_DIR, then
// ../share/gcsim/scenes next to the executable's directory (an install), then the source tree the
// binary was built from (apps/common/data_file.hpp, as `gcsim plot` finds its script).
#include <filesystem>
#include <string>

#include "apps/common/data_file.hpp"

namespace gcsim::media {

// The first existing <candidate>/<relative>; throws std::runtime_error naming every path tried.
inline std::filesystem::path find_scene_data(const std::string& relative) {
  return apps::find_data_file("scenes", relative, "GCSIM_SCENES_DIR", "the scene data file");
}

}  // namespace gcsim::media
