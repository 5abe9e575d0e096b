#include "apps/common/scene/object_placement.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

namespace gcsim::scene {

namespace {

bool mirrors(const Placement& at) {
  const glm::dvec3& s = at.scale;
  return (s.x < 0) != ((s.y < 0) != (s.z < 0));
}

Polygon placed_polygon(Polygon p, const Placement& at) {
  const std::array<glm::dvec3, 4> v = p.vertex;
  const bool mirrored = mirrors(at);
  for (int k = 0; k < p.count; ++k) p.vertex[k] = at.apply(v[mirrored ? p.count - 1 - k : k]);
  p.facing.reset();
  p.elements.clear();
  p.layout_vertex.reset();
  return p;
}

// The box's faces, each wound outwards, as the ray tracer splits a box.
std::vector<Polygon> box_faces(const Box& box) {
  auto corner = [&](int i) {
    return glm::dvec3(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y, i & 4 ? box.hi.z : box.lo.z);
  };
  static constexpr int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Polygon> faces;
  for (const auto& f : kFaces) {
    Polygon p;
    p.count = 4;
    for (int k = 0; k < 4; ++k) p.vertex[k] = corner(f[k]);
    faces.push_back(p);
  }
  return faces;
}

void add_placed(const Shape& shape, const Placement& at, std::vector<Shape>& out) {
  Shape s = shape;
  if (const auto* p = std::get_if<Polygon>(&shape.geometry)) {
    s.geometry = placed_polygon(*p, at);
    out.push_back(s);
  } else if (const auto* box = std::get_if<Box>(&shape.geometry)) {
    for (const Polygon& face : box_faces(*box)) {
      s.geometry = placed_polygon(face, at);
      out.push_back(s);
    }
  } else if (const auto* sphere = std::get_if<Sphere>(&shape.geometry)) {
    const glm::dvec3 k = glm::abs(at.scale);
    if (k.x != k.y || k.y != k.z)
      throw std::invalid_argument("object '" + shape.object + "': a sphere placed with a non-uniform scale");
    s.geometry = Sphere{at.apply(sphere->center), sphere->radius * k.x};
    out.push_back(s);
  } else {
    Mesh m = std::get<Mesh>(shape.geometry);
    if (!m.vertex_normals.empty())
      throw std::invalid_argument("object '" + shape.object + "': a mesh with vertex normals placed by a layout");
    for (glm::dvec3& v : m.mesh.positions) v = at.apply(v);
    if (mirrors(at))
      for (auto& t : m.mesh.triangles) std::swap(t[1], t[2]);
    s.geometry = std::move(m);
    out.push_back(std::move(s));
  }
}

}  // namespace

bool places_objects(const SceneDescription& d) {
  for (const ObjectLayout& l : d.layouts)
    if (!l.instances.empty()) return true;
  return false;
}

SceneDescription with_objects_placed(const SceneDescription& d) {
  std::map<std::string, const std::vector<Placement>*> instances;
  for (const ObjectLayout& l : d.layouts)
    if (!l.instances.empty()) instances[l.object] = &l.instances;
  SceneDescription out = d;
  out.layouts.clear();
  out.shapes.clear();
  for (const Shape& shape : d.shapes) {
    auto it = shape.object.empty() ? instances.end() : instances.find(shape.object);
    if (it == instances.end()) {
      out.shapes.push_back(shape);
      continue;
    }
    for (const Placement& at : *it->second) add_placed(shape, at, out.shapes);
  }
  return out;
}

}  // namespace gcsim::scene
