#include "apps/radiosity/shooter_samples.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gcsim::radiosity {

namespace {

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

double diameter(const Polygon& polygon) {
  double d = 0;
  for (int i = 0; i < polygon.count; ++i)
    for (int j = i + 1; j < polygon.count; ++j) d = std::max(d, glm::length(polygon.v[i] - polygon.v[j]));
  return d;
}

// Bilinear point of a quad (a triangle repeats its last vertex) at (s, t) in [0, 1]^2.
Vec3 bilinear(const Polygon& q, double s, double t) {
  const Vec3& v3 = q.count == 4 ? q.v[3] : q.v[2];
  return (1 - s) * (1 - t) * q.v[0] + s * (1 - t) * q.v[1] + s * t * q.v[2] + (1 - s) * t * v3;
}

}  // namespace

double distance_to_polygon(const Vec3& p, const Polygon& polygon) {
  const Vec3 n = polygon_normal(polygon);
  const Vec3 foot = p - glm::dot(p - polygon.v[0], n) * n;
  // Inside when the foot lies on the inner side of every edge (convex polygon, either winding).
  int positive = 0, negative = 0;
  double nearest_edge = std::numeric_limits<double>::infinity();
  for (int i = 0; i < polygon.count; ++i) {
    const Vec3& a = polygon.v[i];
    const Vec3& b = polygon.v[(i + 1) % polygon.count];
    const double side = glm::dot(glm::cross(b - a, foot - a), n);
    positive += side > 0, negative += side < 0;
    nearest_edge = std::min(nearest_edge, distance_to_segment(p, a, b));
  }
  if (positive == 0 || negative == 0) return std::abs(glm::dot(p - polygon.v[0], n));
  return nearest_edge;
}

std::vector<int> shooter_samples_per_side(const Scene& scene, double ratio, int max_per_side) {
  std::vector<int> per_side(scene.patches.size(), 1);
  if (max_per_side <= 1) return per_side;
  const double eps = 1e-12 * scene.extent();
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const ScenePatch& sp = scene.patches[p];
    double nearest = std::numeric_limits<double>::infinity();
    for (const SceneElement& el : scene.elements) {
      if (el.patch == int(p)) continue;
      bool in_front = false;
      for (int k = 0; k < el.count; ++k) in_front |= glm::dot(el.polygon.v[k] - sp.center, sp.normal) > eps;
      if (in_front) nearest = std::min(nearest, distance_to_polygon(sp.center, el.polygon));
    }
    const double need = diameter(sp.polygon) / (ratio * std::max(nearest, eps));
    int n = 1;
    while (n < max_per_side && n < need) n *= 2;
    per_side[p] = std::min(n, max_per_side);
  }
  return per_side;
}

std::shared_ptr<const std::vector<int>> SamplesPerSideMemo::get(const Scene& scene, double ratio, int max_per_side) {
  const bool same = table_ && scene_ == &scene && patches_ == scene.patches.size() &&
                    elements_ == scene.elements.size() && extent_ == scene.extent() && ratio_ == ratio &&
                    max_per_side_ == max_per_side;
  if (!same) {
    table_ = std::make_shared<const std::vector<int>>(shooter_samples_per_side(scene, ratio, max_per_side));
    scene_ = &scene, patches_ = scene.patches.size(), elements_ = scene.elements.size(), extent_ = scene.extent();
    ratio_ = ratio, max_per_side_ = max_per_side;
    ++computed_;
  }
  return table_;
}

std::vector<ShooterSample> shooter_samples(const ScenePatch& patch, int n) {
  if (n <= 1) return {{patch.center, 1.0}};
  std::vector<ShooterSample> out;
  double total = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double s0 = double(i) / n, s1 = double(i + 1) / n, t0 = double(j) / n, t1 = double(j + 1) / n;
      Polygon part;
      part.count = 4;
      part.v = {bilinear(patch.polygon, s0, t0), bilinear(patch.polygon, s1, t0), bilinear(patch.polygon, s1, t1),
                bilinear(patch.polygon, s0, t1)};
      const double area = polygon_area(part);
      out.push_back({bilinear(patch.polygon, 0.5 * (s0 + s1), 0.5 * (t0 + t1)), area});
      total += area;
    }
  for (auto& s : out) s.weight /= total;
  return out;
}

}  // namespace gcsim::radiosity
