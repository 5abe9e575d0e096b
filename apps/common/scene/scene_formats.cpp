#include "apps/common/scene/scene_formats.hpp"

#include "apps/common/scene/obj_mesh.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/common/scene/world_description.hpp"

namespace gcsim::scene {

const std::vector<SceneFormat>& table_formats() {
  static const std::vector<SceneFormat> formats{
      {"TOML scene file", {".toml"}, [](const std::filesystem::path& f) { return load_scene_file(f); }},
      {"Wavefront OBJ", {".obj"}, [](const std::filesystem::path& f) { return load_obj_description(f); }},
      {"WORLD/ENTITY", {".wld", ".world"}, [](const std::filesystem::path& f) { return load_world_description(f); }},
  };
  return formats;
}

}  // namespace gcsim::scene
