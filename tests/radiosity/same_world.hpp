#pragma once
// Exact equality of two WORLDs, field by field (doubles compared with ==), as GoogleTest
// expectations: for the tests that lower one scene two ways and expect the same mesh.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::test_support {

using radiosity::Entity;
using radiosity::PolygonRecord;
using radiosity::World;

inline void expect_same_records(const std::vector<PolygonRecord>& a, const std::vector<PolygonRecord>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE(std::string(what) + " " + std::to_string(i));
    EXPECT_EQ(a[i].owner, b[i].owner);
    EXPECT_EQ(a[i].count, b[i].count);
    for (int k = 0; k < a[i].count; ++k) EXPECT_EQ(a[i].vertex[k], b[i].vertex[k]) << "corner " << k;
  }
}

inline void expect_same_entity(const Entity& a, const Entity& b) {
  SCOPED_TRACE("entity " + b.name);
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]) << "vertex " << i;
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    EXPECT_EQ(a.surfaces[i].reflectance, b.surfaces[i].reflectance) << "surface " << i;
    EXPECT_EQ(a.surfaces[i].exitance, b.surfaces[i].exitance) << "surface " << i;
  }
  expect_same_records(a.patches, b.patches, "patch");
  expect_same_records(a.elements, b.elements, "element");
}

inline void expect_same_world(const World& a, const World& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.entities.size(), b.entities.size());
  for (std::size_t e = 0; e < a.entities.size(); ++e) expect_same_entity(a.entities[e], b.entities[e]);
  ASSERT_EQ(a.instances.size(), b.instances.size());
  for (std::size_t i = 0; i < a.instances.size(); ++i) {
    SCOPED_TRACE("instance " + std::to_string(i));
    EXPECT_EQ(a.instances[i].entity, b.instances[i].entity);
    EXPECT_EQ(a.instances[i].placement.scale, b.instances[i].placement.scale);
    EXPECT_EQ(a.instances[i].placement.rotation_degrees, b.instances[i].placement.rotation_degrees);
    EXPECT_EQ(a.instances[i].placement.translation, b.instances[i].placement.translation);
  }
  ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
  if (!a.camera) return;
  EXPECT_EQ(a.camera->eye, b.camera->eye);
  EXPECT_EQ(a.camera->look_at, b.camera->look_at);
  EXPECT_EQ(a.camera->up, b.camera->up);
  EXPECT_EQ(a.camera->fov_y_degrees, b.camera->fov_y_degrees);
}

}  // namespace gcsim::test_support
