#pragma once
// The closed object's surface as seen by the media code: the closest hit along a ray, with the normal
// facing the incoming ray and whether the ray enters the object. An analytic sphere here; the triangle
// mesh through the shared BVH of apps/common is mesh_boundary.hpp.
#include <cmath>
#include <cstdint>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace gcsim::media {

struct BoundaryHit {
  double t;
  glm::dvec3 normal;  // faces the incoming ray: dot(d, normal) < 0
  bool entering;      // the ray goes from outside to inside
};

// The work a boundary query did beyond the analytic sphere test that media_camera_ray and
// media_photon_step already include: box-tree nodes expanded and triangles tested (a mesh).
struct BoundaryTally {
  std::uint64_t node_tests = 0, triangle_tests = 0;
  bool any() const { return node_tests != 0 || triangle_tests != 0; }
  void add(const BoundaryTally& o) { node_tests += o.node_tests, triangle_tests += o.triangle_tests; }
};

// A ray leaving the sphere starts this far along its direction from the hit point.
inline constexpr double kSphereSurfaceOffset = 1e-7;

class Boundary {
 public:
  virtual ~Boundary() = default;
  // The closest hit with t in (t_min, t_max); the work is added to *tally when given.
  virtual std::optional<BoundaryHit> intersect(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max,
                                               BoundaryTally* tally = nullptr) const = 0;
  virtual bool inside(const glm::dvec3& p, BoundaryTally* tally = nullptr) const = 0;
  // Where a ray leaving the surface at `at` (the point of `hit`) along `direction` starts, so that
  // it cannot hit the same surface again at t ≈ 0 and starts on the side it goes to.
  virtual glm::dvec3 leave_surface(const glm::dvec3& at, const BoundaryHit& /*hit*/, const glm::dvec3& direction) const {
    return at + kSphereSurfaceOffset * direction;
  }
};

class SphereBoundary final : public Boundary {
 public:
  SphereBoundary(glm::dvec3 centre, double radius) : centre_(centre), radius_(radius) {}
  std::optional<BoundaryHit> intersect(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max,
                                       BoundaryTally* /*tally*/ = nullptr) const override {
    // Solved in the numerically stable form (q = −(b + sign(b)√disc)), d unit length.
    const glm::dvec3 oc = o - centre_;
    const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - radius_ * radius_;
    const glm::dvec3 perp = oc - b * d;  // the discriminant from the perpendicular distance
    const double disc = radius_ * radius_ - glm::dot(perp, perp);
    if (disc < 0.0) return std::nullopt;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = q, t1 = q != 0.0 ? c / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    for (double t : {t0, t1}) {
      if (t > t_min && t < t_max) {
        glm::dvec3 n = (o + t * d - centre_) / radius_;
        const bool entering = glm::dot(d, n) < 0.0;
        return BoundaryHit{t, entering ? n : -n, entering};
      }
    }
    return std::nullopt;
  }
  bool inside(const glm::dvec3& p, BoundaryTally* /*tally*/ = nullptr) const override {
    const glm::dvec3 v = p - centre_;
    return glm::dot(v, v) < radius_ * radius_;
  }
  const glm::dvec3& centre() const { return centre_; }
  double radius() const { return radius_; }

 private:
  glm::dvec3 centre_;
  double radius_;
};

}  // namespace gcsim::media
