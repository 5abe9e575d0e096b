#pragma once
// The thesis's three test environments (table 4.1), rebuilt so that their counts of instances,
// surfaces, patches, elements and vertices equal the table exactly:
//   ROOM     9 / 22 /  48 / 197 / 326   furnished room, two ceiling lights
//   PICROOM 10 / 27 / 176 / 205 / 343   furnished room, one light, three pictures on the walls
//   CORNELL  8 /  9 / 112 / 166 / 274   the published Cornell box (geometry in mm, its colours)
#include <string>
#include <string_view>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

World room_world();
World picroom_world();
World cornell_world();

std::vector<std::string> builtin_scene_names();  // room, picroom, cornell
// A built-in name (any case) or a path to a WORLD file; throws with the list of names otherwise.
World load_scene_world(const std::string& name_or_path);

// The thesis's table 4.1 row for a built-in scene (all zero for others).
SceneCounts thesis_counts(std::string_view scene_name);

}  // namespace gcsim::radiosity
