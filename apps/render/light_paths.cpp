#include "apps/render/light_paths.hpp"

#include <algorithm>
#include <variant>

#include "apps/common/geometry/polygon.hpp"

namespace gcsim::render {

namespace {


// The plane of a polygon side: unit normal (turned for the back) and a point on it.
struct Plane {
  glm::dvec3 normal, point;
};
bool plane_of(const scene::SceneDescription& d, const SurfaceSide& s, Plane* out) {
  const auto* p = std::get_if<scene::Polygon>(&d.shapes[s.shape].geometry);
  if (!p) return false;
  geometry::Polygon g;
  g.count = p->count;
  for (int k = 0; k < p->count; ++k) g.v[k] = p->vertex[k];
  glm::dvec3 n = geometry::polygon_normal(g);
  // A facing direction orients the side as the lowering to the radiosity mesh does.
  if (p->facing && glm::dot(n, *p->facing) < 0) n = -n;
  *out = {s.back ? -n : n, geometry::polygon_centroid(g)};
  return true;
}

// Whether some point of side b lies strictly in front of the plane.
bool in_front(const scene::SceneDescription& d, const Plane& plane, const SurfaceSide& b) {
  auto ahead = [&](const glm::dvec3& p) { return glm::dot(plane.normal, p - plane.point) > 1e-9; };
  const auto& g = d.shapes[b.shape].geometry;
  if (const auto* p = std::get_if<scene::Polygon>(&g))
    return std::any_of(p->vertex.begin(), p->vertex.begin() + p->count, ahead);
  if (const auto* s = std::get_if<scene::Sphere>(&g))
    return glm::dot(plane.normal, s->center - plane.point) + s->radius > 1e-9;
  if (const auto* box = std::get_if<scene::Box>(&g)) {
    for (int k = 0; k < 8; ++k)
      if (ahead({k & 1 ? box->hi.x : box->lo.x, k & 2 ? box->hi.y : box->lo.y, k & 4 ? box->hi.z : box->lo.z}))
        return true;
    return false;
  }
  const auto& m = std::get<scene::Mesh>(g).mesh;
  return std::any_of(m.positions.begin(), m.positions.end(), ahead);
}

}  // namespace

bool only_bounds_medium(const scene::Material& m) {
  return m.medium && scene::largest(m.diffuse) == 0.0 && scene::largest(m.emission) == 0.0 && m.mirror == 0.0 &&
         m.transmittance == 0.0 && m.specular == 0.0;
}

bool invisible_boundary(const scene::Material& m) { return only_bounds_medium(m) && m.medium->boundary_ior == 1.0; }

std::vector<SurfaceSide> visible_sides(const scene::SceneDescription& d) {
  std::vector<SurfaceSide> sides;
  for (int i = 0; i < int(d.shapes.size()); ++i) {
    const scene::Shape& s = d.shapes[i];
    if (!invisible_boundary(d.materials.at(s.material))) sides.push_back({i, s.material, false});
    if (s.back_material >= 0 && !invisible_boundary(d.materials.at(s.back_material)))
      sides.push_back({i, s.back_material, true});
  }
  return sides;
}

bool faces(const scene::SceneDescription& d, const SurfaceSide& a, const SurfaceSide& b) {
  Plane plane;
  return !plane_of(d, a, &plane) || in_front(d, plane, b);
}

bool faces_point(const scene::SceneDescription& d, const SurfaceSide& a, const glm::dvec3& p) {
  Plane plane;
  return !plane_of(d, a, &plane) || glm::dot(plane.normal, p - plane.point) > 1e-9;
}

bool exchange(const scene::SceneDescription& d, const SurfaceSide& a, const SurfaceSide& b) {
  if (a.shape == b.shape) return a.back == b.back && std::holds_alternative<scene::Mesh>(d.shapes[a.shape].geometry);
  return faces(d, a, b) && faces(d, b, a);
}

}  // namespace gcsim::render
