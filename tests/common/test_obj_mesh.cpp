// The OBJ loader of the scene layer (tinyobjloader behind a line checker): it must give exactly the
// triangles written, keep the old loader's errors and reject huge coordinates.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "apps/common/scene/obj_mesh.hpp"
#include "apps/raytrace/obj_loader.hpp"
#include "apps/raytrace/teapot.hpp"

namespace gcsim::scene {
namespace {

std::string error_of(const std::string& text) {
  std::istringstream in(text);
  try {
    parse_obj_mesh(in, "bad.obj");
  } catch (const ObjError& e) {
    return e.what();
  }
  return "";
}

// %.9g round-trips every float, so parsing the text must give back the same bits.
std::string obj_text_of(const std::vector<geometry::Triangle>& triangles) {
  std::string text;
  char line[128];
  for (const auto& t : triangles)
    for (const auto& p : {t.p0, t.p1, t.p2}) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
      text += line;
    }
  for (std::size_t i = 0; i < triangles.size(); ++i)
    text += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " + std::to_string(3 * i + 3) + "\n";
  return text;
}

TEST(ObjMesh, TeapotRoundTripsBitForBit) {
  const auto teapot = raytrace::make_teapot();
  std::istringstream in(obj_text_of(teapot.triangles));
  const raytrace::Scene s = raytrace::parse_obj_scene(in, "teapot.obj");
  ASSERT_EQ(s.triangles.size(), teapot.triangles.size());
  for (std::size_t i = 0; i < teapot.triangles.size(); ++i) {
    EXPECT_EQ(s.triangles[i].p0, teapot.triangles[i].p0) << i;
    EXPECT_EQ(s.triangles[i].p1, teapot.triangles[i].p1) << i;
    EXPECT_EQ(s.triangles[i].p2, teapot.triangles[i].p2) << i;
  }
}

TEST(ObjMesh, PolygonsBecomeFansWithNegativeIndicesResolved) {
  std::istringstream in("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1/1/1 2/2/1 3//1 4\nf -4 -3 -2\n");
  const TriangleMesh m = parse_obj_mesh(in, "quad.obj");
  ASSERT_EQ(m.triangles.size(), 3u);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(m.positions[2], glm::dvec3(1, 1, 0));
}

TEST(ObjMesh, RejectsNonFiniteAndHugeCoordinatesWithTheirLine) {
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 zero\n"), "bad.obj:2: expected a finite number for coordinate 3 of a vertex, got 'zero'");
  EXPECT_NE(error_of("v 0 inf 0\n").find("bad.obj:1: expected a finite number for coordinate 2"), std::string::npos);
  EXPECT_NE(error_of("v 0 0 0\nv 2e15 0 0\n").find("bad.obj:2: expected coordinate 1 of a vertex within +-1e15"),
            std::string::npos);
  std::istringstream at_cap("v 1e15 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  // tinyobjloader reads floats, as the ray tracer stores them.
  EXPECT_EQ(parse_obj_mesh(at_cap, "cap.obj").positions[0].x, double(1e15f));
}

TEST(ObjMesh, FaceTokensTinyobjloaderReadsDifferentlyAreRefused) {
  // Found by fuzz_obj: the line checker stops a token at '#', tinyobjloader reads on to a huge index.
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3#9 77775555554\n"),
            "bad.obj: a face refers to vertex 466144226, but 3 vertices are defined");
  EXPECT_EQ(error_of(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\0 9\n", 35)),
            "bad.obj:4: unexpected NUL byte at column 8");
}

}  // namespace
}  // namespace gcsim::scene
