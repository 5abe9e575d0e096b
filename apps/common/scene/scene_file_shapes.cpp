// The shapes of the scene file: [[polygon]], [[box]], [[sphere]], [[mesh]] (Wavefront OBJ) and
// [[world]] (the thesis's WORLD/ENTITY files).
#include <cmath>

#include <fmt/format.h>

#include "apps/common/geometry/polygon.hpp"
#include "apps/common/scene/obj_mesh.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/common/scene/scene_file_reader.hpp"
#include "apps/common/scene/world_description.hpp"
#include "apps/common/scene/world_loader.hpp"

namespace gcsim::scene::file {

namespace {

constexpr int kMaxGrid = 1000;                   // patches or elements along one side
constexpr long kMaxElementsPerPolygon = 1000000;  // keeps a typo from asking for a huge mesh

int material_of(const Reader& r, const toml::table& t, std::string_view key, const std::string& where,
                const MaterialIndex& materials) {
  const std::string name = r.string(t, key, where);
  auto it = materials.find(name);
  if (it == materials.end()) {
    std::string known;
    for (const auto& [n, i] : materials) known += (known.empty() ? "" : ", ") + n;
    r.fail(t.get(key), fmt::format("'{}' in {} names material '{}', which is not defined; expected one of the "
                                   "[materials.NAME] tables ({})",
                                   key, where, name, known.empty() ? "none defined" : known));
  }
  return it->second;
}

Shape shape_base(const Reader& r, const toml::table& t, const std::string& where, const MaterialIndex& materials) {
  Shape s;
  s.material = material_of(r, t, "material", where, materials);
  const std::string none;
  s.object = r.string(t, "object", where, &none);
  s.source_line = r.line_of(&t);  // for errors found after parsing (e.g. what the renderer refuses)
  return s;
}

geometry::Polygon as_geometry(const std::array<glm::dvec3, 4>& v, int count) {
  geometry::Polygon p;
  p.count = count;
  for (int k = 0; k < count; ++k) p.v[k] = v[k];
  return p;
}

void read_polygon(const Reader& r, const toml::table& t, const MaterialIndex& materials, SceneDescription& out) {
  const std::string where = "[[polygon]]";
  r.only_keys(t, where, {"material", "object", "vertices", "patches", "elements", "facing", "back_material", "single_patch"});
  Shape s = shape_base(r, t, where, materials);
  Polygon p;
  const toml::node* vn = t.get("vertices");
  if (!vn) r.fail(&t, "missing key 'vertices' in [[polygon]]");
  const toml::array* va = vn->as_array();
  if (!va || va->size() < 3 || va->size() > 4)
    r.fail(vn, "'vertices' in [[polygon]] must be an array of 3 or 4 points [[x, y, z], ...]");
  p.count = int(va->size());
  for (int k = 0; k < p.count; ++k) p.vertex[k] = r.vec3_node(*va->get(k), fmt::format("vertex {} of [[polygon]]", k + 1));
  const geometry::Polygon g = as_geometry(p.vertex, p.count);
  if (!(geometry::polygon_area(g) > 0.0) || !std::isfinite(geometry::polygon_area(g)))
    r.fail(vn, "degenerate [[polygon]]: its vertices enclose no area; expected 3 or 4 distinct, non-collinear points");
  const auto patches = r.grid(t, "patches", where, kMaxGrid), elements = r.grid(t, "elements", where, kMaxGrid);
  if (p.count == 3 && (patches != std::array<int, 2>{1, 1} || elements != std::array<int, 2>{1, 1}))
    r.fail(t.get("patches") ? t.get("patches") : t.get("elements"),
           "a triangle is one patch of one element; 'patches' and 'elements' need 4 vertices");
  if (long(patches[0]) * patches[1] * elements[0] * elements[1] > kMaxElementsPerPolygon)
    r.fail(t.get("elements"), fmt::format("[[polygon]] asks for more than {} elements", kMaxElementsPerPolygon));
  p.patch_columns = patches[0], p.patch_rows = patches[1];
  p.element_columns = elements[0], p.element_rows = elements[1];
  p.single_patch = r.boolean(t, "single_patch", where, false);
  if (p.single_patch && (patches != std::array<int, 2>{1, 1} || elements != std::array<int, 2>{1, 1}))
    r.fail(t.get("patches") ? t.get("patches") : t.get("elements"),
           "'single_patch' in [[polygon]] is one patch of one element; expected no 'patches' or 'elements'");
  if (t.get("facing")) {
    p.facing = r.vec3(t, "facing", where);
    if (glm::dot(*p.facing, geometry::newell_normal(g)) == 0.0)
      r.fail(t.get("facing"), "'facing' in [[polygon]] lies in the polygon's plane; expected a direction off it");
  }
  if (t.get("back_material")) s.back_material = material_of(r, t, "back_material", where, materials);
  s.geometry = p;
  out.shapes.push_back(s);
}

void read_box(const Reader& r, const toml::table& t, const MaterialIndex& materials, SceneDescription& out) {
  r.only_keys(t, "[[box]]", {"material", "object", "min", "max"});
  Shape s = shape_base(r, t, "[[box]]", materials);
  Box b{r.vec3(t, "min", "[[box]]"), r.vec3(t, "max", "[[box]]")};
  for (int k = 0; k < 3; ++k)
    if (!(b.lo[k] < b.hi[k]))
      r.fail(t.get("max"), fmt::format("[[box]] is flat or inverted along axis {}: min {} >= max {}; expected "
                                       "min < max on every axis",
                                       "xyz"[k], b.lo[k], b.hi[k]));
  s.geometry = b;
  out.shapes.push_back(s);
}

void read_sphere(const Reader& r, const toml::table& t, const MaterialIndex& materials, SceneDescription& out) {
  r.only_keys(t, "[[sphere]]", {"material", "object", "center", "radius"});
  Shape s = shape_base(r, t, "[[sphere]]", materials);
  Sphere sp{r.vec3(t, "center", "[[sphere]]"), r.required_number(t, "radius", "[[sphere]]", 0.0, kMaxCoordinate)};
  if (sp.radius <= 0.0) r.fail(t.get("radius"), "'radius' in [[sphere]] is 0; expected a positive radius");
  s.geometry = sp;
  out.shapes.push_back(s);
}

void read_mesh(const Reader& r, const toml::table& t, const MaterialIndex& materials, SceneDescription& out) {
  r.only_keys(t, "[[mesh]]", {"material", "object", "file", "scale", "translate"});
  Shape s = shape_base(r, t, "[[mesh]]", materials);
  const auto path = r.existing_file(t, "file", "[[mesh]]");
  const double scale = r.number(t, "scale", "[[mesh]]", 0.0, kMaxCoordinate, 1.0);
  if (scale <= 0.0) r.fail(t.get("scale"), "'scale' in [[mesh]] is 0; expected a positive factor");
  const glm::dvec3 translate = t.get("translate") ? r.vec3(t, "translate", "[[mesh]]") : glm::dvec3(0.0);
  Mesh m;
  try {
    m.mesh = load_obj_mesh(path);
  } catch (const ObjError& e) {
    r.fail(t.get("file"), std::string("in the OBJ file of [[mesh]]: ") + e.what());
  }
  if (m.mesh.triangles.empty()) r.fail(t.get("file"), "the OBJ file of [[mesh]] has no faces; expected a mesh");
  for (auto& v : m.mesh.positions) v = v * scale + translate;
  s.geometry = std::move(m);
  out.shapes.push_back(std::move(s));
}

void read_world(const Reader& r, const toml::table& t, SceneDescription& out) {
  r.only_keys(t, "[[world]]", {"file"});
  const auto path = r.existing_file(t, "file", "[[world]]");
  World w;
  try {
    w = load_world(path);
  } catch (const ParseError& e) {
    r.fail(t.get("file"), std::string("in the WORLD file of [[world]]: ") + e.what());
  }
  if (const std::string problem = world_problem(w, " of [[world]]"); !problem.empty()) r.fail(t.get("file"), problem);
  add_world(w, path.stem().string(), out);
}

}  // namespace

void read_shapes(const Reader& r, const toml::table& root, const MaterialIndex& materials, SceneDescription& out) {
  for (const toml::table* t : r.tables(root, "polygon")) read_polygon(r, *t, materials, out);
  for (const toml::table* t : r.tables(root, "box")) read_box(r, *t, materials, out);
  for (const toml::table* t : r.tables(root, "sphere")) read_sphere(r, *t, materials, out);
  for (const toml::table* t : r.tables(root, "mesh")) read_mesh(r, *t, materials, out);
  for (const toml::table* t : r.tables(root, "world")) read_world(r, *t, out);
}

}  // namespace gcsim::scene::file
