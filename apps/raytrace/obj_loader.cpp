#include "apps/raytrace/obj_loader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/coordinate_limit.hpp"

namespace gcsim::raytrace {

ObjError::ObjError(const std::string& f, int l, const std::string& what)
    : std::runtime_error(l > 0 ? f + ":" + std::to_string(l) + ": " + what : f + ": " + what), file(f), line(l) {}

namespace {

std::vector<std::string_view> split(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

}  // namespace

Scene parse_obj_scene(std::istream& in, const std::string& source) {
  Scene scene;
  scene.name = source;
  const int material = scene.add_material({.diffuse = {0.75f, 0.75f, 0.72f}, .specular = 0.3f});
  std::vector<glm::vec3> vertices;
  std::string line;
  int number = 0;
  auto fail = [&](const std::string& what) { throw ObjError(source, number, what); };
  while (std::getline(in, line)) {
    ++number;
    const auto hash = line.find('#');
    const auto words = split(std::string_view(line).substr(0, hash));
    if (words.empty()) continue;
    const std::string_view key = words[0];
    if (key == "v") {
      if (words.size() < 4 || words.size() > 5) fail("expected 'v x y z' (three coordinates)");
      glm::vec3 p;
      for (int i = 0; i < 3; ++i) {
        float value;
        const auto w = words[1 + i];
        const auto r = std::from_chars(w.data(), w.data() + w.size(), value);
        if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(value))
          fail("expected a finite number for coordinate " + std::to_string(i + 1) + " of a vertex, got '" + std::string(w) + "'");
        if (const std::string problem = vertex_coordinate_error(value, i); !problem.empty()) fail(problem);
        p[i] = value;
      }
      vertices.push_back(p);
    } else if (key == "f") {
      if (words.size() < 4) fail("expected a face with at least three vertices ('f i j k ...')");
      std::vector<int> idx;
      for (std::size_t i = 1; i < words.size(); ++i) {
        const auto w = words[i];
        const auto slash = w.find('/');
        const auto num = w.substr(0, slash);
        int value = 0;
        const auto r = std::from_chars(num.data(), num.data() + num.size(), value);
        if (r.ec != std::errc() || r.ptr != num.data() + num.size() || value == 0)
          fail("expected a vertex index (1-based, or negative from the end) in face, got '" + std::string(w) + "'");
        const int n = static_cast<int>(vertices.size());
        const int resolved = value > 0 ? value - 1 : n + value;
        if (resolved < 0 || resolved >= n)
          fail("vertex index " + std::to_string(value) + " is out of range (" + std::to_string(n) + " vertices defined so far)");
        idx.push_back(resolved);
      }
      for (std::size_t i = 1; i + 1 < idx.size(); ++i)
        scene.add_triangle({vertices[idx[0]], vertices[idx[i]], vertices[idx[i + 1]]}, material);
    } else if (key == "vt" || key == "vn" || key == "vp" || key == "o" || key == "g" || key == "s" || key == "usemtl" ||
               key == "mtllib" || key == "l") {
      continue;
    } else {
      fail("unknown statement '" + std::string(key) + "' (expected v, f, or one of vt vn vp o g s usemtl mtllib l)");
    }
  }
  if (scene.triangles.empty()) throw ObjError(source, number, "no faces found (expected at least one 'f' line)");
  scene.camera = frame_scene(scene.bounds(), {0.6f, 0.5f, 1.0f}, {0, 1, 0}, 40.0f);
  const Bounds3 b = scene.bounds();
  const float r = 0.5f * glm::length(b.extent());
  scene.lights.push_back({scene.camera.eye + glm::vec3(0, 2.0f * r, 0), glm::vec3(9.0f * r * r)});
  return scene;
}

Scene load_obj_scene(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw ObjError(file.string(), 0, "cannot open the file");
  return parse_obj_scene(in, file.string());
}

}  // namespace gcsim::raytrace
