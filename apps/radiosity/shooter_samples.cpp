#include "apps/radiosity/shooter_samples.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

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

double point_form_factor_in_front(const Vec3& x, const Vec3& n, const Polygon& polygon) {
  // Clip to the half-space in front of the point (a quad cut by a plane has at most 5 corners).
  Vec3 part[5];
  int m = 0;
  for (int i = 0; i < polygon.count; ++i) {
    const Vec3 a = polygon.v[i] - x, b = polygon.v[(i + 1) % polygon.count] - x;
    const double da = glm::dot(a, n), db = glm::dot(b, n);
    if (da >= 0) part[m++] = a;
    if ((da >= 0) != (db >= 0)) part[m++] = a + (b - a) * (da / (da - db));
  }
  // Lambert's contour integral: sum over edges of the angle they subtend times their plane's tilt.
  double sum = 0;
  for (int i = 0; i < m; ++i) {
    const Vec3& a = part[i];
    const Vec3& b = part[(i + 1) % m];
    const Vec3 c = glm::cross(a, b);
    const double lc = glm::length(c);
    if (lc == 0) continue;
    sum += std::atan2(lc, glm::dot(a, b)) * glm::dot(n, c) / lc;
  }
  return std::abs(sum) / (2 * std::numbers::pi);
}

namespace {

// The elements a patch's point sampling can misjudge (facing it, in front of it, near it), and how
// many elements each of its samples projects (every one in front of it).
std::vector<int> near_receivers(const Scene& scene, int patch, std::int64_t* in_front_count) {
  const ScenePatch& sp = scene.patches[patch];
  const double eps = 1e-12 * scene.extent(), reach = kNearFieldReach * diameter(sp.polygon);
  std::vector<int> near;
  *in_front_count = 0;
  for (int e = 0; e < int(scene.elements.size()); ++e) {
    const SceneElement& el = scene.elements[e];
    if (el.patch == patch) continue;
    bool in_front = false;
    for (int k = 0; k < el.count; ++k) in_front |= glm::dot(el.polygon.v[k] - sp.center, sp.normal) > eps;
    if (!in_front) continue;
    ++*in_front_count;
    if (glm::dot(el.normal, sp.center - el.polygon.v[0]) > eps && distance_to_polygon(sp.center, el.polygon) < reach)
      near.push_back(e);
  }
  return near;
}

// F(patch -> e) for each near element e by the n x n midpoint rule.
std::vector<double> sampled_form_factors(const Scene& scene, int patch, const std::vector<int>& near, int n) {
  std::vector<double> f(near.size(), 0.0);
  for (const ShooterSample& s : shooter_samples(scene.patches[patch], n))
    for (std::size_t k = 0; k < near.size(); ++k)
      f[k] += s.weight * point_form_factor_in_front(s.point, scene.patches[patch].normal, scene.elements[near[k]].polygon);
  return f;
}

}  // namespace

std::vector<int> shooter_samples_per_side(const Scene& scene, double tolerance, int max_per_side,
                                          std::int64_t pixel_budget) {
  std::vector<int> per_side(scene.patches.size(), 1);
  for (int p = 0; p < int(scene.patches.size()) && max_per_side > 1; ++p) {
    std::int64_t projected = 0;
    const std::vector<int> near = near_receivers(scene, p, &projected);
    if (near.empty()) continue;
    // 2 x 2 points are always allowed (the projections grow 4 times); more within the budget.
    int affordable = 2;
    while (affordable < max_per_side &&
           std::int64_t(4) * affordable * affordable * projected * kProjectionPixels <= pixel_budget)
      affordable *= 2;
    int n = 1;
    std::vector<double> coarse = sampled_form_factors(scene, p, near, n);
    while (n < affordable) {
      const std::vector<double> fine = sampled_form_factors(scene, p, near, 2 * n);
      double change = 0;
      for (std::size_t k = 0; k < near.size(); ++k) change += std::abs(fine[k] - coarse[k]);
      if (change <= tolerance) break;
      n *= 2;
      coarse = fine;
    }
    per_side[p] = n;
  }
  return per_side;
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
