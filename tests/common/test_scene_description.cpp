#include <cmath>
// The scene description lowered to the ray tracer's primitives: counts, id order (spheres first),
// materials per primitive, closed boxes, and refusal of what Whitted ray tracing cannot show.
#include <gtest/gtest.h>

#include <stdexcept>

#include "apps/common/geometry/traversal.hpp"
#include "apps/raytrace/lower_scene.hpp"

namespace gcsim::raytrace {
namespace {

scene::SceneDescription two_shapes_and_a_box() {
  scene::SceneDescription d;
  const int grey = d.add_material({.name = "grey"});
  const int glass = d.add_material({.name = "glass", .transmittance = 1.0, .ior = 1.5});
  scene::Polygon quad;
  quad.vertex = {glm::dvec3(-5, 0, -5), glm::dvec3(5, 0, -5), glm::dvec3(5, 0, 5), glm::dvec3(-5, 0, 5)};
  d.shapes.push_back({quad, grey});
  d.shapes.push_back({scene::Sphere{{0, 1, 0}, 1.0}, glass});
  d.shapes.push_back({scene::Box{{2, 0, 2}, {3, 1, 3}}, grey});
  d.lights.push_back(scene::PointLight{{0, 10, 0}, {100, 100, 100}});
  return d;
}

TEST(LowerScene, SpheresFirstThenTrianglesWithTheirMaterials) {
  const Scene s = lower_scene(two_shapes_and_a_box());
  ASSERT_EQ(s.sphere_count(), 1);
  ASSERT_EQ(s.prim_count(), 1 + 2 + 12);
  EXPECT_EQ(s.material_of(0).transmittance, 1.0f);
  for (int p = 1; p < s.prim_count(); ++p) EXPECT_EQ(s.material_of(p).transmittance, 0.0f) << p;
  EXPECT_EQ(s.lights.size(), 1u);
}

// A box is closed: rays from its centre in every axis direction hit it at the half-width.
TEST(LowerScene, BoxIsClosed) {
  scene::SceneDescription d;
  d.add_material({});
  d.shapes.push_back({scene::Box{{-1, -2, -3}, {1, 2, 3}}, 0});
  const Scene s = lower_scene(d);
  for (int axis = 0; axis < 3; ++axis)
    for (const float sign : {-1.0f, 1.0f}) {
      glm::vec3 dir(0.0f);
      dir[axis] = sign;
      Hit hit;
      TestTally tally;
      intersect_brute_force(s, Ray(glm::vec3(0.0f), dir), hit, tally);
      ASSERT_GE(hit.prim, 0);
      EXPECT_FLOAT_EQ(hit.t, float(axis + 1));
    }
  for (const Triangle& t : s.triangles) {  // wound outwards: the normal points away from the centre
    const glm::vec3 n = glm::cross(t.p1 - t.p0, t.p2 - t.p0);
    EXPECT_GT(glm::dot(n, (t.p0 + t.p1 + t.p2) / 3.0f), 0.0f);
  }
}

TEST(LowerScene, RefusesMediaAndBadMaterialIndices) {
  auto d = two_shapes_and_a_box();
  d.materials[0].medium = scene::Medium{};
  EXPECT_THROW(lower_scene(d), std::invalid_argument);
  d = two_shapes_and_a_box();
  d.shapes[0].material = 7;
  EXPECT_THROW(lower_scene(d), std::invalid_argument);
}

// A spot light of half-angle 30 degrees pointing down lights directions within 30 degrees of down,
// and nothing beyond; a point light lights every direction.
TEST(LowerScene, SpotLightsLightOnlyInsideTheirCone) {
  auto d = two_shapes_and_a_box();
  scene::SpotLight spot;
  spot.direction = {0, -2, 0};  // not unit: lowering normalizes it
  spot.cone_degrees = 30;
  d.lights.push_back(spot);
  const Scene s = lower_scene(d);
  const PointLight& l = s.lights.back();
  auto at_degrees = [](double a) {
    const double r = a * 3.14159265358979 / 180;
    return glm::vec3(float(std::sin(r)), float(-std::cos(r)), 0.0f);
  };
  EXPECT_TRUE(l.lights_direction(at_degrees(0)));
  EXPECT_TRUE(l.lights_direction(at_degrees(29.9)));
  EXPECT_FALSE(l.lights_direction(at_degrees(30.1)));
  EXPECT_FALSE(l.lights_direction(glm::vec3(0, 1, 0)));
  EXPECT_TRUE(PointLight{}.lights_direction(glm::vec3(0, 1, 0)));
}

// Glass of weight g is the ray tracer's dielectric with reflectance = transmittance = g: Fresnel's F
// sends g F along the reflected ray and g (1 - F) along the refracted one. What that dielectric cannot
// express (glass without Fresnel, a mirror weight besides) is refused, naming the material.
TEST(LowerScene, GlassSplitsItsWeightByFresnel) {
  auto d = two_shapes_and_a_box();
  d.materials[1].transmittance = 0.75;
  const Scene s = lower_scene(d);
  EXPECT_EQ(s.material_of(0).transmittance, 0.75f);
  EXPECT_EQ(s.material_of(0).reflectance, 0.75f);
  EXPECT_EQ(s.material_of(1).reflectance, 0.0f);  // grey: no mirror
  d.materials[1].fresnel = false;
  EXPECT_THROW(lower_scene(d), std::invalid_argument);
  d.materials[1].fresnel = true;
  d.materials[1].mirror = 0.2;
  try {
    lower_scene(d);
    ADD_FAILURE() << "glass with a mirror weight lowered";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'glass'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gcsim::raytrace
