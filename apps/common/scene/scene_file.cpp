#include "apps/common/scene/scene_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "apps/common/scene/scene_file_reader.hpp"
#include "machine/input_file.hpp"
#include "machine/toml_limits.hpp"

namespace gcsim::scene {

SceneFileError::SceneFileError(std::string f, int l, const std::string& m)
    : SceneError(std::move(f), l, m) {}

namespace file {
namespace {

constexpr double kMaxEmission = 1e15;
constexpr double kMaxCoefficient = 1e6;  // sigma_s, sigma_a per unit length

void read_camera(const Reader& r, const toml::table& root, SceneDescription& out) {
  const toml::table* t = r.table(root, "camera", "the scene");
  if (!t) return;
  r.only_keys(*t, "[camera]", {"eye", "target", "up", "fov"});
  Camera c;
  c.eye = r.vec3(*t, "eye", "[camera]");
  c.look_at = r.vec3(*t, "target", "[camera]");
  if (t->get("up")) c.up = r.vec3(*t, "up", "[camera]");
  c.fov_y_degrees = r.number(*t, "fov", "[camera]", 0.0, 180.0, c.fov_y_degrees);
  if (c.fov_y_degrees <= 0.0 || c.fov_y_degrees >= 180.0)
    r.fail(t->get("fov"), fmt::format("'fov' in [camera] is {}; expected degrees strictly between 0 and 180",
                                      c.fov_y_degrees));
  const glm::dvec3 view = c.look_at - c.eye;
  const double view_length = glm::length(view), up_length = glm::length(c.up);
  if (!(view_length > 0.0) || !std::isfinite(view_length))
    r.fail(t->get("target"), "degenerate camera: 'target' equals 'eye'; expected a point the camera looks at");
  if (!(up_length > 0.0) || !std::isfinite(up_length))
    r.fail(t->get("up"), "degenerate camera: 'up' is the zero vector; expected a direction");
  if (glm::length(glm::cross(view / view_length, c.up / up_length)) < 1e-9)
    r.fail(t->get("up") ? t->get("up") : t,
           "degenerate camera: 'up' is parallel to the view direction (target - eye); expected a direction across it");
  out.camera = c;
}

void read_image(const Reader& r, const toml::table& root, SceneDescription& out) {
  const toml::table* t = r.table(root, "image", "the scene");
  if (!t) return;
  r.only_keys(*t, "[image]", {"width", "height", "spp", "background", "ambient"});
  ImageSettings& im = out.image;
  im.width = r.integer(*t, "width", "[image]", 1, 16384, im.width);
  im.height = r.integer(*t, "height", "[image]", 1, 16384, im.height);
  im.samples_per_pixel = r.integer(*t, "spp", "[image]", 1, 65536, im.samples_per_pixel);
  im.background = r.rgb(*t, "background", "[image]", 0.0, kMaxEmission, im.background);
  im.ambient = r.rgb(*t, "ambient", "[image]", 0.0, 1.0, im.ambient);
}

Medium read_medium(const Reader& r, const toml::table& t, const std::string& where) {
  r.only_keys(t, where, {"sigma_s", "sigma_a", "phase", "g", "ior"});
  Medium m;
  m.sigma_s = r.rgb(t, "sigma_s", where, 0.0, kMaxCoefficient, Rgb(0.0));
  m.sigma_a = r.rgb(t, "sigma_a", where, 0.0, kMaxCoefficient, Rgb(0.0));
  const std::string isotropic = "isotropic";
  const std::string phase = r.string(t, "phase", where, &isotropic);
  if (phase == "isotropic") m.phase = PhaseKind::isotropic;
  else if (phase == "hg") m.phase = PhaseKind::henyey_greenstein;
  else if (phase == "schlick") m.phase = PhaseKind::schlick;
  else r.fail(t.get("phase"), fmt::format("'phase' in {} is '{}'; expected \"isotropic\", \"schlick\" or \"hg\"", where, phase));
  if (m.phase == PhaseKind::isotropic) {
    if (t.get("g")) r.fail(t.get("g"), fmt::format("'g' in {} needs phase = \"schlick\" or \"hg\"", where));
  } else {
    m.phase_g = r.required_number(t, "g", where, -1.0, 1.0);
    if (std::abs(m.phase_g) >= 1.0)
      r.fail(t.get("g"), fmt::format("'g' in {} is {}; expected a value strictly between -1 and 1", where, m.phase_g));
  }
  m.boundary_ior = r.number(t, "ior", where, 1.0, 10.0, 1.0);
  return m;
}

Material read_material(const Reader& r, const std::string& name, const toml::table& t) {
  const std::string where = "[materials." + name + "]";
  r.only_keys(t, where, {"reflectance", "emission", "mirror", "glass", "ior", "fresnel", "specular", "shininess",
                         "checker", "checker_size", "medium"});
  Material m;
  m.name = name;
  m.diffuse = r.rgb(t, "reflectance", where, 0.0, 1.0, Rgb(0.0));
  m.emission = r.rgb(t, "emission", where, 0.0, kMaxEmission, Rgb(0.0));
  m.mirror = r.number(t, "mirror", where, 0.0, 1.0, 0.0);
  m.transmittance = r.number(t, "glass", where, 0.0, 1.0, 0.0);
  m.ior = r.number(t, "ior", where, 1.0, 10.0, m.ior);
  m.fresnel = r.boolean(t, "fresnel", where, true);
  m.specular = r.number(t, "specular", where, 0.0, 1.0, 0.0);
  m.shininess = r.number(t, "shininess", where, 0.0, 1e6, m.shininess);
  if (t.get("checker")) m.checker_other = r.rgb(t, "checker", where, 0.0, 1.0, Rgb(0.0));
  m.checker_size = r.number(t, "checker_size", where, 1e-12, kMaxCoordinate, 1.0);
  const double largest = std::max({m.diffuse.r, m.diffuse.g, m.diffuse.b});
  if (largest + m.mirror + m.transmittance > 1.0 + 1e-12)
    r.fail(&t, fmt::format("{} reflects more than it receives: reflectance {} + mirror {} + glass {} > 1; expected "
                           "a sum of at most 1",
                           where, largest, m.mirror, m.transmittance));
  if (const toml::table* medium = r.table(t, "medium", where)) m.medium = read_medium(r, *medium, where + " medium");
  return m;
}

MaterialIndex read_materials(const Reader& r, const toml::table& root, SceneDescription& out) {
  MaterialIndex index;
  const toml::table* t = r.table(root, "materials", "the scene");
  if (!t) return index;
  for (const auto& [key, node] : *t) {
    const std::string name(key.str());
    if (!node.is_table())
      r.fail(&node, fmt::format("material '{}' must be a table, written [materials.{}]", name, name));
    index.emplace(name, out.add_material(read_material(r, name, *node.as_table())));
  }
  return index;
}

void read_lights(const Reader& r, const toml::table& root, SceneDescription& out) {
  for (const toml::table* t : r.tables(root, "point_light")) {
    r.only_keys(*t, "[[point_light]]", {"position", "intensity"});
    PointLight l;
    l.position = r.vec3(*t, "position", "[[point_light]]");
    l.intensity = r.rgb(*t, "intensity", "[[point_light]]", 0.0, kMaxEmission, l.intensity);
    out.lights.emplace_back(l);
  }
  for (const toml::table* t : r.tables(root, "spot_light")) {
    const std::string where = "[[spot_light]]";
    r.only_keys(*t, where, {"position", "direction", "intensity", "cone"});
    SpotLight l;
    l.position = r.vec3(*t, "position", where);
    l.direction = r.vec3(*t, "direction", where);
    if (!(glm::length(l.direction) > 0.0))
      r.fail(t->get("direction"), "'direction' in [[spot_light]] is the zero vector; expected a direction");
    l.direction = glm::normalize(l.direction);
    l.intensity = r.rgb(*t, "intensity", where, 0.0, kMaxEmission, l.intensity);
    l.cone_degrees = r.number(*t, "cone", where, 0.0, 90.0, l.cone_degrees);
    if (l.cone_degrees <= 0.0) r.fail(t->get("cone"), "'cone' in [[spot_light]] is 0; expected a half-angle in (0, 90] degrees");
    out.lights.emplace_back(l);
  }
}

SceneDescription read_scene(const Reader& r, const toml::table& root, const std::string& default_name) {
  r.only_keys(root, "the scene",
              {"name", "camera", "image", "materials", "polygon", "box", "sphere", "mesh", "world", "point_light",
               "spot_light"});
  SceneDescription out;
  out.name = r.string(root, "name", "the scene", &default_name);
  read_camera(r, root, out);
  read_image(r, root, out);
  const MaterialIndex materials = read_materials(r, root, out);
  read_shapes(r, root, materials, out);
  read_lights(r, root, out);
  return out;
}

}  // namespace
}  // namespace file

SceneDescription parse_scene_file(std::string_view text, const std::string& file_name,
                                  const std::filesystem::path& base_dir) {
  if (auto too_much = machine::check_toml_limits(text)) throw SceneFileError(file_name, too_much->line, too_much->message);
  toml::table root;
  try {
    root = toml::parse(text, file_name);
  } catch (const toml::parse_error& e) {
    throw SceneFileError(file_name, int(e.source().begin.line), std::string(e.description()) + " (not valid TOML)");
  }
  const file::Reader reader(file_name, base_dir);
  return file::read_scene(reader, root, std::filesystem::path(file_name).stem().string());
}

SceneDescription load_scene_file(const std::filesystem::path& path) {
  const machine::InputFile in = machine::read_input_file(path, machine::kMaxTomlFileBytes);
  if (!in.ok()) throw SceneFileError(path.string(), 0, "cannot read the scene file: it " + in.error);
  return parse_scene_file(in.text, path.string(), path.parent_path());
}

}  // namespace gcsim::scene
