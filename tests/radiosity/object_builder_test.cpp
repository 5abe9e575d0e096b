// ObjectBuilder (the built-in scenes' description builder) against EntityBuilder (the ENTITY built
// directly, still used by the analytic cases): the same calls lowered by to_world give the same
// ENTITY exactly (vertices in order, surfaces, patch and element records), including per-patch
// surfaces, boxes on shared and own corners, a two-sided single patch and placements.
#include <gtest/gtest.h>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/radiosity/entity_builder.hpp"
#include "apps/radiosity/object_builder.hpp"
#include "tests/radiosity/same_world.hpp"

namespace gcsim::radiosity {
namespace {

using F = EntityBuilder::Face;

// The same furniture through either builder: surfaces declared out of their order of use, a
// skewed quad coloured patch by patch, two boxes sharing a corner plane, a box with own corners.
template <class Builder>
void furnish(Builder& b) {
  const int back = b.surface({0.1, 0.2, 0.3});
  const int front = b.surface({0.4, 0.5, 0.6}, {1.5, 1.0, 0.5});
  const int spare = b.surface({0.7, 0.7, 0.7});
  b.quad({{0, 0, 0}, {1.3, 0.1, 0}, {1.2, 0.9, 0.2}, {-0.1, 1.0, 0.1}}, {0.1, 0.2, 1}, 3, 2, 2, 3,
         [&](int i, int j) { return (i + j) % 2 ? front : spare; });
  b.box_shared({-0.3, 0, -0.3}, {0.3, 0.4, 0.3}, F::kTop | F::kSides, [&](F f) { return f == F::kTop ? front : back; });
  b.box_shared({-0.3, 0.4, -0.3}, {0.3, 0.9, -0.2}, F::kBottom | F::kMaxZ, [&](F) { return spare; });
  b.box_separate({1, 0, 1}, {1.5, 0.25, 2}, F::kTop | F::kMinX | F::kMaxZ, [&](F f) { return f == F::kMaxZ ? back : front; });
}

using test_support::expect_same_entity;

TEST(ObjectBuilder, LowersToTheEntityBuilderEntity) {
  EntityBuilder direct("furniture");
  furnish(direct);
  scene::SceneDescription d;
  ObjectBuilder described(d, "furniture");
  furnish(described);
  described.place({1, 2, 3}, 90);
  described.place({0, 0, 0});
  const World w = scene::to_world(d);
  ASSERT_EQ(w.entities.size(), 1u);
  expect_same_entity(w.entities[0], direct.take());
  ASSERT_EQ(w.instances.size(), 2u);
  EXPECT_EQ(w.instances[0].placement.translation, Vec3(1, 2, 3));
  EXPECT_EQ(w.instances[0].placement.rotation_degrees, Vec3(0, 90, 0));
}

// A two-sided single patch (the Cornell light): front and housing on the same four corners.
TEST(ObjectBuilder, TwoSidedSinglePatchIsTwoEntityBuilderSingles) {
  const std::array<Vec3, 4> q{Vec3{3, 5, 2}, {3, 5, 4}, {1, 5, 4}, {1, 5, 2}};
  EntityBuilder direct("light");
  const int lamp = direct.surface({0.8, 0.8, 0.8}, {10, 9, 8}), housing = direct.surface(Rgb(0.0));
  std::array<int, 4> v{};
  for (int k = 0; k < 4; ++k) v[k] = direct.add_vertex(q[k]);
  direct.single(v, {0, -1, 0}, lamp);
  direct.single(v, {0, 1, 0}, housing);
  scene::SceneDescription d;
  ObjectBuilder described(d, "light");
  const int m_lamp = described.surface({0.8, 0.8, 0.8}, {10, 9, 8}), m_housing = described.surface(Rgb(0.0));
  described.single({q[0], q[1], q[2], q[3]}, {0, -1, 0}, m_lamp, m_housing);
  expect_same_entity(scene::to_world(d).entities.at(0), direct.take());
}

}  // namespace
}  // namespace gcsim::radiosity
