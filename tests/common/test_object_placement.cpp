// Objects placed as their layouts say, for the renderers that do not place them themselves: each
// shape once per instance, moved by its placement, boxes as six outward faces, mirrors reversing
// the vertex order; shapes of objects without instances are left as they are.
#include <gtest/gtest.h>

#include "apps/common/scene/object_placement.hpp"

namespace gcsim::scene {
namespace {

SceneDescription two_placed_boxes_and_a_loose_sphere() {
  SceneDescription d;
  const int m = d.add_material({.name = "m"});
  d.shapes.push_back({.geometry = Box{{0, 0, 0}, {1, 1, 1}}, .material = m, .object = "crate"});
  d.shapes.push_back({.geometry = Sphere{{5, 0, 0}, 2.0}, .material = m});
  ObjectLayout crate;
  crate.object = "crate";
  Placement here, there;
  there.translation = {10, 0, 0};
  crate.instances = {here, there};
  d.layouts.push_back(crate);
  return d;
}

TEST(ObjectPlacement, EachInstanceGetsTheObjectsShapesMoved) {
  const SceneDescription d = two_placed_boxes_and_a_loose_sphere();
  ASSERT_TRUE(places_objects(d));
  const SceneDescription placed = with_objects_placed(d);
  EXPECT_FALSE(places_objects(placed));
  EXPECT_TRUE(placed.layouts.empty());
  ASSERT_EQ(placed.shapes.size(), 13u);  // 2 x 6 faces, then the sphere
  glm::dvec3 lo(1e9), hi(-1e9);
  for (int i = 6; i < 12; ++i) {
    const auto& p = std::get<Polygon>(placed.shapes[i].geometry);
    for (int k = 0; k < p.count; ++k) lo = glm::min(lo, p.vertex[k]), hi = glm::max(hi, p.vertex[k]);
  }
  EXPECT_EQ(lo, glm::dvec3(10, 0, 0));  // the second instance's box, moved by 10 along x
  EXPECT_EQ(hi, glm::dvec3(11, 1, 1));
  EXPECT_EQ(std::get<Sphere>(placed.shapes[12].geometry).center, glm::dvec3(5, 0, 0));
}

TEST(ObjectPlacement, BoxFacesLookOutwards) {
  const SceneDescription placed = with_objects_placed(two_placed_boxes_and_a_loose_sphere());
  for (int i = 0; i < 6; ++i) {
    const auto& p = std::get<Polygon>(placed.shapes[i].geometry);
    const glm::dvec3 normal = glm::cross(p.vertex[1] - p.vertex[0], p.vertex[2] - p.vertex[0]);
    const glm::dvec3 centre = (p.vertex[0] + p.vertex[2]) * 0.5;
    EXPECT_GT(glm::dot(normal, centre - glm::dvec3(0.5)), 0.0) << "face " << i;
  }
}

TEST(ObjectPlacement, AMirroringPlacementReversesTheWinding) {
  SceneDescription d;
  const int m = d.add_material({.name = "m"});
  Polygon quad;
  quad.vertex = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 0)};
  d.shapes.push_back({.geometry = quad, .material = m, .object = "card"});
  Placement mirror;
  mirror.scale = {-1, 1, 1};
  d.layouts.push_back({.object = "card", .surface_materials = {}, .vertices = {}, .instances = {mirror}});
  const SceneDescription placed = with_objects_placed(d);
  const auto& p = std::get<Polygon>(placed.shapes.at(0).geometry);
  EXPECT_EQ(p.vertex[0], glm::dvec3(0, 1, 0));  // the last corner first, mirrored in x
  EXPECT_EQ(p.vertex[1], glm::dvec3(-1, 1, 0));
  // Mirrored and reversed: the front still faces +z, as the unplaced quad's does.
  EXPECT_GT(glm::cross(p.vertex[1] - p.vertex[0], p.vertex[2] - p.vertex[0]).z, 0.0);
}

TEST(ObjectPlacement, RefusesASphereUnderANonUniformScale) {
  SceneDescription d;
  const int m = d.add_material({.name = "m"});
  d.shapes.push_back({.geometry = Sphere{}, .material = m, .object = "ball"});
  Placement squash;
  squash.scale = {1, 2, 1};
  d.layouts.push_back({.object = "ball", .surface_materials = {}, .vertices = {}, .instances = {squash}});
  EXPECT_THROW(with_objects_placed(d), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::scene
