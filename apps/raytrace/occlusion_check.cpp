#include "apps/raytrace/occlusion_check.hpp"

namespace gcsim::raytrace {

OcclusionCheck::OcclusionCheck(const Scene& scene, const Bvh& bvh, const Camera& camera)
    : scene_(scene), bvh_(bvh), eye_(camera.eye()), shades_(std::size_t(scene.prim_count())) {
  for (int x = 0; x < camera.width(); ++x) {
    const Plane p = camera.column_plane_at(x + 0.5f);
    columns_.emplace_back(p);
    flipped_columns_.emplace_back(flipped(p));
  }
  for (int y = 0; y < camera.height(); ++y) {
    const Plane p = camera.row_plane_at(y + 0.5f);
    rows_.emplace_back(p);
    flipped_rows_.emplace_back(flipped(p));
  }
}

const OcclusionCheck::Shade& OcclusionCheck::shade_of(int prim) {
  Shade& s = shades_[prim];
  if (s.ready) return s;
  s.ready = true;
  if (!scene_.is_sphere(prim)) {
    const Triangle& t = scene_.triangle(prim);
    const glm::dvec3 p0(t.p0);
    const glm::dvec3 pn = glm::cross(glm::dvec3(t.p1) - p0, glm::dvec3(t.p2) - p0);
    const double eye_side = glm::dot(pn, glm::dvec3(eye_) - p0) > 0 ? 1.0 : -1.0;
    const glm::vec3 n = glm::vec3(-eye_side * pn);
    s.behind = Plane{n, glm::dot(n, t.p0)};
    s.has_behind = true;
    s.plane = {p0, pn, eye_side, 1e-9 * glm::length(pn)};
  } else {
    // The visible cap of a sphere seen from distance D lies in front of the plane at r^2/D from
    // the centre towards the eye; a ray meets P there before it can reach anything behind it.
    const Sphere& sp = scene_.spheres[prim];
    const glm::vec3 to_eye = eye_ - sp.center;
    const float d = glm::length(to_eye);
    if (d > sp.radius) {
      const glm::vec3 u = to_eye / d;
      s.behind = Plane{-u, glm::dot(-u, sp.center + u * (sp.radius * sp.radius / d))};
      s.has_behind = true;
    }
    s.sphere_bound = (d > sp.radius ? d : d + sp.radius) * (1.0f + 1e-5f);  // d: the eye to the centre
  }
  if (s.has_behind) s.behind_abs = abs_components(s.behind.normal);
  return s;
}

float OcclusionCheck::sphere_distance_bound(int prim) { return shade_of(prim).sphere_bound; }

// A triangle q with its three vertices behind or on P's plane, seen from the eye (P's neighbours
// across a convex fold of a mesh), cannot hide P.
bool OcclusionCheck::triangle_behind(const Shade& p, int q) const {
  if (scene_.is_sphere(q) || !p.has_plane()) return false;
  const Triangle& t = scene_.triangle(q);
  for (const glm::vec3& v : {t.p0, t.p1, t.p2}) {
    const glm::dvec3 d = glm::dvec3(v) - p.plane.p0;
    if (p.plane.eye_side * glm::dot(p.plane.normal, d) > p.plane.scale * glm::length(d)) return false;
  }
  return true;
}

// Every primitive that meets the subregion's pyramid is in the subtree. A box cannot hold one
// in front of P if it is farther from the eye than P can be (max_distance), or wholly behind
// P's plane as seen from the eye, or outside the pyramid of the region's corner rays.
bool OcclusionCheck::nothing_in_front(const Subtree& subtree, int prim, float max_distance, int rx0, int ry0, int rx1,
                                      int ry1, std::int64_t& checks) {
  if (is_primitive(subtree.root)) return primitive_of(subtree.root) == prim;
  const Shade& shade = shade_of(prim);
  // distance_to(eye) > max_distance, without a square root per box.
  const float max_squared = largest_with_sqrt_at_most(max_distance);
  const FourPlanes region({&columns_[rx0], &flipped_columns_[rx1], &rows_[ry0], &flipped_rows_[ry1]});
  auto cannot_occlude = [&](const Bounds3& box) {
    if (box.squared_distance_to(eye_) > max_squared) return true;
    const BoxCentre b(box);
    return (shade.has_behind && classify(b, shade.behind, shade.behind_abs) == Side::inside) || region.any_outside(b);
  };
  NodeRef stack[256];
  int top = 0;
  stack[top++] = subtree.root;
  ++checks;
  while (top > 0) {
    const PairNode& n = subtree.packed.nodes[stack[--top]];
    for (int i = 0; i < 2; ++i) {
      const NodeRef c = n.child[i];
      if (is_primitive(c) && primitive_of(c) == prim) continue;
      ++checks;
      const Bounds3 box{{n.bounds[0][i], n.bounds[1][i], n.bounds[2][i]},
                        {n.bounds[0][2 + i], n.bounds[1][2 + i], n.bounds[2][2 + i]}};
      if (is_primitive(c)) {
        if (!cannot_occlude(box) && !triangle_behind(shade, primitive_of(c))) return false;
      } else if (!cannot_occlude(box)) {
        if (top >= 256) return false;
        stack[top++] = c;
      }
    }
  }
  return true;
}

}  // namespace gcsim::raytrace
