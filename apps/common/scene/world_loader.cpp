#include "apps/common/scene/world_loader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "machine/input_file.hpp"

namespace gcsim::scene {

using namespace gcsim::geometry;  // the double-precision polygons the area checks use

ParseError::ParseError(std::string f, int l, const std::string& m)
    : SceneError(f, l, m, fmt::format("{}:{}: {}", f, l, m)) {}

Vec3 Placement::apply(const Vec3& p0) const {
  Vec3 p = p0 * scale;
  auto rad = rotation_degrees * (std::numbers::pi / 180.0);
  double c = std::cos(rad.x), s = std::sin(rad.x);
  p = {p.x, c * p.y - s * p.z, s * p.y + c * p.z};
  c = std::cos(rad.y), s = std::sin(rad.y);
  p = {c * p.x + s * p.z, p.y, -s * p.x + c * p.z};
  c = std::cos(rad.z), s = std::sin(rad.z);
  p = {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
  return p + translation;
}

namespace {

struct Token {
  std::string text;
  int line;
};

// Splits into tokens, dropping /* ... */ comments; brackets are tokens of their own.
std::vector<Token> tokenize(std::string_view s, const std::string& file) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  while (i < s.size()) {
    char c = s[i];
    if (c == '\n') { ++line; ++i; continue; }
    if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
    if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
      int start = line;
      std::size_t end = s.find("*/", i + 2);
      if (end == std::string_view::npos) throw ParseError(file, start, "comment opened with /* is never closed with */");
      for (std::size_t k = i; k < end; ++k) line += s[k] == '\n';
      i = end + 2;
      continue;
    }
    if (std::string_view("<>[]{}").find(c) != std::string_view::npos) {
      out.push_back({std::string(1, c), line});
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j])) &&
           std::string_view("<>[]{}").find(s[j]) == std::string_view::npos &&
           !(s[j] == '/' && j + 1 < s.size() && s[j + 1] == '*'))
      ++j;
    out.push_back({std::string(s.substr(i, j - i)), line});
    i = j;
  }
  return out;
}

class Cursor {
 public:
  Cursor(std::vector<Token> t, std::string file) : toks_(std::move(t)), file_(std::move(file)) {}
  bool done() const { return pos_ >= toks_.size(); }
  const Token& peek() const { return toks_[pos_]; }
  int line() const {
    if (toks_.empty()) return 1;
    return done() ? toks_.back().line : toks_[pos_].line;
  }
  [[noreturn]] void fail(const std::string& expected) const {
    std::string found = done() ? "end of file" : "'" + toks_[pos_].text + "'";
    throw ParseError(file_, line(), fmt::format("expected {}, found {}", expected, found));
  }
  [[noreturn]] void fail_at(int line, const std::string& message) const { throw ParseError(file_, line, message); }
  const Token& next(const std::string& expected) {
    if (done()) fail(expected);
    return toks_[pos_++];
  }
  void expect(std::string_view word, const std::string& expected) {
    if (done() || toks_[pos_].text != word) fail(expected);
    ++pos_;
  }
  bool accept(std::string_view word) {
    if (!done() && toks_[pos_].text == word) { ++pos_; return true; }
    return false;
  }
  // The remaining tokens of the current line, joined by spaces (names such as "unit square").
  std::string rest_of_line(int line) {
    std::string s;
    while (!done() && toks_[pos_].line == line) {
      if (!s.empty()) s += ' ';
      s += toks_[pos_++].text;
    }
    return s;
  }
  double number(const std::string& what) {
    if (done()) fail(what);
    const std::string& t = toks_[pos_].text;
    double v = 0;
    auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v)) fail(what);
    ++pos_;
    return v;
  }
  int integer(const std::string& what) {
    if (done()) fail(what);
    const std::string& t = toks_[pos_].text;
    int v = 0;
    auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size()) fail(what);
    ++pos_;
    return v;
  }
  Vec3 triple(char open, char close, const std::string& what) {
    expect(std::string(1, open), fmt::format("'{}' opening {}", open, what));
    Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = number(fmt::format("number {} of {}", k + 1, what));
    expect(std::string(1, close), fmt::format("'{}' closing {} (three numbers)", close, what));
    return v;
  }
  const std::string& file() const { return file_; }

 private:
  std::vector<Token> toks_;
  std::string file_;
  std::size_t pos_ = 0;
};

// "N { a b c [d] }" : owner index and 3 or 4 vertex indices (a repeated last vertex makes a triangle).
PolygonRecord polygon_record(Cursor& c, const char* owner_name, int owners, int vertices, int& line) {
  line = c.line();
  PolygonRecord r;
  r.owner = c.integer(fmt::format("{} index", owner_name));
  if (r.owner < 0 || r.owner >= owners)
    c.fail_at(line, fmt::format("{} index {} out of range: {} {}s defined", owner_name, r.owner, owners, owner_name));
  c.expect("{", "'{' before the vertex indices");
  std::vector<int> idx;
  while (!c.done() && c.peek().text != "}") {
    int vl = c.line();
    int v = c.integer("vertex index or '}'");
    if (v < 0 || v >= vertices)
      c.fail_at(vl, fmt::format("vertex index {} out of range: {} vertices defined", v, vertices));
    idx.push_back(v);
  }
  c.expect("}", "'}' after the vertex indices");
  if (idx.size() == 4 && idx[3] == idx[2]) idx.pop_back();
  if (idx.size() < 3 || idx.size() > 4)
    c.fail_at(line, fmt::format("expected 3 or 4 vertex indices, found {}", idx.size()));
  r.count = int(idx.size());
  for (int k = 0; k < r.count; ++k) r.vertex[k] = idx[k];
  return r;
}

void check_area(Cursor& c, const Entity& e, const PolygonRecord& r, int line, const char* what) {
  geometry::Polygon p;
  p.count = r.count;
  for (int k = 0; k < r.count; ++k) p.v[k] = e.vertices[r.vertex[k]];
  double a = polygon_area(p);
  double scale = 0;
  for (int k = 0; k < r.count; ++k) scale = std::max(scale, glm::length(p.v[k] - p.v[0]));
  if (!(a > 1e-12 * scale * scale) || scale == 0) c.fail_at(line, fmt::format("{} has zero area (repeated or collinear vertices)", what));
}

}  // namespace

Entity parse_entity(std::string_view text, const std::string& file) {
  Cursor c(tokenize(text, file), file);
  Entity e;
  int l = c.line();
  c.expect("ENTITY", "'ENTITY' at the start of an entity file");
  e.name = c.rest_of_line(l);
  c.expect("VERTEX", "'VERTEX' section");
  while (!c.accept("END_VERT")) {
    if (c.done() || c.peek().text != "<") c.fail("'< x y z >' vertex or 'END_VERT'");
    int vl = c.line();
    Vec3 v = c.triple('<', '>', "vertex vector");
    // Far beyond any scene; squares of such numbers would overflow the geometry.
    for (int k = 0; k < 3; ++k)
      if (std::abs(v[k]) > 1e15) c.fail_at(vl, fmt::format("vertex coordinate {} is too large (limit 1e15)", v[k]));
    e.vertices.push_back(v);
  }
  c.expect("SURFACE", "'SURFACE' section");
  while (!c.accept("END_SURF")) {
    if (c.done() || c.peek().text != "[") c.fail("'[ r g b ] [ r g b ]' surface (reflectance, exitance) or 'END_SURF'");
    int sl = c.line();
    Surface s;
    s.reflectance = c.triple('[', ']', "reflectance vector");
    s.exitance = c.triple('[', ']', "exitance vector");
    for (int k = 0; k < 3; ++k) {
      if (s.reflectance[k] < 0 || s.reflectance[k] > 1)
        c.fail_at(sl, fmt::format("reflectance {} is outside [0, 1]", s.reflectance[k]));
      if (s.exitance[k] < 0) c.fail_at(sl, fmt::format("exitance {} is negative", s.exitance[k]));
      if (s.exitance[k] > 1e30) c.fail_at(sl, fmt::format("exitance {} is too large (limit 1e30)", s.exitance[k]));
    }
    e.surfaces.push_back(s);
  }
  c.expect("PATCH", "'PATCH' section");
  std::vector<int> patch_lines;
  while (!c.accept("END_PATCH")) {
    int line;
    auto r = polygon_record(c, "surface", int(e.surfaces.size()), int(e.vertices.size()), line);
    check_area(c, e, r, line, "patch");
    e.patches.push_back(r);
    patch_lines.push_back(line);
  }
  c.expect("ELEMENT", "'ELEMENT' section");
  std::vector<int> elements_of(e.patches.size(), 0);
  while (!c.accept("END_ELEM")) {
    int line;
    auto r = polygon_record(c, "patch", int(e.patches.size()), int(e.vertices.size()), line);
    check_area(c, e, r, line, "element");
    e.elements.push_back(r);
    ++elements_of[r.owner];
  }
  c.expect("END_ENTITY", "'END_ENTITY'");
  if (!c.done()) c.fail("end of file after END_ENTITY");
  for (std::size_t i = 0; i < e.patches.size(); ++i)
    if (elements_of[i] == 0)
      c.fail_at(patch_lines[i], fmt::format("patch {} has no elements (every patch needs at least one ELEMENT)", i));
  if (e.patches.empty()) c.fail_at(c.line(), "entity has no patches");
  return e;
}

World parse_world(std::string_view text, const std::string& file, const std::filesystem::path& base_dir) {
  Cursor c(tokenize(text, file), file);
  World w;
  int l = c.line();
  c.expect("WORLD", "'WORLD' at the start of a world file");
  w.name = c.rest_of_line(l);
  std::map<std::string, int> loaded;
  while (!c.accept("END_FILE")) {
    if (c.done()) c.fail("entity file name, COMMENT, CAMERA or 'END_FILE'");
    int tl = c.line();
    if (c.accept("COMMENT")) {
      c.rest_of_line(tl);
      continue;
    }
    if (c.accept("CAMERA")) {
      Camera cam;
      cam.eye = c.triple('<', '>', "camera eye");
      cam.look_at = c.triple('<', '>', "camera target");
      cam.up = c.triple('<', '>', "camera up vector");
      cam.fov_y_degrees = c.number("vertical field of view in degrees");
      if (!(cam.fov_y_degrees > 0 && cam.fov_y_degrees < 180)) c.fail_at(tl, "field of view must be in (0, 180) degrees");
      w.camera = cam;
      continue;
    }
    const Token& name = c.next("entity file name");
    if (name.text == "<" || name.text == "[") c.fail_at(name.line, "expected entity file name, found a vector");
    Instance inst;
    int scale_line = c.line();
    inst.placement.scale = c.triple('<', '>', "scaling vector");
    for (int k = 0; k < 3; ++k)
      if (inst.placement.scale[k] == 0)
        c.fail_at(scale_line, "scaling vector has a zero component: the entity would be flattened");
    int rest_line = c.line();
    inst.placement.rotation_degrees = c.triple('<', '>', "rotation vector");
    inst.placement.translation = c.triple('<', '>', "translation vector");
    for (int k = 0; k < 3; ++k)
      if (std::abs(inst.placement.scale[k]) > 1e15 || std::abs(inst.placement.translation[k]) > 1e15 ||
          std::abs(inst.placement.rotation_degrees[k]) > 1e6)
        c.fail_at(rest_line, "scaling, rotation or translation too large (limits 1e15, 1e6 degrees, 1e15)");
    auto it = loaded.find(name.text);
    if (it == loaded.end()) {
      std::filesystem::path p = base_dir / name.text;
      const machine::InputFile in = machine::read_input_file(p, machine::kMaxMeshFileBytes);
      if (!in.ok()) c.fail_at(name.line, fmt::format("cannot open entity file '{}': it {}", p.string(), in.error));
      w.entities.push_back(parse_entity(in.text, p.string()));
      it = loaded.emplace(name.text, int(w.entities.size()) - 1).first;
    }
    inst.entity = it->second;
    w.instances.push_back(inst);
  }
  if (!c.done()) c.fail("end of file after END_FILE");
  if (w.instances.empty()) c.fail_at(c.line(), "world has no instances");
  return w;
}

World load_world(const std::filesystem::path& world_file) {
  const machine::InputFile in = machine::read_input_file(world_file, machine::kMaxMeshFileBytes);
  if (!in.ok()) throw ParseError(world_file.string(), 0, "cannot read world file: it " + in.error);
  return parse_world(in.text, world_file.string(), world_file.parent_path());
}

namespace {
std::string vec(char open, char close, const Vec3& v) {
  return fmt::format("{} {} {} {} {}", open, v.x, v.y, v.z, close);
}
std::string record(const PolygonRecord& r) {
  std::string s = fmt::format("{} {{", r.owner);
  for (int k = 0; k < r.count; ++k) s += fmt::format(" {}", r.vertex[k]);
  return s + " }";
}
}  // namespace

std::string format_entity(const Entity& e) {
  std::string s = "ENTITY " + e.name + "\nVERTEX\n";
  for (const auto& v : e.vertices) s += vec('<', '>', v) + "\n";
  s += "END_VERT\nSURFACE\n";
  for (const auto& sf : e.surfaces) s += vec('[', ']', sf.reflectance) + " " + vec('[', ']', sf.exitance) + "\n";
  s += "END_SURF\nPATCH\n";
  for (const auto& p : e.patches) s += record(p) + "\n";
  s += "END_PATCH\nELEMENT\n";
  for (const auto& el : e.elements) s += record(el) + "\n";
  return s + "END_ELEM\nEND_ENTITY\n";
}

std::string format_world(const World& w, const std::vector<std::string>& files) {
  std::string s = "WORLD " + w.name + "\n";
  for (const auto& inst : w.instances) {
    s += fmt::format("{}\n{}\n{}\n{}\n", files.at(inst.entity), vec('<', '>', inst.placement.scale),
                     vec('<', '>', inst.placement.rotation_degrees), vec('<', '>', inst.placement.translation));
  }
  if (w.camera)
    s += fmt::format("CAMERA {} {} {} {}\n", vec('<', '>', w.camera->eye), vec('<', '>', w.camera->look_at),
                     vec('<', '>', w.camera->up), w.camera->fov_y_degrees);
  return s + "END_FILE\n";
}

}  // namespace gcsim::scene
