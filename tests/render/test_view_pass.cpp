// The unified renderer's view pass: the radiosity pass's solution seen through the ray tracer.
// Its radiosity pass is the radiosity program (same radiosities, same simulated time); its image
// agrees with the Gouraud display of the same solution, shows a uniform radiosity as exactly its
// exposed value, tells a polygon's back from its front, and is the same on any node count.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <array>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_file.hpp"
#include "apps/render/plan.hpp"
#include "apps/radiosity/gouraud_renderer.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/raytrace/pixel_encoding.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/render/unified_render.hpp"
#include "apps/render/view_scene.hpp"
#include "parix/sim/simulated_runtime.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::render {
namespace {

scene::SceneDescription scene_file(const char* name) {
  return scene::load_scene_file(std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / name);
}

radiosity::ParallelOptions small_solve() {
  radiosity::ParallelOptions o;
  o.solver.hemicube.resolution = 32;
  o.solver.energy = 0.9;
  return o;
}

using test_support::published_machine;

struct ViewRendered {
  std::unique_ptr<UnifiedRender> out;
  parix::RunResult run;
};

ViewRendered render_on(const scene::SceneDescription& d, const radiosity::Scene* mesh, int nodes, ViewSettings view = {}) {
  ViewRendered r{std::make_unique<UnifiedRender>(nodes), {}};
  const radiosity::ParallelOptions o = small_solve();
  r.run = parix::run_simulated(published_machine(nodes), [&](parix::Processor& p) { unified_render_program(p, d, mesh, o, view, nullptr, *r.out); });
  finish(*r.out);
  return r;
}

scene::SceneDescription small_image(scene::SceneDescription d) {
  d.image.width = d.image.height = 64;
  return d;
}

TEST(ViewPass, RadiosityPassIsTheRadiosityProgram) {
  const auto d = small_image(scene_file("cornell.toml"));
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
  const ViewRendered unified = render_on(d, &mesh, 2);
  radiosity::ParallelOutcome alone;
  const auto run = parix::run_simulated(published_machine(2), [&](parix::Processor& p) {
    radiosity::radiosity_program(p, mesh, small_solve(), &alone);
  });
  EXPECT_EQ(unified.out->radiosity.element_radiosity, alone.element_radiosity);
  EXPECT_EQ(unified.out->radiosity_seconds(), run.simulated_seconds());
  EXPECT_GT(unified.run.simulated_seconds(), run.simulated_seconds());  // the view pass comes after
}

TEST(ViewPass, ImageIsTheSameOnAnyNodeCount) {
  const auto d = small_image(scene_file("cornell-mirror-glass.toml"));
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
  const ViewRendered one = render_on(d, &mesh, 1), three = render_on(d, &mesh, 3);
  ASSERT_EQ(one.out->view->result.image.pixels().size(), three.out->view->result.image.pixels().size());
  EXPECT_EQ(one.out->view->result.image.pixels(), three.out->view->result.image.pixels());
  EXPECT_EQ(one.out->view->scene.sphere_count(), 2);  // the mirror and the glass, as true spheres
}

// Seen from the scene's camera, the ray-traced view of CORNELL's solution and the radiosity app's
// Gouraud display of it (same exposure) differ only along edges, where the two rasterize a pixel
// from different sides.
TEST(ViewPass, CornellAgreesWithTheGouraudDisplay) {
  const auto d = small_image(scene_file("cornell.toml"));
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
  const ViewRendered r = render_on(d, &mesh, 2);
  radiosity::RenderOptions ro;
  ro.width = ro.height = 64;
  ro.exposure = r.out->view->exposure;
  const apps::Image gouraud = radiosity::render_gouraud(mesh, r.out->radiosity.element_radiosity, *mesh.camera, ro);
  const apps::Image& view = r.out->view->result.image;
  int far = 0, n = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x, ++n)
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(raytrace::encode_srgb8(view.at(x, y)[c])) - int(raytrace::encode_srgb8(gouraud.at(x, y)[c]))) > 8) {
          ++far;
          break;
        }
  EXPECT_LT(far, n / 10) << far << " of " << n << " pixels differ by more than 8 of 255";
}

// Every element at the same radiosity B: every pixel that sees an element is exactly B x exposure.
TEST(ViewPass, UniformRadiosityShowsAsItsExposedValue) {
  const auto d = small_image(scene_file("cornell.toml"));
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
  const std::vector<radiosity::Rgb> b(mesh.elements.size(), radiosity::Rgb(0.25, 0.5, 0.125));
  const raytrace::Scene view = make_view_scene(d, mesh, b, 2.0);
  raytrace::RenderSettings s;
  s.width = s.height = 64;
  s.shading = raytrace::Shading::whitted;
  const raytrace::RenderOutput out = raytrace::render_image(view, geometry::build_bvh_by_clustering(view), s);
  int seen = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      if (out.prim_ids[std::size_t(y) * 64 + x] < 0) continue;
      ++seen;
      const glm::vec3 c = out.image.at(x, y);
      ASSERT_NEAR(c.r, 0.5f, 1e-6f);
      ASSERT_NEAR(c.g, 1.0f, 1e-6f);
      ASSERT_NEAR(c.b, 0.25f, 1e-6f);
    }
  EXPECT_GT(seen, 64 * 64 / 2);
}

// --force-pass: the plan turns off the shadow rays of direct-light.toml (a single plane cannot
// shadow itself) and its secondary rays (no mirror or glass); casting them anyway costs simulated
// time and changes no pixel. Likewise forced on in CORNELL, which has neither point lights nor
// mirrors.
TEST(ViewPass, ForcingAPassThePlanSkipsChangesNoPixel) {
  for (const char* file : {"direct-light.toml", "cornell.toml"}) {
    SCOPED_TRACE(file);
    const auto d = small_image(scene_file(file));
    const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
    const bool radiosity = std::string(file) == "cornell.toml";
    const ViewRendered planned = render_on(d, radiosity ? &mesh : nullptr, 2, ViewSettings{false, false});
    const ViewRendered forced = render_on(d, radiosity ? &mesh : nullptr, 2, ViewSettings{true, true});
    EXPECT_EQ(planned.out->view->result.image.pixels(), forced.out->view->result.image.pixels());
    EXPECT_EQ(planned.out->view->result.counters.shadow_rays, 0);
    if (!radiosity) {
      EXPECT_GT(forced.out->view->result.counters.shadow_rays, 0);
      EXPECT_GT(forced.run.makespan, planned.run.makespan);
    }
  }
}

// A checkerboard lies in the plane of its surface: a floor facing +y (direct-light.toml's) shows
// squares, changing colour along x and along z, not stripes along one of them.
TEST(ViewPass, CheckerboardSquaresLieInTheFloorsPlane) {
  raytrace::Scene s;
  raytrace::Material floor;
  floor.diffuse = glm::vec3(1.0f);
  floor.checker_other = glm::vec3(0.0f);
  floor.checker_size = 1.0f;
  const int m = s.add_material(floor);
  s.add_triangle(raytrace::Triangle{{-8, 0, -8}, {-8, 0, 8}, {8, 0, 8}}, m);
  s.add_triangle(raytrace::Triangle{{-8, 0, -8}, {8, 0, 8}, {8, 0, -8}}, m);
  s.ambient = glm::vec3(1.0f);
  s.camera = scene::Camera{{0.25, 10, 0.25}, {0.25, 0, 0.2500001}, {0, 0, 1}, 60};
  raytrace::RenderSettings rs;
  rs.width = rs.height = 32;
  const raytrace::RenderOutput out = raytrace::render_image(s, geometry::build_bvh_by_clustering(s), rs);
  auto changes = [&](bool along_x) {
    int n = 0;
    for (int k = 1; k < 32; ++k) {
      const glm::vec3 a = along_x ? out.image.at(k - 1, 16) : out.image.at(16, k - 1);
      const glm::vec3 b = along_x ? out.image.at(k, 16) : out.image.at(16, k);
      n += a != b;
    }
    return n;
  };
  EXPECT_GE(changes(true), 4);
  EXPECT_GE(changes(false), 4);
}

// A triangle shows its front radiance to rays that meet its front, its back radiance otherwise.
TEST(ViewPass, GivenRadianceHasTwoSides) {
  raytrace::Scene s;
  raytrace::Material lit;
  lit.given_radiance = true;
  s.add_triangle(raytrace::Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, s.add_material(lit));  // normal +z
  const glm::vec3 red(1, 0, 0), blue(0, 0, 1);
  s.triangle_radiance.push_back({{red, red, red}, {blue, blue, blue}});
  s.validate();
  EXPECT_EQ(s.given_radiance(raytrace::Ray({0.2f, 0.2f, 1}, {0, 0, -1}), 0, 0.2f, 0.2f), red);
  EXPECT_EQ(s.given_radiance(raytrace::Ray({0.2f, 0.2f, -1}, {0, 0, 1}), 0, 0.2f, 0.2f), blue);
  s.triangle_radiance.clear();
  EXPECT_THROW(s.validate(), std::invalid_argument);  // given radiance with none given
}

// The light of cornell-mirror-glass.toml is a two-sided polygon (emitter below, black housing
// above) on the same vertices: it becomes one set of triangles, never two coincident ones.
TEST(ViewPass, APolygonsBackIsNotASecondCoincidentSurface) {
  const auto d = scene_file("cornell-mirror-glass.toml");
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
  const std::vector<radiosity::Rgb> b(mesh.elements.size(), radiosity::Rgb(1.0));
  const raytrace::Scene view = make_view_scene(d, mesh, b, 1.0);
  std::set<std::array<float, 9>> seen;
  for (const raytrace::Triangle& t : view.triangles) {
    std::array<glm::vec3, 3> v{t.p0, t.p1, t.p2};
    std::sort(v.begin(), v.end(), [](const glm::vec3& a, const glm::vec3& c) {
      return std::tie(a.x, a.y, a.z) < std::tie(c.x, c.y, c.z);
    });
    EXPECT_TRUE(seen.insert({v[0].x, v[0].y, v[0].z, v[1].x, v[1].y, v[1].z, v[2].x, v[2].y, v[2].z}).second);
  }
}

}  // namespace
}  // namespace gcsim::render

namespace gcsim::render {
namespace {

// A point light inside CORNELL: on the radiosity-lit walls it adds its direct light (times the
// same exposure), exactly rho I cos / d^2 on a triangle in the open, nothing where it is shadowed.
TEST(ViewPass, PointLightsAddTheirDirectLightToRadiositySurfaces) {
  raytrace::Scene s;
  raytrace::Material lit;
  lit.given_radiance = true;
  lit.diffuse = glm::vec3(0.5f, 0.25f, 1.0f);
  s.add_triangle(raytrace::Triangle{{-10, -10, 0}, {10, -10, 0}, {-10, 10, 0}}, s.add_material(lit));  // faces +z
  const glm::vec3 given(0.1f, 0.2f, 0.3f);
  s.triangle_radiance.push_back({{given, given, given}, {given, given, given}});
  s.lights.push_back({{0, 0, 2}, glm::vec3(8.0f)});
  s.camera = scene::Camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 10.0};
  s.validate();
  const geometry::Bvh bvh = geometry::build_bvh_by_clustering(s);
  raytrace::RenderSettings settings;
  settings.width = settings.height = 9;
  settings.shading = raytrace::Shading::whitted;
  const raytrace::RenderOutput out = raytrace::render_image(s, bvh, settings);
  // The centre pixel sees (0, 0, 0) under the light: 0.1 + 0.5 * 8 / 4 in red, and so on.
  const glm::vec3 centre = out.image.at(4, 4);
  EXPECT_NEAR(centre.r, 0.1f + 0.5f * 2.0f, 1e-4f);
  EXPECT_NEAR(centre.g, 0.2f + 0.25f * 2.0f, 1e-4f);
  EXPECT_NEAR(centre.b, 0.3f + 1.0f * 2.0f, 1e-4f);
  // Seen from behind (back_diffuse 0): only the given radiance, no light.
  s.camera = scene::Camera{{0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 10.0};
  const raytrace::RenderOutput back = raytrace::render_image(s, bvh, settings);
  EXPECT_EQ(back.image.at(4, 4), given);
}

TEST(ViewPass, CornellWithAPointLightIsBrighterNowhereDarker) {
  auto d = small_image(scene_file("cornell.toml"));
  const radiosity::Scene mesh = radiosity::flatten(scene::to_world(d));
  const ViewRendered plain = render_on(d, &mesh, 2);
  scene::SceneDescription lamp = d;
  lamp.lights.push_back(scene::PointLight{{278, 300, 150}, scene::Rgb(2e5)});
  ViewSettings same;
  same.exposure = plain.out->view->exposure;  // the plain render's, so pixels compare
  const ViewRendered lit = render_on(lamp, &mesh, 2, same);
  int brighter = 0;
  for (std::size_t i = 0; i < plain.out->view->result.image.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float a = plain.out->view->result.image.pixels()[i][c], b = lit.out->view->result.image.pixels()[i][c];
      ASSERT_GE(b, a) << "pixel " << i;
      brighter += b > a;
    }
  EXPECT_GT(brighter, int(plain.out->view->result.image.pixels().size()));
}

}  // namespace
}  // namespace gcsim::render

namespace gcsim::render {
namespace {

// A lamp (an emissive square facing down) over a floor, with a point light so the floor shows.
scene::SceneDescription lamp_scene(double floor_reflectance, bool lamp_faces_down) {
  const std::string lamp = lamp_faces_down ? "[[-1, 3, -1], [1, 3, -1], [1, 3, 1], [-1, 3, 1]]"
                                           : "[[-1, 3, -1], [-1, 3, 1], [1, 3, 1], [1, 3, -1]]";
  const std::string text = fmt::format(R"(
name = "LAMP"
[camera]
eye = [0, 1, -7]
target = [0, 1.5, 0]
fov = 50
[image]
width = 48
height = 48
background = 0
ambient = 0
[materials.lamp]
reflectance = 0
emission = [0.6, 0.5, 0.4]
[materials.floor]
reflectance = {}
[[polygon]]
material = "lamp"
vertices = {}
[[polygon]]
material = "floor"
vertices = [[-4, 0, -4], [-4, 0, 4], [4, 0, 4], [4, 0, -4]]
[[point_light]]
position = [2, 4, -3]
intensity = 20
)",
                                       floor_reflectance, lamp);
  return scene::parse_scene_file(text, "lamp.toml", ".");
}

// --force-pass radiosity where the plan skips it: nothing emits (direct-light.toml), nothing
// reflects (a black floor under the lamp), or the lamp's light reaches no diffuse surface (it faces
// up, away from the floor). The pass runs on every node, finds no reflected light (B - E = 0 on
// every element) and leaves every pixel as it was; where a lamp shoots, it costs simulated time.
TEST(ViewPass, ForcingRadiosityWhereThePlanSkipsItChangesNoPixel) {
  struct Case {
    const char* name;
    scene::SceneDescription d;
  };
  const Case cases[] = {{"nothing emits", small_image(scene_file("direct-light.toml"))},
                        {"nothing reflects", lamp_scene(0.0, true)},
                        {"the lamp faces away", lamp_scene(0.7, false)}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    ASSERT_FALSE(make_plan(c.d).pass(PassId::radiosity).on);
    const radiosity::Scene mesh = radiosity::flatten(scene::to_world(c.d));
    ViewSettings forced_view;
    forced_view.shows_radiosity = false;
    const ViewRendered planned = render_on(c.d, nullptr, 2);
    const ViewRendered forced = render_on(c.d, &mesh, 2, forced_view);
    EXPECT_EQ(planned.out->view->result.image.pixels(), forced.out->view->result.image.pixels());
    EXPECT_EQ(reflected_light(mesh, forced.out->radiosity.element_radiosity).element, -1);
    ASSERT_EQ(forced.out->radiosity.element_radiosity.size(), mesh.elements.size());
    if (std::string(c.name) != "nothing emits") {
      EXPECT_GT(forced.out->radiosity.steps.size(), 0u);
      EXPECT_GT(forced.run.makespan, planned.run.makespan);
    }
  }
}

// Where the plan skips radiosity, an emitter still shows its emission (what radiosity would show on
// a surface that reflects nothing), on its front only: before, it was black.
TEST(ViewPass, AnEmitterWithoutARadiosityPassShowsItsEmission) {
  const auto d = lamp_scene(0.0, true);
  ASSERT_FALSE(make_plan(d).pass(PassId::radiosity).on);
  const ViewRendered r = render_on(d, nullptr, 1);
  const auto& image = r.out->view->result.image;
  int lamp = 0;  // pixels showing the emission, to the image's 8-bit encoding (the floor and background are black)
  for (const glm::vec3& c : image.pixels())
    lamp += glm::all(glm::lessThan(glm::abs(c - glm::vec3(0.6f, 0.5f, 0.4f)), glm::vec3(0.005f)));
  EXPECT_GT(lamp, 40);  // the underside spans about 20 x 4 of the 48 x 48 pixels
  int lit = 0;
  for (const glm::vec3& c : image.pixels()) lit += c != glm::vec3(0.0f);
  EXPECT_EQ(lit, lamp);
  // Seen from above, the lamp's back is black.
  auto from_above = d;
  from_above.camera->eye = glm::dvec3(0, 8, -0.5);
  from_above.camera->look_at = glm::dvec3(0, 3, 0);
  const ViewRendered above = render_on(from_above, nullptr, 1);
  for (const glm::vec3& c : above.out->view->result.image.pixels()) ASSERT_EQ(c, glm::vec3(0.0f));
}

}  // namespace
}  // namespace gcsim::render
