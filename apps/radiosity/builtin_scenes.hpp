#pragma once
// Radiosity's scenes by name: the thesis's three test environments of table 4.1 (ROOM, PICROOM,
// CORNELL; built as scene descriptions in builtin_descriptions.hpp and lowered by scene::to_world),
// a TOML scene file (through the same description path) or a WORLD file.
#include <string>
#include <string_view>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// The built-in scenes' WORLDs: scene::to_world of their descriptions.
World room_world();
World picroom_world();
World cornell_world();

std::vector<std::string> builtin_scene_names();  // room, picroom, cornell
// A built-in name (any case), the path of a TOML scene file (.toml) or of a WORLD file; throws with
// the list of names otherwise.
World load_scene_world(const std::string& name_or_path);

// The thesis's table 4.1 row for a built-in scene (all zero for others).
SceneCounts thesis_counts(std::string_view scene_name);

}  // namespace gcsim::radiosity
