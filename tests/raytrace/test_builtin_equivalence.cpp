// TEMPORARY: the built-ins' old float builders against their scene descriptions lowered, bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/lower_scene.hpp"
#include "apps/raytrace/obj_loader.hpp"

namespace gcsim::raytrace {
namespace {

template <class T>
void expect_same_bits(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_EQ(std::memcmp(&a[i], &b[i], sizeof(T)), 0) << what << " " << i;
}

void expect_same_scene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  expect_same_bits(a.spheres, b.spheres, "sphere");
  expect_same_bits(a.triangles, b.triangles, "triangle");
  expect_same_bits(a.triangle_normals, b.triangle_normals, "normals");
  expect_same_bits(a.materials, b.materials, "material");
  expect_same_bits(a.lights, b.lights, "light");
  EXPECT_EQ(a.prim_material, b.prim_material);
  EXPECT_EQ(std::memcmp(&a.background, &b.background, sizeof a.background), 0);
  EXPECT_EQ(std::memcmp(&a.ambient, &b.ambient, sizeof a.ambient), 0);
  EXPECT_EQ(a.camera.eye, b.camera.eye);
  EXPECT_EQ(a.camera.look_at, b.camera.look_at);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.fov_y_degrees, b.camera.fov_y_degrees);
}

TEST(BuiltinEquivalence, DescriptionsLowerToTheOldScenes) {
  for (auto name : builtin_scene_names()) {
    SCOPED_TRACE(std::string(name));
    expect_same_scene(make_builtin_scene(name), lower_scene(builtin_scene_description(name)));
  }
}

TEST(BuiltinEquivalence, ObjDescriptionsLowerToTheOldScenes) {
  for (const char* f : {"tetrahedron.obj", "bunny.obj"}) {
    const auto path = std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "meshes" / f;
    SCOPED_TRACE(f);
    expect_same_scene(load_obj_scene(path), lower_scene(load_obj_description(path)));
  }
}

}  // namespace
}  // namespace gcsim::raytrace
