#include "apps/radiosity/scene.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::radiosity {

double Scene::extent() const {
  if (vertices.empty()) return 1.0;
  Vec3 lo = vertices[0], hi = vertices[0];
  for (const auto& v : vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  double d = glm::length(hi - lo);
  return d > 0 ? d : 1.0;
}

namespace {

Polygon make_polygon(const std::vector<Vec3>& verts, const std::array<int, 4>& idx, int count) {
  Polygon p;
  p.count = count;
  for (int i = 0; i < count; ++i) p.v[i] = verts[idx[i]];
  return p;
}

void check_record(const Entity& e, const PolygonRecord& r, const char* what, std::size_t index, int owners) {
  if (r.owner < 0 || r.owner >= owners)
    throw std::invalid_argument(fmt::format("entity '{}': {} {} refers to {} {}, but there are {}", e.name, what,
                                            index, what == std::string("patch") ? "surface" : "patch", r.owner,
                                            owners));
  if (r.count < 3 || r.count > 4)
    throw std::invalid_argument(fmt::format("entity '{}': {} {} has {} vertices, expected 3 or 4", e.name, what,
                                            index, r.count));
  for (int i = 0; i < r.count; ++i)
    if (r.vertex[i] < 0 || r.vertex[i] >= int(e.vertices.size()))
      throw std::invalid_argument(fmt::format("entity '{}': {} {} uses vertex {}, but there are {}", e.name, what,
                                              index, r.vertex[i], e.vertices.size()));
}

}  // namespace

Scene flatten(const World& world) {
  Scene s;
  s.name = world.name;
  s.camera = world.camera;
  s.instance_count = int(world.instances.size());
  // Elements must be contiguous per patch: collect them per patch first.
  for (const Instance& inst : world.instances) {
    if (inst.entity < 0 || inst.entity >= int(world.entities.size()))
      throw std::invalid_argument("instance refers to an unknown entity");
    const Entity& e = world.entities[inst.entity];
    int v0 = int(s.vertices.size()), s0 = int(s.surfaces.size()), p0 = int(s.patches.size());
    // A mirroring placement (odd number of negative scale factors) would turn every polygon to face
    // the other way; reversing the vertex order keeps the sides the entity file meant.
    const Vec3& sc = inst.placement.scale;
    const bool mirrored = (sc.x < 0) != ((sc.y < 0) != (sc.z < 0));
    for (const Vec3& v : e.vertices) s.vertices.push_back(inst.placement.apply(v));
    for (const Surface& sf : e.surfaces) s.surfaces.push_back(sf);
    std::vector<std::vector<int>> elements_of(e.patches.size());
    for (std::size_t i = 0; i < e.elements.size(); ++i) {
      check_record(e, e.elements[i], "element", i, int(e.patches.size()));
      elements_of[e.elements[i].owner].push_back(int(i));
    }
    for (std::size_t i = 0; i < e.patches.size(); ++i) {
      const PolygonRecord& r = e.patches[i];
      check_record(e, r, "patch", i, int(e.surfaces.size()));
      if (elements_of[i].empty())
        throw std::invalid_argument(fmt::format("entity '{}': patch {} has no elements", e.name, i));
      ScenePatch p;
      p.surface = s0 + r.owner;
      std::array<int, 4> gv{};
      for (int k = 0; k < r.count; ++k) gv[k] = v0 + r.vertex[mirrored ? r.count - 1 - k : k];
      p.polygon = make_polygon(s.vertices, gv, r.count);
      p.area = polygon_area(p.polygon);
      if (!(p.area > 0))
        throw std::invalid_argument(fmt::format("entity '{}': patch {} has zero area", e.name, i));
      p.normal = polygon_normal(p.polygon);
      p.center = polygon_centroid(p.polygon);
      p.first_element = int(s.elements.size());
      p.element_count = int(elements_of[i].size());
      for (int ei : elements_of[i]) {
        const PolygonRecord& er = e.elements[ei];
        SceneElement el;
        el.patch = p0 + int(i);
        el.count = er.count;
        for (int k = 0; k < er.count; ++k) el.vertex[k] = v0 + er.vertex[mirrored ? er.count - 1 - k : k];
        el.polygon = make_polygon(s.vertices, el.vertex, er.count);
        el.area = polygon_area(el.polygon);
        if (!(el.area > 0))
          throw std::invalid_argument(fmt::format("entity '{}': element {} has zero area", e.name, ei));
        el.normal = polygon_normal(el.polygon);
        el.center = polygon_centroid(el.polygon);
        s.elements.push_back(el);
      }
      s.patches.push_back(p);
    }
  }
  return s;
}

Camera default_camera(const Scene& scene) {
  Vec3 lo(0.0), hi(1.0);
  if (!scene.vertices.empty()) {
    lo = hi = scene.vertices[0];
    for (const auto& v : scene.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  }
  Vec3 c = 0.5 * (lo + hi);
  double r = 0.5 * glm::length(hi - lo);
  Camera cam;
  cam.look_at = c;
  cam.eye = c + glm::normalize(Vec3(0.3, 0.4, -1.0)) * (r * 2.8 + 1e-9);
  cam.up = {0, 1, 0};
  cam.fov_y_degrees = 45;
  return cam;
}

}  // namespace gcsim::radiosity
