#include "apps/raytrace/lower_scene.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "apps/common/scene/object_placement.hpp"
#include "apps/raytrace/framing.hpp"

namespace gcsim::raytrace {

namespace {

Material lower_material(const scene::Material& m, std::size_t index) {
  if (m.transmittance > 0.0 && (!m.fresnel || m.mirror > 0.0))
    throw std::invalid_argument("material " + std::to_string(index) + " ('" + m.name + "') is glass " +
                                (m.fresnel ? "with a mirror weight besides" : "without Fresnel") +
                                "; the ray tracer's glass reflects and refracts by Fresnel only");
  Material out;
  out.diffuse = glm::vec3(m.diffuse);
  if (m.checker_other) out.checker_other = glm::vec3(*m.checker_other);
  out.checker_size = static_cast<float>(m.checker_size);
  out.specular = static_cast<float>(m.specular);
  out.shininess = static_cast<float>(m.shininess);
  out.reflectance = static_cast<float>(m.mirror);
  out.transmittance = static_cast<float>(m.transmittance);
  out.ior = static_cast<float>(m.ior);
  out.emission = glm::vec3(m.emission);
  // The dielectric weighs its reflected ray F * reflectance and its refracted one
  // (1 - F) * transmittance: reflectance = transmittance gives glass of weight g.
  if (m.transmittance > 0.0) out.reflectance = out.transmittance;
  return out;
}

Triangle triangle_of(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return {glm::vec3(a), glm::vec3(b), glm::vec3(c)};
}

// The 12 triangles of an axis-aligned box, wound outwards.
void add_box(Scene& out, const scene::Box& box, int material) {
  const glm::dvec3 lo = box.lo, hi = box.hi;
  auto corner = [&](int i) { return glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
  static constexpr int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : kFaces) {
    out.add_triangle(triangle_of(corner(f[0]), corner(f[1]), corner(f[2])), material);
    out.add_triangle(triangle_of(corner(f[0]), corner(f[2]), corner(f[3])), material);
  }
}

void add_mesh(Scene& out, const scene::Mesh& m, int material) {
  const auto& p = m.mesh.positions;
  for (std::size_t i = 0; i < m.mesh.triangles.size(); ++i) {
    const auto& t = m.mesh.triangles[i];
    const Triangle tri = triangle_of(p[t[0]], p[t[1]], p[t[2]]);
    if (m.vertex_normals.empty()) {
      out.add_triangle(tri, material);
    } else {
      const auto& n = m.vertex_normals[i];
      out.add_triangle(tri, {glm::vec3(n[0]), glm::vec3(n[1]), glm::vec3(n[2])}, material);
    }
  }
}

void add_shape(Scene& out, const scene::Shape& shape) {
  const int material = shape.material;
  if (const auto* s = std::get_if<scene::Sphere>(&shape.geometry)) {
    out.add_sphere({glm::vec3(s->center), static_cast<float>(s->radius)}, material);
  } else if (const auto* poly = std::get_if<scene::Polygon>(&shape.geometry)) {
    for (int k = 1; k + 1 < poly->count; ++k)
      out.add_triangle(triangle_of(poly->vertex[0], poly->vertex[k], poly->vertex[k + 1]), material);
  } else if (const auto* box = std::get_if<scene::Box>(&shape.geometry)) {
    add_box(out, *box, material);
  } else {
    add_mesh(out, std::get<scene::Mesh>(shape.geometry), material);
  }
}

}  // namespace

Scene lower_scene(const scene::SceneDescription& d) {
  if (scene::places_objects(d)) return lower_scene(scene::with_objects_placed(d));
  Scene out;
  out.name = d.name;
  for (std::size_t i = 0; i < d.materials.size(); ++i) out.add_material(lower_material(d.materials[i], i));
  // A material no shape uses may hold a medium (the unified renderer takes the media's bounds out).
  for (const scene::Shape& shape : d.shapes) {
    const std::size_t m = std::size_t(shape.material);
    if (m < d.materials.size() && d.materials[m].medium)
      throw std::invalid_argument("material " + std::to_string(m) + " ('" + d.materials[m].name +
                                  "') holds a participating medium, which the ray tracer cannot render");
  }
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    if (d.shapes[i].material < 0 || d.shapes[i].material >= static_cast<int>(d.materials.size()))
      throw std::invalid_argument("shape " + std::to_string(i) + " names material " +
                                  std::to_string(d.shapes[i].material) + ", expected one of the " +
                                  std::to_string(d.materials.size()) + " materials");
    add_shape(out, d.shapes[i]);
  }
  out.lights = lower_lights(d);
  out.background = glm::vec3(d.image.background);
  out.ambient = glm::vec3(d.image.ambient);
  if (d.camera) {
    out.camera = *d.camera;
  } else if (out.prim_count() > 0) {
    out.camera = frame_scene(out.bounds(), {0.6f, 0.5f, 1.0f}, {0, 1, 0}, 40.0f);
  }
  if (d.light_above_camera && d.lights.empty() && out.prim_count() > 0) {
    // Above the eye, bright enough for the scene's size (float, as the OBJ scenes always were).
    const float r = 0.5f * glm::length(out.bounds().extent());
    out.lights.push_back({glm::vec3(out.camera.eye) + glm::vec3(0, 2.0f * r, 0), glm::vec3(9.0f * r * r)});
  }
  out.validate();
  return out;
}

std::vector<PointLight> lower_lights(const scene::SceneDescription& d) {
  std::vector<PointLight> lights;
  for (const scene::Light& light : d.lights) {
    if (const auto* p = std::get_if<scene::PointLight>(&light)) {
      lights.push_back({glm::vec3(p->position), glm::vec3(p->intensity)});
      continue;
    }
    const auto* disk = std::get_if<scene::DiskLight>(&light);
    if (disk != nullptr)
      throw std::invalid_argument("scene '" + d.name + "': a disk light (the media renderer's): the ray tracer lights by "
                                  "point and spot lights only");
    const auto& spot = std::get<scene::SpotLight>(light);
    PointLight l{glm::vec3(spot.position), glm::vec3(spot.intensity)};
    l.spot_direction = glm::vec3(glm::normalize(spot.direction));
    l.spot_cos = float(std::cos(spot.cone_degrees * std::numbers::pi / 180.0));
    lights.push_back(l);
  }
  return lights;
}

Bounds3 lowered_bounds(const scene::SceneDescription& d) {
  if (scene::places_objects(d)) return lowered_bounds(scene::with_objects_placed(d));
  Scene shapes;
  for (const auto& shape : d.shapes) add_shape(shapes, shape);
  return shapes.bounds();
}

}  // namespace gcsim::raytrace
