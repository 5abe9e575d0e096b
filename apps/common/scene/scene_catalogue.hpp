#pragma once
// The one scene entry every application calls: a name or a path becomes a SceneDescription.
//   - a built-in scene's name (any case): the scenes the applications register here, as they
//     register with the pipeline (radiosity's ROOM, PICROOM, CORNELL; the ray tracer's six);
//   - else a file, read by the format its extension (any case) names: the TOML scene file, Wavefront
//     OBJ, the thesis's WORLD files (the table in scene_formats.cpp), and any format registered from
//     its own file with a SceneFormatRegistrar (tests/scene_formats/ holds one).
// Each application then lowers the description to its own primitives.
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "apps/common/scene/scene_description.hpp"

namespace gcsim::scene {

// A file format: what it is called, the extensions it reads (lower case, with the dot) and its
// loader, which throws a SceneError (or a type derived from it) naming the file and line.
struct SceneFormat {
  std::string name;
  std::vector<std::string> extensions;
  std::function<SceneDescription(const std::filesystem::path&)> load;
};

// A built-in scene: its name (lower case), the application that provides it, and its builder.
struct BuiltinScene {
  std::string name;
  std::string provider;
  std::function<SceneDescription()> build;
};

// Registers from a static object in the format's or the application's own source file; a second
// format for an extension, or a second scene of a name, stops the program at start-up.
struct SceneFormatRegistrar {
  explicit SceneFormatRegistrar(SceneFormat format);
};
struct BuiltinSceneRegistrar {
  explicit BuiltinSceneRegistrar(BuiltinScene scene);
};

// A name that is neither a built-in scene nor a file of a known format; the message lists both.
class UnknownSceneError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Every format (the table's, then the registered ones, by name) and every built-in scene (by name).
std::vector<SceneFormat> scene_formats();
std::vector<BuiltinScene> builtin_scenes();
std::vector<std::string> builtin_scene_names();
bool is_builtin_scene(std::string_view name);

// The format that reads this path's extension; throws UnknownSceneError listing the formats.
const SceneFormat& format_for(const std::filesystem::path& file);

// The built-in scene of that name, else the file read by its format. Throws UnknownSceneError
// (a name with no extension that is no built-in; an extension no format reads) or the loader's
// SceneError.
SceneDescription load_scene(const std::string& name_or_path);

}  // namespace gcsim::scene
