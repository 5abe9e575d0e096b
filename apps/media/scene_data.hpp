#pragma once
// Where the media scenes' data files (scenes/meshes/*.obj) are at run time: $GCSIM_SCENES_DIR, then
// ../share/gcsim/scenes next to the executable's directory (an install), then the source tree the
// binary was built from (GCSIM_SOURCE_DIR), as `gcsim plot` finds its script.
#include <filesystem>
#include <string>

namespace gcsim::media {

// The first existing <candidate>/<relative>; throws std::runtime_error naming every path tried.
std::filesystem::path find_scene_data(const std::string& relative);

}  // namespace gcsim::media
