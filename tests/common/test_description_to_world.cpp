// The description lowered to the thesis's WORLD: one entity per object, one surface per material,
// grids of patches and elements, and every closed shape's patches facing outwards.
#include <gtest/gtest.h>

#include "apps/common/geometry/polygon.hpp"
#include "apps/common/scene/description_to_world.hpp"

namespace gcsim::scene {
namespace {

geometry::Polygon placed(const Entity& e, const PolygonRecord& r) {
  geometry::Polygon p;
  p.count = r.count;
  for (int k = 0; k < r.count; ++k) p.v[k] = e.vertices[r.vertex[k]];
  return p;
}

// Every patch of the entity faces away from `inside`, and its elements lie in and face as it does.
void expect_facing_out(const Entity& e, const glm::dvec3& inside) {
  for (const PolygonRecord& r : e.patches) {
    const geometry::Polygon p = placed(e, r);
    EXPECT_GT(glm::dot(geometry::polygon_normal(p), geometry::polygon_centroid(p) - inside), 0.0);
  }
  for (const PolygonRecord& r : e.elements) {
    const geometry::Polygon el = placed(e, r), patch = placed(e, e.patches[r.owner]);
    EXPECT_GT(glm::dot(geometry::polygon_normal(el), geometry::polygon_normal(patch)), 0.99);
  }
}

TEST(DescriptionToWorld, ClosedShapesFaceOutwards) {
  SceneDescription d;
  const int grey = d.add_material({.name = "grey"});
  d.shapes.push_back({Box{{0, 0, 0}, {1, 2, 3}}, grey});
  d.shapes.push_back({Sphere{{5, 0, 0}, 2.0}, grey});
  const World w = to_world(d);
  ASSERT_EQ(w.entities.size(), 2u);
  EXPECT_EQ(w.entities[0].patches.size(), 6u);
  EXPECT_EQ(w.entities[1].patches.size(), std::size_t(kSphereSlices * kSphereStacks));
  expect_facing_out(w.entities[0], {0.5, 1, 1.5});
  expect_facing_out(w.entities[1], {5, 0, 0});
  // The sphere's patches cover it: their areas sum to a little under 4 pi r^2.
  double area = 0;
  for (const PolygonRecord& r : w.entities[1].patches) area += geometry::polygon_area(placed(w.entities[1], r));
  EXPECT_GT(area, 0.95 * 4 * 3.141592653589793 * 4.0);
  EXPECT_LT(area, 4 * 3.141592653589793 * 4.0);
}

TEST(DescriptionToWorld, ObjectsShareAnEntityAndOneSurfacePerMaterial) {
  SceneDescription d;
  const int a = d.add_material({.name = "a"}), b = d.add_material({.name = "b"});
  Polygon quad;
  quad.vertex = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 0)};
  quad.patch_columns = 3, quad.patch_rows = 2, quad.element_columns = 2, quad.element_rows = 2;
  Shape s1{quad, a};
  s1.object = "thing";
  Shape s2{quad, a};
  s2.object = "thing";
  s2.back_material = b;
  d.shapes = {s1, s2, Shape{quad, b}};
  const World w = to_world(d);
  ASSERT_EQ(w.entities.size(), 2u);
  ASSERT_EQ(w.instances.size(), 2u);
  const Entity& thing = w.entities[0];
  EXPECT_EQ(thing.surfaces.size(), 2u);                  // a, then b for the back
  EXPECT_EQ(thing.patches.size(), 3u * 6u);              // s1, s2 front, s2 back
  EXPECT_EQ(thing.elements.size(), 3u * 24u);
  EXPECT_EQ(thing.vertices.size(), 2u * 7u * 5u);        // one 7 x 5 grid per polygon, shared by both sides
  // The back patches are the front ones turned round.
  const geometry::Polygon front = placed(thing, thing.patches[6]), back = placed(thing, thing.patches[12]);
  EXPECT_EQ(geometry::polygon_normal(front), -geometry::polygon_normal(back));
}

Polygon unit_square() {
  Polygon p;
  p.vertex = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0), glm::dvec3(0, 1, 0)};
  return p;
}

// A single-patch quad keeps its corners in their order; a 1 x 1 grid numbers them row by row.
TEST(DescriptionToWorld, SinglePatchKeepsTheCornerOrder) {
  SceneDescription d;
  const int a = d.add_material({.name = "a"});
  Polygon single = unit_square();
  single.single_patch = true;
  d.shapes = {Shape{unit_square(), a}, Shape{single, a}};
  const World w = to_world(d);
  ASSERT_EQ(w.entities.size(), 2u);
  const Entity &grid = w.entities[0], &one = w.entities[1];
  EXPECT_EQ(grid.vertices[2], glm::dvec3(0, 1, 0));
  EXPECT_EQ((grid.patches[0].vertex), (std::array<int, 4>{0, 1, 3, 2}));
  EXPECT_EQ(one.vertices[2], glm::dvec3(1, 1, 0));
  EXPECT_EQ((one.patches[0].vertex), (std::array<int, 4>{0, 1, 2, 3}));
  ASSERT_EQ(one.elements.size(), 1u);
  EXPECT_EQ(one.elements[0].vertex, one.patches[0].vertex);
}

// A layout orders the entity's surfaces, lends it shared vertices and places it several times.
TEST(DescriptionToWorld, LayoutOrdersSurfacesSharesVerticesAndPlaces) {
  SceneDescription d;
  const int a = d.add_material({.name = "a"}), b = d.add_material({.name = "b"});
  Polygon left = unit_square(), right = unit_square();
  right.vertex = {glm::dvec3(1, 0, 0), glm::dvec3(2, 0, 0), glm::dvec3(2, 1, 0), glm::dvec3(1, 1, 0)};
  left.layout_vertex = {0, 1, 2, 3};
  right.layout_vertex = {1, 4, 5, 2};
  Shape l{left, a}, r{right, b};
  l.object = r.object = "pair";
  d.shapes = {l, r};
  Placement moved;
  moved.translation = {0, 0, 5};
  d.layouts.push_back({"pair", {b, a}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}}, {{}, moved}});
  const World w = to_world(d);
  ASSERT_EQ(w.entities.size(), 1u);
  const Entity& e = w.entities[0];
  EXPECT_EQ(e.vertices.size(), 6u);  // the shared corners only
  EXPECT_EQ(e.patches[0].owner, 1);  // material a is the second surface
  EXPECT_EQ(e.patches[1].owner, 0);
  EXPECT_EQ((e.patches[1].vertex), (std::array<int, 4>{1, 4, 5, 2}));
  ASSERT_EQ(w.instances.size(), 2u);
  EXPECT_EQ(w.instances[1].placement.translation, glm::dvec3(0, 0, 5));
  d.layouts[0].object = "nothing";
  EXPECT_THROW(to_world(d), std::invalid_argument);  // a layout for no shape's object
  d.layouts[0].object = "pair";
  d.layouts[0].vertices.resize(5);
  EXPECT_THROW(to_world(d), std::invalid_argument);  // shared vertex 5 of 5
}

// Per-patch materials colour a grid patch by patch, row by row; their count must match the grid.
TEST(DescriptionToWorld, PatchMaterialsColourTheGrid) {
  SceneDescription d;
  const int a = d.add_material({.name = "a"}), b = d.add_material({.name = "b"});
  Polygon p = unit_square();
  p.patch_columns = 2, p.patch_rows = 2;
  p.patch_materials = {b, a, a, b};
  d.shapes = {Shape{p, b}};
  const Entity e = to_world(d).entities[0];
  ASSERT_EQ(e.patches.size(), 4u);
  EXPECT_EQ(e.patches[0].owner, 0);  // b, first used
  EXPECT_EQ(e.patches[1].owner, 1);
  EXPECT_EQ(e.patches[2].owner, 1);
  EXPECT_EQ(e.patches[3].owner, 0);
  std::get<Polygon>(d.shapes[0].geometry).patch_materials.pop_back();
  EXPECT_THROW(to_world(d), std::invalid_argument);
  std::get<Polygon>(d.shapes[0].geometry).single_patch = true;
  EXPECT_THROW(to_world(d), std::invalid_argument);  // one patch has no grid to colour
}

}  // namespace
}  // namespace gcsim::scene
