// The triangle-mesh boundary (the Stanford bunny through the shared float BVH): the closest hit and
// its side agree with brute force over every triangle, `inside` agrees with ray parity, paths leaving
// the surface (refraction, total internal reflection) stay on their side, a tessellated sphere
// matches the analytic one within the tessellation error, and bad meshes are refused by name.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <sstream>

#include "apps/common/geometry/triangle.hpp"
#include "apps/common/rng.hpp"
#include "apps/common/scene/obj_mesh.hpp"
#include "apps/media/fresnel.hpp"
#include "apps/media/builtin_scenes.hpp"
#include "apps/media/mesh_boundary.hpp"
#include "apps/common/media/sampling.hpp"
#include "apps/media/scene_data.hpp"

namespace gcsim::media {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const MeshBoundary& bunny() {
  static const auto mesh = load_mesh_boundary(find_scene_data("meshes/bunny.obj"), kBunnyPlacement);
  return *mesh;
}

glm::dvec3 random_direction(apps::Rng& rng) { return uniform_sphere(rng.uniform_double(), rng.uniform_double()); }

// A point of the box around the bunny's sphere (centre (0, −0.3, 0.5), radius 0.9), a little larger.
glm::dvec3 random_point_near_bunny(apps::Rng& rng) {
  return kBunnyPlacement.centre + glm::dvec3(rng.uniform_double() * 2 - 1, rng.uniform_double() * 2 - 1,
                                             rng.uniform_double() * 2 - 1);
}

// The closest hit over every triangle in float (the same watertight test, no tree).
struct BruteHit {
  bool found = false;
  float t = geometry::kInfinity;
  bool entering = false;
};
BruteHit brute_force(const MeshBoundary& m, const glm::dvec3& o, const glm::dvec3& d) {
  const geometry::Ray ray{glm::vec3(o), glm::vec3(d)};
  BruteHit best;
  for (const geometry::Triangle& tri : m.primitives().triangles) {
    float t, b1, b2;
    if (geometry::intersect_triangle(tri, ray, best.t, &t, &b1, &b2) && t < best.t) {
      best = {true, t, glm::dot(glm::dvec3(tri.geometric_normal()), d) < 0.0};
    }
  }
  return best;
}

// How many triangles a ray from o crosses ahead (no tree): odd inside a closed mesh.
int crossings(const MeshBoundary& m, const glm::dvec3& o, const glm::dvec3& d) {
  const geometry::Ray ray{glm::vec3(o), glm::vec3(d)};
  int n = 0;
  for (const geometry::Triangle& tri : m.primitives().triangles) {
    float t, b1, b2;
    n += geometry::intersect_triangle(tri, ray, geometry::kInfinity, &t, &b1, &b2);
  }
  return n;
}

TEST(MeshBoundary, ClosestHitAndSideAgreeWithBruteForce) {
  const MeshBoundary& m = bunny();
  ASSERT_EQ(m.primitives().triangles.size(), 3674u);
  apps::Rng rng(11, 1);
  int hits = 0, entering = 0;
  for (int i = 0; i < 3000; ++i) {
    const glm::dvec3 o = random_point_near_bunny(rng), d = random_direction(rng);
    BoundaryTally tally;
    const auto hit = m.intersect(o, d, 0.0, kInf, &tally);
    const BruteHit ref = brute_force(m, o, d);
    ASSERT_EQ(bool(hit), ref.found) << "ray " << i;
    EXPECT_GT(tally.node_tests, 0u);
    EXPECT_LT(tally.triangle_tests, 3674u / 4);  // the tree prunes most triangles
    if (!hit) continue;
    ++hits, entering += hit->entering;
    EXPECT_NEAR(hit->t, ref.t, 1e-5 * (1.0 + ref.t)) << "ray " << i;
    EXPECT_EQ(hit->entering, ref.entering) << "ray " << i;
    EXPECT_LT(glm::dot(d, hit->normal), 0.0);
    EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-12);
    // A limit before the hit hides it; a limit beyond keeps the same hit.
    EXPECT_FALSE(m.intersect(o, d, 0.0, hit->t * 0.999));
    const auto again = m.intersect(o, d, 0.0, hit->t * 1.001 + 1e-9);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->t, hit->t);
  }
  EXPECT_GT(hits, 400);  // both kinds occur often (507 hits, 197 of them exits)
  EXPECT_GT(entering, 150);
  EXPECT_GT(hits - entering, 150);
}

TEST(MeshBoundary, InsideAgreesWithRayParityInSeveralDirections) {
  const MeshBoundary& m = bunny();
  apps::Rng rng(12, 1);
  int inside = 0;
  for (int i = 0; i < 400; ++i) {
    const glm::dvec3 p = random_point_near_bunny(rng);
    const bool in = m.inside(p);
    inside += in;
    for (int k = 0; k < 4; ++k) {
      const glm::dvec3 d = random_direction(rng);
      EXPECT_EQ(crossings(m, p, d) % 2 == 1, in) << "point " << i << " direction " << k;
    }
  }
  EXPECT_GT(inside, 20);  // the bunny fills about a tenth of the box
  EXPECT_LT(inside, 380);
}

// Points inside the bunny, by rejection.
std::vector<glm::dvec3> points_inside(const MeshBoundary& m, int count, apps::Rng& rng) {
  std::vector<glm::dvec3> out;
  while (int(out.size()) < count) {
    const glm::dvec3 p = random_point_near_bunny(rng);
    if (m.inside(p)) out.push_back(p);
  }
  return out;
}

// Follows a ray through the bunny for 30 surface events or until it leaves for good: at each hit it
// refracts through (then it is on the other side, and a ray that went in finds its exit) or, at total
// internal reflection, reflects and stays inside: the photon tracer's crossing with leave_surface.
struct PathCounts {
  int total_reflections = 0, refractions_out = 0, refractions_in = 0;
};
void follow_path(const MeshBoundary& m, glm::dvec3 x, glm::dvec3 w, bool in, PathCounts& counts) {
  for (int event = 0; event < 30; ++event) {
    const auto hit = m.intersect(x, w, 0.0, kInf);
    if (!in && !hit) return;  // left the bunny for good
    ASSERT_TRUE(hit) << "a ray from inside found no exit (event " << event << ")";
    ASSERT_EQ(hit->entering, !in) << "event " << event;
    const glm::dvec3 at = x + hit->t * w;
    const double eta_i = in ? 1.5 : 1.0, eta_t = in ? 1.0 : 1.5;
    const auto refracted = refract_direction(w, hit->normal, eta_i, eta_t);
    counts.total_reflections += !refracted;
    (in ? counts.refractions_out : counts.refractions_in) += refracted.has_value();
    w = refracted ? *refracted : reflect_direction(w, hit->normal);
    x = m.leave_surface(at, *hit, w);
    if (refracted) in = !in;
    ASSERT_EQ(m.inside(x), in) << "event " << event << (refracted ? " after refraction" : " after reflection");
  }
}

TEST(MeshBoundary, PathsRefractingInAndOutAlwaysFindTheirExitAndStayOnTheirSide) {
  const MeshBoundary& m = bunny();
  apps::Rng rng(13, 1);
  PathCounts counts;
  for (const glm::dvec3& start : points_inside(m, 150, rng)) follow_path(m, start, random_direction(rng), true, counts);
  // From outside, aimed at a point inside: the ray refracts in, then must find its way out.
  for (const glm::dvec3& target : points_inside(m, 150, rng)) {
    const glm::dvec3 from = kBunnyPlacement.centre + 1.5 * random_direction(rng);
    follow_path(m, from, glm::normalize(target - from), false, counts);
  }
  EXPECT_GT(counts.total_reflections, 50);
  EXPECT_GT(counts.refractions_out, 200);
  EXPECT_GT(counts.refractions_in, 100);
}

// Total internal reflection every time, 40 bounces: the path never leaves the bunny.
TEST(MeshBoundary, RepeatedReflectionInsideKeepsThePathInside) {
  const MeshBoundary& m = bunny();
  apps::Rng rng(14, 1);
  for (const glm::dvec3& start : points_inside(m, 60, rng)) {
    glm::dvec3 x = start, w = random_direction(rng);
    for (int bounce = 0; bounce < 40; ++bounce) {
      const auto hit = m.intersect(x, w, 0.0, kInf);
      ASSERT_TRUE(hit) << "bounce " << bounce;
      ASSERT_FALSE(hit->entering) << "bounce " << bounce;
      const glm::dvec3 at = x + hit->t * w;
      w = reflect_direction(w, hit->normal);
      x = m.leave_surface(at, *hit, w);
      ASSERT_TRUE(m.inside(x)) << "bounce " << bounce;
    }
  }
}

// An icosphere, subdivided `levels` times, on the unit sphere.
scene::TriangleMesh icosphere(int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  scene::TriangleMesh m;
  for (const glm::dvec3 v : {glm::dvec3(-1, g, 0), glm::dvec3(1, g, 0), glm::dvec3(-1, -g, 0), glm::dvec3(1, -g, 0),
                             glm::dvec3(0, -1, g), glm::dvec3(0, 1, g), glm::dvec3(0, -1, -g), glm::dvec3(0, 1, -g),
                             glm::dvec3(g, 0, -1), glm::dvec3(g, 0, 1), glm::dvec3(-g, 0, -1), glm::dvec3(-g, 0, 1)})
    m.positions.push_back(glm::normalize(v));
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = midpoint.find(key); it != midpoint.end()) return it->second;
      m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
      return midpoint[key] = int(m.positions.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : m.triangles) {
      const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

TEST(MeshBoundary, TessellatedSphereMatchesTheAnalyticSphereWithinItsTessellationError) {
  const glm::dvec3 centre(0.2, -0.3, 0.5);
  const double radius = 0.9;
  const scene::TriangleMesh ico = icosphere(4);  // 5120 triangles
  // The icosahedron is symmetric about its centre, so placement keeps centre and radius.
  const MeshBoundary mesh(place_mesh(ico, {centre, radius, 0.0}), "icosphere");
  const SphereBoundary sphere(centre, radius);
  // How far a flat triangle lies inside the sphere: at most r (1 − cos of its longest vertex angle).
  double min_cos = 1.0;
  for (const auto& [a, b, c] : ico.triangles) {
    const glm::dvec3 mid = glm::normalize(ico.positions[a] + ico.positions[b] + ico.positions[c]);
    for (int v : {a, b, c}) min_cos = std::min(min_cos, glm::dot(mid, ico.positions[v]));
  }
  const double sagitta = radius * (1.0 - min_cos);
  ASSERT_LT(sagitta, 0.005);
  apps::Rng rng(15, 1);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 o = centre + 1.5 * (glm::dvec3(rng.uniform_double(), rng.uniform_double(), rng.uniform_double()) * 2.0 - 1.0);
    const glm::dvec3 d = random_direction(rng);
    const auto s = sphere.intersect(o, d, 0.0, kInf);
    const auto t = mesh.intersect(o, d, 0.0, kInf);
    if (!s) continue;
    const double cos_incidence = -glm::dot(d, s->normal);
    if (cos_incidence < 0.3) continue;  // near-grazing: the flat facets may miss or hit far off
    ASSERT_TRUE(t) << "ray " << i;
    EXPECT_EQ(t->entering, s->entering) << "ray " << i;
    EXPECT_NEAR(t->t, s->t, sagitta / cos_incidence + 1e-9) << "ray " << i;
    EXPECT_GT(glm::dot(t->normal, s->normal), min_cos - 1e-9) << "ray " << i;
    ++compared;
    const glm::dvec3 p = o + (0.5 + rng.uniform_double()) * s->t * d;  // around the surface
    const double r = glm::length(p - centre);
    if (std::abs(r - radius) > sagitta) {
      EXPECT_EQ(mesh.inside(p), sphere.inside(p)) << "point " << i;
    }
  }
  EXPECT_GT(compared, 300);
}

scene::TriangleMesh tetrahedron() {
  scene::TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};  // counter-clockwise seen from outside
  return m;
}

TEST(MeshBoundary, RefusesOpenInwardAndMissingMeshesByName) {
  EXPECT_NO_THROW(MeshBoundary(place_mesh(tetrahedron(), {}), "tet"));
  scene::TriangleMesh open = tetrahedron();
  open.triangles.pop_back();
  try {
    MeshBoundary(place_mesh(open, {}), "open.obj");
    FAIL() << "an open mesh was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("open.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("closed"), std::string::npos) << e.what();
  }
  scene::TriangleMesh inward = tetrahedron();
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  try {
    MeshBoundary(place_mesh(inward, {}), "inward.obj");
    FAIL() << "an inward mesh was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("inward.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inwards"), std::string::npos) << e.what();
  }
  try {
    load_mesh_boundary("/no/such/dir/bunny.obj", {});
    FAIL() << "a missing file was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/no/such/dir/bunny.obj"), std::string::npos) << e.what();
  }
  try {
    find_scene_data("meshes/no-such-mesh.obj");
    FAIL() << "a missing data file was found";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("meshes/no-such-mesh.obj"), std::string::npos) << e.what();
  }
}

// The placement: the bunny's farthest vertex is 0.9 from (0, −0.3, 0.5), its box centred there.
TEST(MeshBoundary, PlacementFitsTheSphereItReplaces) {
  glm::dvec3 lo(kInf), hi(-kInf);
  double far = 0.0;
  for (const auto& tri : bunny().primitives().triangles)
    for (const glm::vec3& v : {tri.p0, tri.p1, tri.p2}) {
      lo = glm::min(lo, glm::dvec3(v)), hi = glm::max(hi, glm::dvec3(v));
      far = std::max(far, glm::length(glm::dvec3(v) - kBunnyPlacement.centre));
    }
  EXPECT_NEAR(far, kBunnyPlacement.radius, 1e-6);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(0.5 * (lo[a] + hi[a]), kBunnyPlacement.centre[a], 1e-6);
}

}  // namespace
}  // namespace gcsim::media
