#include "apps/radiosity/builtin_scenes.hpp"

#include <algorithm>
#include <cctype>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/radiosity/builtin_descriptions.hpp"

namespace gcsim::radiosity {

World room_world() { return scene::to_world(room_description()); }
World picroom_world() { return scene::to_world(picroom_description()); }
World cornell_world() { return scene::to_world(cornell_description()); }

std::vector<std::string> builtin_scene_names() { return {"room", "picroom", "cornell"}; }

World load_scene_world(const std::string& name_or_path) { return scene::to_world(scene::load_scene(name_or_path)); }

namespace {

// The thesis's three in the scene catalogue, so that every application and the one entry know them.
const scene::BuiltinSceneRegistrar kRoom({"room", "radiosity", room_description});
const scene::BuiltinSceneRegistrar kPicroom({"picroom", "radiosity", picroom_description});
const scene::BuiltinSceneRegistrar kCornell({"cornell", "radiosity", cornell_description});

}  // namespace

SceneCounts thesis_counts(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "room") return {9, 22, 48, 197, 326};
  if (lower == "picroom") return {10, 27, 176, 205, 343};
  if (lower == "cornell") return {8, 9, 112, 166, 274};
  return {};
}

}  // namespace gcsim::radiosity
