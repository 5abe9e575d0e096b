// Built-in scenes (sizes of the paper's photos, determinism) and OBJ input errors.
#include <sstream>

#include <gtest/gtest.h>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/coordinate_limit.hpp"
#include "apps/raytrace/obj_loader.hpp"

namespace gcsim::raytrace {
namespace {

TEST(Scenes, PrimitiveCountsOfThePaper) {
  EXPECT_EQ(make_builtin_scene("spheres-a").spheres.size(), 512u);
  EXPECT_EQ(make_builtin_scene("spheres-b").spheres.size(), 512u);
  EXPECT_EQ(make_builtin_scene("spheres-random").spheres.size(), 512u);
  EXPECT_EQ(make_builtin_scene("teapot").triangles.size(), 552u);
  EXPECT_EQ(make_builtin_scene("teapots").triangles.size(), 4416u);
}

TEST(Scenes, Deterministic) {
  const Scene a = make_builtin_scene("spheres-random"), b = make_builtin_scene("spheres-random");
  for (std::size_t i = 0; i < a.spheres.size(); ++i) {
    EXPECT_EQ(a.spheres[i].center, b.spheres[i].center);
    EXPECT_EQ(a.spheres[i].radius, b.spheres[i].radius);
  }
}

TEST(Scenes, TeapotHasNoDegenerateTriangles) {
  for (const Triangle& t : make_builtin_scene("teapot").triangles) EXPECT_GT(glm::length(t.geometric_normal()), 0.0f);
}

TEST(Scenes, UnknownNameListsTheKnownOnes) {
  try {
    make_builtin_scene("teapot2");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("spheres-random"), std::string::npos);
  }
}

std::string obj_error(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_obj_scene(in, "bad.obj");
  } catch (const ObjError& e) {
    return e.what();
  }
  return "";
}

TEST(Obj, ParsesPolygonsAndNegativeIndices) {
  std::istringstream in("# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1/1/1 2/2/1 3//1 4\nf -4 -3 -2\n");
  const Scene s = parse_obj_scene(in, "quad.obj");
  EXPECT_EQ(s.triangles.size(), 3u);
}

TEST(Obj, ErrorsNameFileLineAndExpectation) {
  EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 zero\n"), "bad.obj:2: expected a finite number for coordinate 3 of a vertex, got 'zero'");
  EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 0\nf 1 2\n"), "bad.obj:3: expected a face with at least three vertices ('f i j k ...')");
  EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").find("bad.obj:4: vertex index 4 is out of range"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\nf 1 x 1\n").find("bad.obj:2: expected a vertex index"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\nbogus 1\n").find("bad.obj:2: unknown statement 'bogus'"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\n").find("no faces"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0\n").find("bad.obj:1: expected 'v x y z'"), std::string::npos);
  EXPECT_NE(obj_error("v nan 0 0\n").find("bad.obj:1:"), std::string::npos);
  EXPECT_THROW(load_obj_scene("/nonexistent/file.obj"), ObjError);
}

TEST(Obj, CoordinatesAreCappedAsInWorldFiles) {
  // `v 1 1e23 -1` once crashed the BVH builder; files now stop at the WORLD parser's 1e15.
  const std::string cube_tail = "v 1 1 1\nv -1 1 1\nv -1 -1 1\nf 1 2 3\nf 2 3 4\n";
  // The tinyobjloader-based loader (apps/common/scene/obj_mesh) names the line and the coordinate.
  EXPECT_EQ(obj_error("v 1 1e23 -1\n" + cube_tail), "bad.obj:1: expected coordinate 2 of a vertex within +-1e15, got '1e23'");
  EXPECT_NE(obj_error("v 0 0 0\nv 0 0 -2e15\n").find("bad.obj:2: expected coordinate 3 of a vertex within +-1e15"),
            std::string::npos);
  EXPECT_EQ(obj_error("v 1 1e15 -1\n" + cube_tail), "");
  EXPECT_EQ(vertex_coordinate_error(1e15, 0), "");
  EXPECT_EQ(vertex_coordinate_error(-1e-300, 2), "");
  EXPECT_NE(vertex_coordinate_error(1.0000001e15, 0), "");
  EXPECT_NE(vertex_coordinate_error(std::numeric_limits<double>::infinity(), 1), "");
  EXPECT_NE(vertex_coordinate_error(std::nan(""), 1), "");
}

}  // namespace
}  // namespace gcsim::raytrace
