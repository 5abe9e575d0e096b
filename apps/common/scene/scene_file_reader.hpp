#pragma once
// Checked reading of the scene file's TOML nodes (internal to scene_file*.cpp): every read names
// the file and line of the offending node and what was expected.
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <toml++/toml.h>

#include "apps/common/scene/scene_description.hpp"

namespace gcsim::scene::file {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Coordinates beyond this are refused, as in the OBJ and WORLD loaders.
constexpr double kMaxCoordinate = 1e15;

class Reader {
 public:
  Reader(std::string file, std::filesystem::path base_dir) : file_(std::move(file)), base_(std::move(base_dir)) {}

  [[noreturn]] void fail(const toml::node* n, const std::string& what) const;
  int line_of(const toml::node* n) const { return n ? int(n->source().begin.line) : 0; }
  const std::string& file() const { return file_; }

  // Refuses keys outside `keys`, so that a typo never falls back silently to a default.
  void only_keys(const toml::table& t, const std::string& where, std::initializer_list<std::string_view> keys) const;
  const toml::table* table(const toml::table& parent, std::string_view key, const std::string& where) const;
  // An array of tables ([[key]]); empty if absent.
  std::vector<const toml::table*> tables(const toml::table& parent, std::string_view key) const;

  double number(const toml::table& t, std::string_view key, const std::string& where, double lo, double hi,
                double fallback) const;
  double required_number(const toml::table& t, std::string_view key, const std::string& where, double lo,
                         double hi) const;
  int integer(const toml::table& t, std::string_view key, const std::string& where, int lo, int hi,
              int fallback) const;
  bool boolean(const toml::table& t, std::string_view key, const std::string& where, bool fallback) const;
  std::string string(const toml::table& t, std::string_view key, const std::string& where,
                     const std::string* fallback = nullptr) const;
  // A point or direction: an array of three finite numbers, each within +-kMaxCoordinate.
  glm::dvec3 vec3(const toml::table& t, std::string_view key, const std::string& where) const;
  glm::dvec3 vec3_node(const toml::node& n, const std::string& what) const;
  // A colour: a number (grey) or [r, g, b], each channel in [lo, hi].
  Rgb rgb(const toml::table& t, std::string_view key, const std::string& where, double lo, double hi,
          Rgb fallback) const;
  // Two integers [columns, rows], each in [1, hi].
  std::array<int, 2> grid(const toml::table& t, std::string_view key, const std::string& where, int hi) const;
  // A referenced file, resolved against the scene's folder; must exist as a regular file.
  std::filesystem::path existing_file(const toml::table& t, std::string_view key, const std::string& where) const;

 private:
  double as_number(const toml::node& n, const std::string& what) const;
  std::string file_;
  std::filesystem::path base_;
};

// The sections, one function each (scene_file_shapes.cpp holds the shapes).
using MaterialIndex = std::map<std::string, int, std::less<>>;
void read_shapes(const Reader& r, const toml::table& root, const MaterialIndex& materials, SceneDescription& out);

}  // namespace gcsim::scene::file
