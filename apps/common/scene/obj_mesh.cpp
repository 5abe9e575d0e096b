#include "apps/common/scene/obj_mesh.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include <tiny_obj_loader.h>

#include "machine/input_file.hpp"

namespace gcsim::scene {

ObjError::ObjError(const std::string& f, int l, const std::string& message) : SceneError(f, l, message) {}

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

// Checks each line against the grammar above, counting the vertices defined so far (for index
// ranges) and the faces.
struct LineChecker {
  const std::string& source;
  int number = 0;
  int vertices = 0;
  int faces = 0;

  [[noreturn]] void fail(const std::string& what) const { throw ObjError(source, number, what); }

  void check_vertex(const std::vector<std::string_view>& words) {
    if (words.size() < 4 || words.size() > 5) fail("expected 'v x y z' (three coordinates)");
    for (int i = 0; i < 3; ++i) {
      double value;
      const auto w = words[1 + i];
      const auto r = std::from_chars(w.data(), w.data() + w.size(), value);
      if (r.ec != std::errc() || r.ptr != w.data() + w.size() || !std::isfinite(value))
        fail("expected a finite number for coordinate " + std::to_string(i + 1) + " of a vertex, got '" +
             std::string(w) + "'");
      if (std::abs(value) > kMaxObjCoordinate)
        fail("expected coordinate " + std::to_string(i + 1) + " of a vertex within +-1e15, got '" + std::string(w) + "'");
    }
    ++vertices;
  }

  void check_face(const std::vector<std::string_view>& words) {
    if (words.size() < 4) fail("expected a face with at least three vertices ('f i j k ...')");
    for (std::size_t i = 1; i < words.size(); ++i) {
      const auto w = words[i];
      const auto num = w.substr(0, w.find('/'));
      int value = 0;
      const auto r = std::from_chars(num.data(), num.data() + num.size(), value);
      if (r.ec != std::errc() || r.ptr != num.data() + num.size() || value == 0)
        fail("expected a vertex index (1-based, or negative from the end) in face, got '" + std::string(w) + "'");
      const int resolved = value > 0 ? value - 1 : vertices + value;
      if (resolved < 0 || resolved >= vertices)
        fail("vertex index " + std::to_string(value) + " is out of range (" + std::to_string(vertices) +
             " vertices defined so far)");
    }
    ++faces;
  }

  void check(const std::string& line) {
    ++number;
    // tinyobjloader reads past a '#' or a NUL inside a line where this checker would stop: refuse
    // the bytes rather than let the two readings differ.
    if (const auto at = line.find('\0'); at != std::string::npos)
      fail("unexpected NUL byte at column " + std::to_string(at + 1));
    const auto words = split(std::string_view(line).substr(0, line.find('#')));
    if (words.empty()) return;
    const std::string_view key = words[0];
    if (key == "v") return check_vertex(words);
    if (key == "f") return check_face(words);
    for (const char* skipped : {"vt", "vn", "vp", "o", "g", "s", "usemtl", "mtllib", "l"})
      if (key == skipped) return;
    fail("unknown statement '" + std::string(key) + "' (expected v, f, or one of vt vn vp o g s usemtl mtllib l)");
  }
};

// tinyobjloader's shapes as one mesh: every polygon split into a fan from its first vertex. Every
// index is checked again here, whatever the line checker let through (fuzzing found a face token
// that the two read differently, `1#2`).
TriangleMesh mesh_from(const tinyobj::ObjReader& reader, const std::string& source) {
  TriangleMesh mesh;
  const auto& v = reader.GetAttrib().vertices;
  mesh.positions.reserve(v.size() / 3);
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) mesh.positions.push_back({v[i], v[i + 1], v[i + 2]});
  for (const auto& shape : reader.GetShapes()) {
    std::size_t at = 0;
    for (const unsigned char n : shape.mesh.num_face_vertices) {
      const auto& idx = shape.mesh.indices;
      if (at + n > idx.size()) throw ObjError(source, 0, "a face lists more vertices than the file holds");
      for (std::size_t k = 0; k < n; ++k)
        if (idx[at + k].vertex_index < 0 || std::size_t(idx[at + k].vertex_index) >= mesh.positions.size())
          throw ObjError(source, 0, "a face refers to vertex " + std::to_string(idx[at + k].vertex_index + 1) + ", but " +
                                        std::to_string(mesh.positions.size()) + " vertices are defined");
      for (std::size_t k = 1; k + 1 < n; ++k)
        mesh.triangles.push_back({idx[at].vertex_index, idx[at + k].vertex_index, idx[at + k + 1].vertex_index});
      at += n;
    }
  }
  return mesh;
}

}  // namespace

TriangleMesh parse_obj_mesh(std::istream& in, const std::string& source) {
  std::ostringstream text;
  LineChecker checker{source};
  for (std::string line; std::getline(in, line);) {
    checker.check(line);
    text << line << '\n';
  }
  if (checker.faces == 0) throw ObjError(source, checker.number, "no faces found (expected at least one 'f' line)");
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // the fan is made in mesh_from, as the thesis-era loader did
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text.str(), "", config))
    throw ObjError(source, 0, "tinyobjloader rejected the file: " + reader.Error());
  TriangleMesh mesh = mesh_from(reader, source);
  if (mesh.triangles.empty()) throw ObjError(source, checker.number, "no faces found (expected at least one 'f' line)");
  return mesh;
}

TriangleMesh load_obj_mesh(const std::filesystem::path& file) {
  machine::InputFile read = machine::read_input_file(file, machine::kMaxMeshFileBytes);
  if (!read.ok()) throw ObjError(file.string(), 0, "cannot read the OBJ file: it " + read.error);
  std::istringstream in(std::move(read.text));
  return parse_obj_mesh(in, file.string());
}

SceneDescription obj_description(TriangleMesh mesh, const std::string& source) {
  SceneDescription d;
  d.name = source;
  Material grey;
  grey.name = "obj grey";
  grey.diffuse = glm::dvec3(glm::vec3(0.75f, 0.75f, 0.72f));  // floats, as the ray tracer holds them
  grey.specular = 0.3f;
  const int material = d.add_material(grey);
  Shape& shape = d.shapes.emplace_back();
  shape.geometry = Mesh{std::move(mesh), {}};
  shape.material = material;
  d.light_above_camera = true;
  return d;
}

SceneDescription load_obj_description(const std::filesystem::path& file) {
  return obj_description(load_obj_mesh(file), file.string());
}

SceneDescription parse_obj_description(std::istream& in, const std::string& source) {
  return obj_description(parse_obj_mesh(in, source), source);
}

}  // namespace gcsim::scene
