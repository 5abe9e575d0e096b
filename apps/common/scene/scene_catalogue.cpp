#include "apps/common/scene/scene_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "apps/common/scene/scene_formats.hpp"

namespace gcsim::scene {

namespace {

std::string lower_case(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

// Filled by the registrars during static initialisation, read afterwards.
std::vector<SceneFormat>& registered_formats() {
  static std::vector<SceneFormat> formats;
  return formats;
}
std::map<std::string, BuiltinScene>& registered_scenes() {
  static std::map<std::string, BuiltinScene> scenes;
  return scenes;
}

// A programming mistake found at start-up, before any command runs: say what and stop.
[[noreturn]] void refuse_registration(const std::string& what) {
  std::fprintf(stderr, "gcsim: scene catalogue: %s\n", what.c_str());
  std::abort();
}

const SceneFormat* find_format(const std::string& extension) {
  for (const std::vector<SceneFormat>* formats : {&table_formats(), &std::as_const(registered_formats())})
    for (const SceneFormat& f : *formats)
      if (std::find(f.extensions.begin(), f.extensions.end(), extension) != f.extensions.end()) return &f;
  return nullptr;
}

std::string known_formats() {
  std::string out;
  for (const SceneFormat& f : scene_formats()) {
    std::string extensions;
    for (const std::string& e : f.extensions) extensions += (extensions.empty() ? "" : "/") + e;
    out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", extensions, f.name);
  }
  return out;
}

std::string known_scenes() {
  std::string out;
  for (const BuiltinScene& s : builtin_scenes()) out += (out.empty() ? "" : ", ") + s.name;
  return out.empty() ? "none registered" : out;
}

}  // namespace

SceneFormatRegistrar::SceneFormatRegistrar(SceneFormat format) {
  if (format.name.empty() || format.extensions.empty() || !format.load) refuse_registration("a format needs a name, extensions and a loader");
  for (std::string& e : format.extensions) {
    e = lower_case(e);
    if (e.size() < 2 || e[0] != '.') refuse_registration(fmt::format("format '{}': extension '{}' does not start with a dot", format.name, e));
    if (find_format(e)) refuse_registration(fmt::format("format '{}': a format for '{}' exists already", format.name, e));
  }
  registered_formats().push_back(std::move(format));
}

BuiltinSceneRegistrar::BuiltinSceneRegistrar(BuiltinScene scene) {
  scene.name = lower_case(scene.name);
  if (scene.name.empty() || !scene.build) refuse_registration("a built-in scene needs a name and a builder");
  const std::string name = scene.name;
  if (!registered_scenes().emplace(name, std::move(scene)).second)
    refuse_registration(fmt::format("two built-in scenes are called '{}'", name));
}

std::vector<SceneFormat> scene_formats() {
  std::vector<SceneFormat> out = table_formats();
  std::vector<SceneFormat> more = registered_formats();
  std::sort(more.begin(), more.end(), [](const SceneFormat& a, const SceneFormat& b) { return a.name < b.name; });
  out.insert(out.end(), more.begin(), more.end());
  return out;
}

std::vector<BuiltinScene> builtin_scenes() {
  std::vector<BuiltinScene> out;
  for (const auto& [name, s] : registered_scenes()) out.push_back(s);
  return out;
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> out;
  for (const auto& [name, s] : registered_scenes()) out.push_back(name);
  return out;
}

bool is_builtin_scene(std::string_view name) { return registered_scenes().count(lower_case(name)) > 0; }

const SceneFormat& format_for(const std::filesystem::path& file) {
  const std::string extension = lower_case(file.extension().string());
  if (const SceneFormat* f = find_format(extension)) return *f;
  throw UnknownSceneError(fmt::format("scene file '{}': {}; expected one of {}", file.string(),
                                      extension.empty() ? "no extension names its format" : "no format reads '" + extension + "'",
                                      known_formats()));
}

SceneDescription load_scene(const std::string& name_or_path) {
  if (auto it = registered_scenes().find(lower_case(name_or_path)); it != registered_scenes().end()) return it->second.build();
  const std::filesystem::path file(name_or_path);
  if (file.extension().empty() && file.parent_path().empty())
    throw UnknownSceneError(fmt::format("unknown scene '{}': expected a built-in scene ({}) or a scene file: {}", name_or_path,
                                        known_scenes(), known_formats()));
  return format_for(file).load(file);
}

}  // namespace gcsim::scene
