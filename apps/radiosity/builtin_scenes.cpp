#include "apps/radiosity/builtin_scenes.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/common/scene/world_loader.hpp"
#include "apps/radiosity/builtin_descriptions.hpp"

namespace gcsim::radiosity {

World room_world() { return scene::to_world(room_description()); }
World picroom_world() { return scene::to_world(picroom_description()); }
World cornell_world() { return scene::to_world(cornell_description()); }

std::vector<std::string> builtin_scene_names() { return {"room", "picroom", "cornell"}; }

World load_scene_world(const std::string& name) {
  if (auto d = builtin_description(name)) return scene::to_world(*d);
  if (std::filesystem::exists(name)) {
    if (std::filesystem::path(name).extension() == ".toml") return scene::to_world(scene::load_scene_file(name));
    return load_world(name);
  }
  throw std::invalid_argument(fmt::format(
      "unknown scene '{}': expected room, picroom, cornell or the path of a TOML scene file or a WORLD file", name));
}

SceneCounts thesis_counts(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "room") return {9, 22, 48, 197, 326};
  if (lower == "picroom") return {10, 27, 176, 205, 343};
  if (lower == "cornell") return {8, 9, 112, 166, 274};
  return {};
}

}  // namespace gcsim::radiosity
