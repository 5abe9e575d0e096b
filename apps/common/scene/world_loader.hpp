#pragma once
// Reader for the thesis's environment format (figures 4.5 and 4.6): a WORLD file names ENTITY files,
// each followed by its scaling, rotation (degrees about x, y, z) and translation vectors; an ENTITY
// file has VERTEX, SURFACE (reflectance [r g b], initial exitance [r g b]), PATCH (surface index and
// vertices) and ELEMENT (patch index and vertices) sections. Comments are /* ... */ and COMMENT lines.
// As an extension a WORLD may hold `CAMERA < eye > < target > < up > fov_y_degrees` before END_FILE.
#include <filesystem>
#include <string>
#include <string_view>

#include "apps/common/scene/scene_error.hpp"
#include "apps/common/scene/world_format.hpp"

namespace gcsim::scene {

// A malformed file: what() reads "FILE:LINE: MESSAGE" (line 0 included).
class ParseError : public SceneError {
 public:
  ParseError(std::string file, int line, const std::string& message);
};

World load_world(const std::filesystem::path& world_file);
// Parses text already in memory; entity files are read relative to base_dir.
World parse_world(std::string_view text, const std::string& file_name, const std::filesystem::path& base_dir);
Entity parse_entity(std::string_view text, const std::string& file_name);

// Writes the formats back (used to export the built-in scenes as files).
std::string format_entity(const Entity& e);
std::string format_world(const World& w, const std::vector<std::string>& entity_file_names);

}  // namespace gcsim::scene

namespace gcsim::radiosity {
using scene::format_entity;
using scene::format_world;
using scene::load_world;
using scene::parse_entity;
using scene::parse_world;
using scene::ParseError;
}  // namespace gcsim::radiosity
