#pragma once
// Radiosity's scenes: the thesis's three test environments of table 4.1 (ROOM, PICROOM, CORNELL;
// built as scene descriptions in builtin_descriptions.hpp, registered in the scene catalogue), and
// whatever the catalogue's one entry reads (any built-in scene, any scene file format), lowered by
// scene::to_world (a WORLD file gives its own World).
#include <string>
#include <string_view>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// The built-in scenes' WORLDs: scene::to_world of their descriptions.
World room_world();
World picroom_world();
World cornell_world();

std::vector<std::string> builtin_scene_names();  // room, picroom, cornell: the thesis's
// scene::to_world(scene::load_scene(name_or_path)); throws as those do (an unknown name lists the
// built-in scenes and the formats).
World load_scene_world(const std::string& name_or_path);

// The thesis's table 4.1 row for a built-in scene (all zero for others).
SceneCounts thesis_counts(std::string_view scene_name);

}  // namespace gcsim::radiosity
