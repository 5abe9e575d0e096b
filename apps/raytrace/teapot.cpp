#include "apps/raytrace/teapot.hpp"

#include <cmath>
#include <map>
#include <tuple>

#include "apps/raytrace/teapot_data.hpp"

namespace gcsim::raytrace {
namespace {

glm::dvec3 bezier(double t, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  const double s = 1.0 - t;
  return s * s * s * a + 3.0 * s * s * t * b + 3.0 * s * t * t * c + t * t * t * d;
}

glm::dvec3 control_point(int patch, int i, int j) {
  const float* p = teapot_data::kPoints[teapot_data::kPatches[patch][i * 4 + j] - 1];
  return {p[0], p[1], p[2]};
}

// Neighbouring patches evaluate a shared edge with their parameters in opposite directions, so
// the results differ in the last bits; snapping to a 2^-20 grid makes them identical, which keeps
// the mesh watertight across patch seams.
glm::vec3 snap(const glm::dvec3& p) {
  constexpr double q = 1048576.0;
  return glm::vec3(std::round(p.x * q) / q, std::round(p.y * q) / q, std::round(p.z * q) / q);
}

}  // namespace

TeapotMesh make_teapot(int n) {
  TeapotMesh mesh;
  using Key = std::tuple<float, float, float>;
  std::map<Key, glm::vec3> normal_sum;
  for (int patch = 0; patch < teapot_data::kPatchCount; ++patch) {
    std::vector<glm::vec3> grid(std::size_t(n + 1) * (n + 1));
    for (int a = 0; a <= n; ++a)
      for (int b = 0; b <= n; ++b) {
        const double u = double(a) / n, v = double(b) / n;
        glm::dvec3 rows[4];
        for (int i = 0; i < 4; ++i)
          rows[i] = bezier(v, control_point(patch, i, 0), control_point(patch, i, 1), control_point(patch, i, 2),
                           control_point(patch, i, 3));
        grid[std::size_t(a) * (n + 1) + b] = snap(bezier(u, rows[0], rows[1], rows[2], rows[3]));
      }
    auto at = [&](int a, int b) { return grid[std::size_t(a) * (n + 1) + b]; };
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const glm::vec3 p00 = at(a, b), p10 = at(a + 1, b), p01 = at(a, b + 1), p11 = at(a + 1, b + 1);
        for (const Triangle& t : {Triangle{p00, p10, p11}, Triangle{p00, p11, p01}}) {
          if (t.p0 == t.p1 || t.p1 == t.p2 || t.p2 == t.p0) continue;  // collapsed at a pole
          mesh.triangles.push_back(t);
        }
      }
  }
  // Smooth normals: area-weighted face normals summed at each (snapped, hence shared) position.
  for (const Triangle& t : mesh.triangles) {
    const glm::vec3 g = t.geometric_normal();
    for (const glm::vec3& p : {t.p0, t.p1, t.p2}) normal_sum[{p.x, p.y, p.z}] += g;
  }
  for (const Triangle& t : mesh.triangles) {
    Scene::VertexNormals vn;
    glm::vec3* out[3] = {&vn.n0, &vn.n1, &vn.n2};
    const glm::vec3 ps[3] = {t.p0, t.p1, t.p2};
    const glm::vec3 g = glm::normalize(t.geometric_normal());
    for (int i = 0; i < 3; ++i) {
      glm::vec3 s = normal_sum[{ps[i].x, ps[i].y, ps[i].z}];
      const float len = glm::length(s);
      *out[i] = len > 0 ? s / len : g;
    }
    mesh.normals.push_back(vn);
  }
  return mesh;
}

}  // namespace gcsim::raytrace
