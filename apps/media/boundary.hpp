#pragma once
// The closed object's surface as seen by the media code: the closest hit along a ray, with the normal
// facing the incoming ray and whether the ray enters the object. An analytic sphere for now; a triangle
// mesh (the shared BVH of apps/common) can implement the same interface later.
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace gcsim::media {

struct BoundaryHit {
  double t;
  glm::dvec3 normal;  // faces the incoming ray: dot(d, normal) < 0
  bool entering;      // the ray goes from outside to inside
};

class Boundary {
 public:
  virtual ~Boundary() = default;
  // The closest hit with t in (t_min, t_max).
  virtual std::optional<BoundaryHit> intersect(const glm::dvec3& o, const glm::dvec3& d, double t_min,
                                               double t_max) const = 0;
  virtual bool inside(const glm::dvec3& p) const = 0;
};

class SphereBoundary final : public Boundary {
 public:
  SphereBoundary(glm::dvec3 centre, double radius) : centre_(centre), radius_(radius) {}
  std::optional<BoundaryHit> intersect(const glm::dvec3& o, const glm::dvec3& d, double t_min,
                                       double t_max) const override {
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
  bool inside(const glm::dvec3& p) const override {
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
