#include "apps/raytrace/scene.hpp"

#include <cmath>
#include <stdexcept>

#include "apps/common/geometry/float_util.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {

bool Scene::has_secondary_effects() const {
  for (const auto& m : materials)
    if (m.spawns_secondary()) return true;
  return false;
}

Bounds3 Scene::bounds() const {
  Bounds3 b;
  for (int i = 0; i < prim_count(); ++i) b.extend(prim_bounds(i));
  return b;
}

glm::vec3 Scene::given_radiance(const Ray& ray, int prim, float b1, float b2) const {
  const GivenRadiance& g = triangle_radiance[std::size_t(prim - sphere_count())];
  const bool back = glm::dot(ray.direction, triangle(prim).geometric_normal()) > 0.0f;
  const VertexRadiance& r = back ? g.back : g.front;
  return (1.0f - b1 - b2) * r.r0 + b1 * r.r1 + b2 * r.r2;
}

int Scene::add_material(const Material& m) {
  materials.push_back(m);
  return static_cast<int>(materials.size() - 1);
}

void Scene::add_sphere(const Sphere& s, int material) {
  // Spheres come first in the id space: shift the triangles' materials if any exist.
  spheres.push_back(s);
  prim_material.insert(prim_material.begin() + (spheres.size() - 1), static_cast<std::uint16_t>(material));
}

void Scene::add_triangle(const Triangle& t, int material) {
  triangles.push_back(t);
  prim_material.push_back(static_cast<std::uint16_t>(material));
  if (!triangle_normals.empty()) {
    const glm::vec3 n = glm::normalize(t.geometric_normal());
    triangle_normals.push_back({n, n, n});
  }
}

void Scene::add_triangle(const Triangle& t, const VertexNormals& n, int material) {
  if (triangle_normals.size() != triangles.size()) {
    // First smooth triangle: give the flat ones their face normal.
    for (std::size_t i = triangle_normals.size(); i < triangles.size(); ++i) {
      glm::vec3 g = triangles[i].geometric_normal();
      const float len = glm::length(g);
      g = len > 0 ? g / len : glm::vec3(0, 0, 1);
      triangle_normals.push_back({g, g, g});
    }
  }
  triangles.push_back(t);
  triangle_normals.push_back(n);
  prim_material.push_back(static_cast<std::uint16_t>(material));
}

SurfacePoint Scene::surface_point(const Ray& ray, int prim, float t, float b1, float b2) const {
  SurfacePoint sp;
  if (is_sphere(prim)) {
    const Sphere& s = spheres[prim];
    // Re-project the hit onto the sphere: the error is then a few ulps of |p|.
    const glm::dvec3 c(s.center);
    glm::dvec3 p = glm::dvec3(ray.origin) + double(t) * glm::dvec3(ray.direction);
    glm::dvec3 radial = p - c;
    const double len = glm::length(radial);
    radial = len > 0 ? radial / len : glm::dvec3(0, 0, 1);
    p = c + double(s.radius) * radial;
    sp.position = glm::vec3(p);
    sp.position_error = gamma(5) * abs_components(sp.position) + gamma(5) * abs_components(s.center);
    sp.geometric_normal = glm::vec3(radial);
    sp.shading_normal = sp.geometric_normal;
  } else {
    const Triangle& tri = triangle(prim);
    const float b0 = 1.0f - b1 - b2;
    sp.position = b0 * tri.p0 + b1 * tri.p1 + b2 * tri.p2;
    sp.position_error = gamma(7) * (abs_components(b0 * tri.p0) + abs_components(b1 * tri.p1) + abs_components(b2 * tri.p2));
    glm::vec3 g = tri.geometric_normal();
    const float len = glm::length(g);
    sp.geometric_normal = len > 0 ? g / len : glm::vec3(0, 0, 1);
    sp.shading_normal = sp.geometric_normal;
    const int ti = prim - sphere_count();
    if (!triangle_normals.empty()) {
      const auto& vn = triangle_normals[ti];
      glm::vec3 n = b0 * vn.n0 + b1 * vn.n1 + b2 * vn.n2;
      const float nl = glm::length(n);
      if (nl > 0 && std::isfinite(nl)) sp.shading_normal = n / nl;
    }
    // Interpolated normals follow the geometric side.
    if (glm::dot(sp.shading_normal, sp.geometric_normal) < 0) sp.shading_normal = -sp.shading_normal;
  }
  sp.entering = glm::dot(ray.direction, sp.geometric_normal) < 0;
  if (!sp.entering) {
    sp.geometric_normal = -sp.geometric_normal;
    sp.shading_normal = -sp.shading_normal;
  }
  return sp;
}

void Scene::validate() const {
  if (prim_count() == 0) throw std::invalid_argument("scene '" + name + "' has no primitives");
  if (prim_material.size() != static_cast<std::size_t>(prim_count()))
    throw std::invalid_argument("scene '" + name + "': one material per primitive expected");
  auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  for (int i = 0; i < sphere_count(); ++i) {
    const auto& s = spheres[i];
    if (!finite(s.center) || !(s.radius > 0) || !std::isfinite(s.radius))
      throw std::invalid_argument("scene '" + name + "': sphere " + std::to_string(i) + " has a non-finite center or a radius that is not positive");
  }
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    if (!finite(t.p0) || !finite(t.p1) || !finite(t.p2))
      throw std::invalid_argument("scene '" + name + "': triangle " + std::to_string(i) + " has a non-finite vertex");
  }
  for (auto m : prim_material)
    if (m >= materials.size()) throw std::invalid_argument("scene '" + name + "': material index out of range");
  if (!triangle_radiance.empty() && triangle_radiance.size() != triangles.size())
    throw std::invalid_argument("scene '" + name + "': given radiance for some triangles only");
  for (int p = 0; p < prim_count(); ++p)
    if (material_of(p).given_radiance && (is_sphere(p) || triangle_radiance.empty()))
      throw std::invalid_argument("scene '" + name + "': primitive " + std::to_string(p) +
                                  " has a material with given radiance but no radiance at its vertices");
}

}  // namespace gcsim::raytrace
