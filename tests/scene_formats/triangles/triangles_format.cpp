// A test-only scene format, added from this folder alone (tests/CMakeLists.txt finds it): a text
// file of one triangle a line, `tri` for a grey one (reflectance 0.5) and `light` for one that
// emits (exitance 1), each followed by the nine coordinates of its corners; `#` starts a comment.
//   light 0 2 0  1 2 0  0 2 1
//   tri   0 0 0  0 0 1  1 0 0
// Errors name the file and line (scene::SceneError).
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <glm/glm.hpp>

#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/common/scene/scene_error.hpp"

namespace gcsim::tests {

namespace {

constexpr double kMaxCoordinate = 1e15;  // as the other formats

struct Line {
  const std::string& file;
  int number;
  [[noreturn]] void fail(const std::string& expected) const { throw scene::SceneError(file, number, "expected " + expected); }
};

double coordinate(std::istringstream& words, const Line& line) {
  std::string word;
  double v = 0.0;
  if (!(words >> word)) line.fail("nine coordinates after 'tri' or 'light'");
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(v) || std::abs(v) > kMaxCoordinate)
    line.fail("a finite coordinate of at most 1e15, got '" + word + "'");
  return v;
}

scene::Polygon triangle(std::istringstream& words, const Line& line) {
  scene::Polygon p;
  p.count = 3;
  for (int k = 0; k < 3; ++k)
    for (int axis = 0; axis < 3; ++axis) p.vertex[k][axis] = coordinate(words, line);
  std::string extra;
  if (words >> extra) line.fail("nine coordinates and nothing after them, got '" + extra + "'");
  const glm::dvec3 n = glm::cross(p.vertex[1] - p.vertex[0], p.vertex[2] - p.vertex[0]);
  if (!(glm::length(n) > 0.0) || !std::isfinite(glm::length(n))) line.fail("a triangle of non-zero, finite area");
  return p;
}

scene::SceneDescription parse_triangles(std::istream& in, const std::string& file, const std::string& name) {
  scene::SceneDescription d;
  d.name = name;
  const int grey = d.add_material({.name = "grey", .diffuse = scene::Rgb(0.5)});
  const int light = d.add_material({.name = "light", .diffuse = scene::Rgb(0.0), .emission = scene::Rgb(1.0)});
  int number = 0;
  for (std::string text; std::getline(in, text);) {
    ++number;
    std::istringstream words(text.substr(0, text.find('#')));
    std::string kind;
    if (!(words >> kind)) continue;
    const Line line{file, number};
    if (kind != "tri" && kind != "light") line.fail("'tri' or 'light' at the start of the line, got '" + kind + "'");
    d.shapes.push_back({.geometry = triangle(words, line), .material = kind == "light" ? light : grey, .source_line = number});
  }
  if (d.shapes.empty()) throw scene::SceneError(file, 0, "expected at least one 'tri' or 'light' line");
  d.light_above_camera = true;  // no lights of its own: the ray tracer lights it from its camera
  return d;
}

scene::SceneDescription load_triangles(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw scene::SceneError(file.string(), 0, "cannot open the triangle file");
  return parse_triangles(in, file.string(), file.stem().string());
}

const scene::SceneFormatRegistrar kTriangles({"triangles, one a line (test-only)", {".tri"}, load_triangles});

}  // namespace

}  // namespace gcsim::tests
