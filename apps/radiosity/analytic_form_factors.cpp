#include "apps/radiosity/analytic_form_factors.hpp"

#include <cmath>
#include <numbers>

#include "apps/radiosity/entity_builder.hpp"

namespace gcsim::radiosity {

using std::numbers::pi;

double point_to_polygon_form_factor(const Vec3& x, const Vec3& n, const Polygon& poly) {
  double sum = 0;
  for (int i = 0; i < poly.count; ++i) {
    Vec3 a = poly.v[i] - x, b = poly.v[(i + 1) % poly.count] - x;
    Vec3 c = glm::cross(a, b);
    double lc = glm::length(c);
    if (lc == 0) continue;
    double gamma = std::atan2(lc, glm::dot(a, b));
    sum += gamma * glm::dot(n, c) / lc;
  }
  return std::abs(sum) / (2 * pi);
}

double parallel_rectangles_form_factor(double a, double b, double c) {
  double x = a / c, y = b / c;
  double x2 = 1 + x * x, y2 = 1 + y * y;
  return 2 / (pi * x * y) *
         (0.5 * std::log(x2 * y2 / (x2 + y * y)) + x * std::sqrt(y2) * std::atan(x / std::sqrt(y2)) +
          y * std::sqrt(x2) * std::atan(y / std::sqrt(x2)) - x * std::atan(x) - y * std::atan(y));
}

double perpendicular_rectangles_form_factor(double l, double w, double h) {
  double W = w / l, H = h / l, W2 = W * W, H2 = H * H, s = std::sqrt(H2 + W2);
  double t1 = (1 + W2) * (1 + H2) / (1 + W2 + H2);
  double t2 = std::pow(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2)), W2);
  double t3 = std::pow(H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2)), H2);
  return 1 / (pi * W) *
         (W * std::atan(1 / W) + H * std::atan(1 / H) - s * std::atan(1 / s) + 0.25 * std::log(t1 * t2 * t3));
}

double point_to_disc_form_factor(double r, double h) { return r * r / (h * h + r * r); }

const char* to_string(FormFactorCase c) {
  switch (c) {
    case FormFactorCase::parallel_squares: return "parallel unit squares, distance 1";
    case FormFactorCase::perpendicular_squares: return "perpendicular unit squares, common edge";
    default: return "small patch facing a disc (256-gon, r = h = 1)";
  }
}

FormFactorSetup form_factor_setup(FormFactorCase c, double s, int n) {
  World w;
  w.name = to_string(c);
  EntityBuilder b("form factor case");
  int surf = b.surface({0.5, 0.5, 0.5}, {1, 1, 1});
  FormFactorSetup out;
  Polygon receiver;
  receiver.count = 4;
  if (c == FormFactorCase::parallel_squares) {
    // Source in z = 0 facing +z, receiver in z = 1 facing -z.
    b.quad({{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}}, {0, 0, 1}, n, n, 1, 1, surf);
    b.quad({{0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}}, {0, 0, -1}, 1, 1, 4, 4, surf);
    receiver.v = {Vec3{0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}};
    out.exact_area = parallel_rectangles_form_factor(1, 1, 1);
  } else if (c == FormFactorCase::perpendicular_squares) {
    // Source in z = 0 facing +z, receiver in x = 0 facing +x, sharing the edge x = z = 0.
    b.quad({{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}}, {0, 0, 1}, n, n, 1, 1, surf);
    b.quad({{0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}}, {1, 0, 0}, 1, 1, 4, 4, surf);
    receiver.v = {Vec3{0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}};
    out.exact_area = perpendicular_rectangles_form_factor(1, 1, 1);
  } else {
    // A 1% patch at the origin facing +z; a disc of radius 1 at height 1 as a fan of 256 triangles.
    // The point value is exact for that polygon; the disc's own closed form is the area column.
    double e = 0.01 * s;
    b.quad({{-e / 2, -e / 2, 0}, {e / 2, -e / 2, 0}, {e / 2, e / 2, 0}, {-e / 2, e / 2, 0}}, {0, 0, 1}, 1, 1, 1, 1, surf);
    EntityBuilder& d = b;
    const int m = 256;
    int centre = d.add_vertex({0, 0, s});
    int first = -1;
    for (int k = 0; k < m; ++k) {
      double a = 2 * pi * k / m;
      int v = d.add_vertex({s * std::cos(a), s * std::sin(a), s});
      if (first < 0) first = v;
    }
    Entity ent = d.take();
    ent.patches.push_back({surf, {centre, first, first + m / 2, 0}, 3});  // the patch outline is only for bookkeeping
    int disc_patch = int(ent.patches.size()) - 1;
    for (int k = 0; k < m; ++k) {
      // Clockwise seen from above, so the triangles face -z (towards the small patch).
      ent.elements.push_back({disc_patch, {centre, first + (k + 1) % m, first + k, 0}, 3});
    }
    // The disc patch polygon: a triangle spanning the disc, facing -z like its elements.
    ent.patches[disc_patch].vertex = {centre, first + m / 4, first, 0};
    w.entities.push_back(std::move(ent));
    w.instances.push_back({0, {}});
    out.scene = flatten(w);
    out.receiver_patch = disc_patch;
    // Lambert's formula triangle by triangle (the triangles do not overlap, so their sum is exact).
    out.exact_point = 0;
    for (int k = 0; k < m; ++k) {
      Polygon t;
      t.count = 3;
      t.v = {out.scene.vertices[centre], out.scene.vertices[first + k], out.scene.vertices[first + (k + 1) % m], Vec3(0.0)};
      out.exact_point += point_to_polygon_form_factor({0, 0, 0}, {0, 0, 1}, t);
    }
    out.exact_area = point_to_disc_form_factor(1, 1);
    return out;
  }
  w.entities.push_back(b.take());
  w.instances.push_back({0, {}});
  out.scene = flatten(w);
  out.receiver_patch = n * n;
  const ScenePatch& p0 = out.scene.patches[0];
  // Point value from the centre of the whole source square (patch 0 when n = 1).
  Vec3 centre = n == 1 ? p0.center : Vec3(s / 2, s / 2, 0);
  out.exact_point = point_to_polygon_form_factor(centre, {0, 0, 1}, receiver);
  return out;
}

}  // namespace gcsim::radiosity
