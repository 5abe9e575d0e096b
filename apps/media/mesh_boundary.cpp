#include "apps/media/mesh_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "apps/common/geometry/traversal.hpp"
#include "apps/common/scene/obj_mesh.hpp"

namespace gcsim::media {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Every edge used once in each direction: the mesh is closed and its triangles wound alike.
void check_closed(const scene::TriangleMesh& mesh, const std::string& source) {
  auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
  std::unordered_map<std::uint64_t, int> directed;
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      throw std::invalid_argument(source + ": a triangle repeats a vertex (" + std::to_string(t[0] + 1) + " " +
                                  std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1) + ")");
    for (int e = 0; e < 3; ++e) ++directed[key(t[e], t[(e + 1) % 3])];
  }
  for (const auto& [edge, count] : directed) {
    const int a = int(edge >> 32), b = int(edge & 0xffffffffu);
    const auto reverse = directed.find(key(b, a));
    if (count != 1 || reverse == directed.end() || reverse->second != 1)
      throw std::invalid_argument(source + ": edge " + std::to_string(a + 1) + "-" + std::to_string(b + 1) +
                                  " is not shared by exactly two triangles wound alike: the object's mesh must be "
                                  "closed and consistently wound");
  }
}

double signed_volume(const std::vector<glm::dvec3>& p, const scene::TriangleMesh& mesh) {
  double six_v = 0.0;
  for (const auto& t : mesh.triangles) six_v += glm::dot(p[t[0]], glm::cross(p[t[1]], p[t[2]]));
  return six_v / 6.0;
}

}  // namespace

scene::TriangleMesh place_mesh(const scene::TriangleMesh& mesh, const MeshPlacement& placement) {
  glm::dvec3 lo(kInf), hi(-kInf);
  for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::dvec3 middle = 0.5 * (lo + hi);
  double far = 0.0;
  for (const glm::dvec3& p : mesh.positions) far = std::max(far, glm::length(p - middle));
  const double scale = far > 0.0 ? placement.radius / far : 1.0;
  const double a = glm::radians(placement.rotate_y_degrees), c = std::cos(a), s = std::sin(a);
  scene::TriangleMesh out{{}, mesh.triangles};
  out.positions.reserve(mesh.positions.size());
  for (const glm::dvec3& p : mesh.positions) {
    const glm::dvec3 v = scale * (p - middle);
    out.positions.push_back(placement.centre + glm::dvec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z));
  }
  return out;
}

namespace {

void count(BoundaryTally* tally, const geometry::TestTally& t) {
  if (!tally) return;
  tally->node_tests += std::uint64_t(t.boxes);
  tally->triangle_tests += std::uint64_t(t.triangles);
}

}  // namespace

MeshBoundary::MeshBoundary(const scene::TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangles.empty()) throw std::invalid_argument(source + ": the object's mesh has no triangles");
  check_closed(mesh, source);
  const std::vector<glm::dvec3>& p = mesh.positions;
  if (!(signed_volume(p, mesh) > 0.0))
    throw std::invalid_argument(source + ": the mesh is wound inwards (negative signed volume); the object's "
                                "triangles must be counter-clockwise seen from outside");
  double extent = 0.0;
  for (const auto& t : mesh.triangles) {
    prims_.triangles.push_back({glm::vec3(p[t[0]]), glm::vec3(p[t[1]]), glm::vec3(p[t[2]])});
    for (int k = 0; k < 3; ++k) extent = std::max(extent, glm::length(p[t[k]]));
  }
  bvh_ = geometry::build_bvh_by_clustering(prims_);
  // 2^-16 of the largest coordinate: 512 float ulps there, far beyond the rounding of a float ray
  // origin (half an ulp) and of the watertight test's distance near its plane (a few ulps), far
  // below the inside medium's mean free path (1/200 in experiment 2).
  offset_ = std::ldexp(std::max(extent, 1.0), -16);
}

std::optional<BoundaryHit> MeshBoundary::intersect(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max,
                                                   BoundaryTally* tally) const {
  geometry::Ray ray(glm::vec3(o), glm::vec3(d), static_cast<float>(t_min));
  geometry::Hit hit;
  // Searched a little beyond t_max in float; whether the hit counts is decided on the double distance.
  const double reach = t_max * (1.0 + 1e-5) + offset_;
  hit.t = reach < double(std::numeric_limits<float>::max()) ? static_cast<float>(reach) : geometry::kInfinity;
  geometry::TestTally tests;
  geometry::traverse_ordered(prims_, bvh_.packed, ray, hit, tests);
  count(tally, tests);
  if (!hit.valid()) return std::nullopt;
  const geometry::Triangle& tri = prims_.triangles[static_cast<std::size_t>(hit.prim)];
  const glm::dvec3 p0(tri.p0);
  const glm::dvec3 n = glm::normalize(glm::cross(glm::dvec3(tri.p1) - p0, glm::dvec3(tri.p2) - p0));
  const double dn = glm::dot(d, n);
  // The distance to the triangle's plane in double, so the hit point lies on it; a ray nearly in
  // the plane (where that is ill-conditioned) keeps the float distance.
  double t = hit.t;
  const double t_plane = dn != 0.0 ? glm::dot(p0 - o, n) / dn : kInf;
  if (std::abs(t_plane - t) <= 1e-4 * (std::abs(t) + 1.0)) t = t_plane;
  if (t >= t_max) return std::nullopt;
  t = std::max(t, std::nextafter(t_min, kInf));
  const bool entering = dn < 0.0;
  return BoundaryHit{t, entering ? n : -n, entering};
}

bool MeshBoundary::inside(const glm::dvec3& p, BoundaryTally* tally) const {
  // Three directions with no zero component and no simple ratio between them.
  static const glm::dvec3 kDirections[3] = {glm::normalize(glm::dvec3(0.5773, 0.6123, 0.5403)),
                                            glm::normalize(glm::dvec3(-0.7071, 0.3217, -0.6293)),
                                            glm::normalize(glm::dvec3(0.2113, -0.8941, 0.3947))};
  int in = 0, out = 0;
  for (const glm::dvec3& d : kDirections) {
    const auto hit = intersect(p, d, 0.0, kInf, tally);
    if (hit && !hit->entering) ++in;
    else ++out;
    if (in == 2) return true;
    if (out == 2) return false;
  }
  return false;  // not reached: three votes always make a majority
}

glm::dvec3 MeshBoundary::leave_surface(const glm::dvec3& at, const BoundaryHit& hit, const glm::dvec3& direction) const {
  const double side = glm::dot(direction, hit.normal) >= 0.0 ? 1.0 : -1.0;
  return at + side * offset_ * hit.normal;
}

std::shared_ptr<MeshBoundary> load_mesh_boundary(const std::filesystem::path& file, const MeshPlacement& placement) {
  if (!std::filesystem::is_regular_file(file))
    throw std::runtime_error("media object mesh '" + file.string() + "': no such file");
  return std::make_shared<MeshBoundary>(place_mesh(scene::load_obj_mesh(file), placement), file.string());
}

}  // namespace gcsim::media
