// Scenes: the built-in environments match table 4.1, the figures' two squares load and solve, and
// malformed files are rejected with the file, the line and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/progressive_solver.hpp"
#include "apps/common/scene/world_loader.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::radiosity {
namespace {

TEST(BuiltinScenes, CountsEqualThesisTable41) {
  for (const auto& name : builtin_scene_names()) {
    Scene s = flatten(load_scene_world(name));
    EXPECT_EQ(s.counts(), thesis_counts(name)) << name;
  }
  EXPECT_EQ(flatten(room_world()).counts(), (SceneCounts{9, 22, 48, 197, 326}));
  EXPECT_EQ(flatten(picroom_world()).counts(), (SceneCounts{10, 27, 176, 205, 343}));
  EXPECT_EQ(flatten(cornell_world()).counts(), (SceneCounts{8, 9, 112, 166, 274}));
}

TEST(BuiltinScenes, HaveLightsCamerasAndPositiveAreas) {
  for (const auto& name : builtin_scene_names()) {
    Scene s = flatten(load_scene_world(name));
    ASSERT_TRUE(s.camera.has_value()) << name;
    double emitted = 0;
    for (const auto& p : s.patches) {
      EXPECT_GT(p.area, 0);
      emitted += channel_sum(s.surfaces[p.surface].exitance) * p.area;
    }
    EXPECT_GT(emitted, 0) << name;
    for (const auto& e : s.elements) EXPECT_GT(e.area, 0);
  }
}

TEST(BuiltinScenes, CornellWallsFaceInwards) {
  Scene s = flatten(cornell_world());
  const Vec3 inside{278, 274, 280};
  for (const auto& p : s.patches) {
    if (s.surfaces[p.surface].reflectance == Rgb(0.0)) continue;  // the light's housing faces the ceiling
    bool block = p.center.y < 331 && p.center.x > 60 && p.center.x < 480 && p.center.z > 60 && p.center.z < 470 &&
                 p.center.y > 0.5;
    if (block) continue;
    EXPECT_GT(glm::dot(p.normal, inside - p.center), 0) << "patch at " << p.center.x << "," << p.center.y << ","
                                                        << p.center.z;
  }
}

TEST(WorldParser, FiguresOpposingSquaresLoadAndSolve) {
  World w = load_world("fixtures/opposing_squares.wld");
  EXPECT_EQ(w.name, "opposing square");
  ASSERT_EQ(w.entities.size(), 1u);
  EXPECT_EQ(w.entities[0].name, "unit square");
  Scene s = flatten(w);
  EXPECT_EQ(s.counts(), (SceneCounts{2, 2, 2, 2, 8}));
  // They face each other across z = 0.
  EXPECT_NEAR(s.patches[0].center.z, -0.5, 1e-12);
  EXPECT_NEAR(s.patches[1].center.z, 0.5, 1e-12);
  EXPECT_NEAR(s.patches[0].normal.z, 1, 1e-12);
  EXPECT_NEAR(s.patches[1].normal.z, -1, 1e-12);
  SolverOptions o;
  o.hemicube.resolution = 32;
  auto r = solve_progressive(s, o);  // nothing glows: solved at once
  EXPECT_TRUE(r.converged);
  for (const auto& b : r.state.element_radiosity()) EXPECT_EQ(b, Rgb(0.0));
}

TEST(WorldParser, LitSquaresReachTheTwoPatchSolution) {
  Scene s = flatten(load_world("fixtures/opposing_squares_lit.wld"));
  ASSERT_TRUE(s.camera.has_value());
  SolverOptions o;
  o.hemicube.resolution = 128;
  o.hemicube.max_shooter_samples = 1;  // one hemicube at each patch centre (the thesis's)
  o.energy = 1 - 1e-12;
  auto r = solve_progressive(s, o);
  ASSERT_TRUE(r.converged);
  // Symmetric two-patch system B = E + rho F B, F from the patch centre (hemicube's assumption).
  const double f_centre = 0.2394;  // differential form factor, centre of a unit square to the one opposite
  for (const auto& b : r.state.element_radiosity()) EXPECT_NEAR(b.r, 1 / (1 - 0.5 * f_centre), 2e-3);
}

std::string error_of(const std::string& text, const std::string& file = "bad.ent") {
  try {
    parse_entity(text, file);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

const char* kGood =
    "ENTITY t\nVERTEX\n< 0 0 0 >\n< 1 0 0 >\n< 1 1 0 >\n< 0 1 0 >\nEND_VERT\nSURFACE\n[ 0.5 0.5 0.5 ] [ 0 0 0 ]\n"
    "END_SURF\nPATCH\n0 { 0 1 2 3 }\nEND_PATCH\nELEMENT\n0 { 0 1 2 3 }\nEND_ELEM\nEND_ENTITY\n";

TEST(WorldParser, GoodEntityParses) {
  Entity e = parse_entity(kGood, "good.ent");
  EXPECT_EQ(e.vertices.size(), 4u);
  EXPECT_EQ(e.patches.size(), 1u);
}

TEST(WorldParser, ErrorsNameFileLineAndExpectation) {
  std::string g = kGood;
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = g;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  EXPECT_EQ(error_of(replaced("< 1 0 0 >", "< 1 0 >")), "bad.ent:4: expected number 3 of vertex vector, found '>'");
  EXPECT_EQ(error_of(replaced("< 1 1 0 >", "< 1 x 0 >")), "bad.ent:5: expected number 2 of vertex vector, found 'x'");
  EXPECT_EQ(error_of(replaced("[ 0.5 0.5 0.5 ]", "[ 1.5 0.5 0.5 ]")), "bad.ent:9: reflectance 1.5 is outside [0, 1]");
  EXPECT_EQ(error_of(replaced("0 { 0 1 2 3 }\nEND_PATCH", "1 { 0 1 2 3 }\nEND_PATCH")),
            "bad.ent:12: surface index 1 out of range: 1 surfaces defined");
  EXPECT_EQ(error_of(replaced("0 { 0 1 2 3 }\nEND_ELEM", "0 { 0 1 2 7 }\nEND_ELEM")),
            "bad.ent:15: vertex index 7 out of range: 4 vertices defined");
  EXPECT_EQ(error_of(replaced("0 { 0 1 2 3 }\nEND_ELEM", "0 { 0 1 }\nEND_ELEM")),
            "bad.ent:15: expected 3 or 4 vertex indices, found 2");
  EXPECT_EQ(error_of(replaced("0 { 0 1 2 3 }\nEND_ELEM", "0 { 0 0 1 1 }\nEND_ELEM")),
            "bad.ent:15: element has zero area (repeated or collinear vertices)");
  EXPECT_EQ(error_of(replaced("END_ENTITY", "")), "bad.ent:16: expected 'END_ENTITY', found end of file");
  EXPECT_EQ(error_of(replaced("SURFACE", "SURFACES")), "bad.ent:8: expected 'SURFACE' section, found 'SURFACES'");
  EXPECT_EQ(error_of(replaced("0 { 0 1 2 3 }\nEND_ELEM", "END_ELEM")),
            "bad.ent:12: patch 0 has no elements (every patch needs at least one ELEMENT)");
  EXPECT_EQ(error_of(replaced("ENTITY t", "/* never closed")), "bad.ent:1: comment opened with /* is never closed with */");
  EXPECT_EQ(error_of(""), "bad.ent:1: expected 'ENTITY' at the start of an entity file, found end of file");
}

TEST(WorldParser, WorldErrorsNameTheFile) {
  auto err = [](const std::string& text) {
    try {
      parse_world(text, "bad.wld", "fixtures");
    } catch (const ParseError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(err("WORLD w\nmissing.ent\n< 1 1 1 >\n< 0 0 0 >\n< 0 0 0 >\nEND_FILE\n"),
            "bad.wld:2: cannot open entity file 'fixtures/missing.ent': it does not exist");
  EXPECT_EQ(err("WORLD w\nsquare.ent\n< 1 1 1 >\n< 0 0 >\n< 0 0 0 >\nEND_FILE\n"),
            "bad.wld:4: expected number 3 of rotation vector, found '>'");
  EXPECT_EQ(err("WORLD w\nsquare.ent\n< 1 1 1 >\n< 0 0 0 >\n< 0 0 0 >\n"),
            "bad.wld:5: expected entity file name, COMMENT, CAMERA or 'END_FILE', found end of file");
  EXPECT_EQ(err("WORLD w\nEND_FILE\n"), "bad.wld:2: world has no instances");
  // An error inside an entity names the entity file.
  auto dir = test_support::scratch_path("gcsim_radiosity_parser_test");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "broken.ent") << "ENTITY b\nVERTEX\n< 0 0 0\nEND_VERT\n";
  try {
    parse_world("WORLD w\nbroken.ent\n< 1 1 1 >\n< 0 0 0 >\n< 0 0 0 >\nEND_FILE\n", "w.wld", dir);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file, (dir / "broken.ent").string());
    EXPECT_EQ(e.line, 4);
    EXPECT_EQ(e.message, "expected '>' closing vertex vector (three numbers), found 'END_VERT'");
  }
  std::filesystem::remove_all(dir);
  EXPECT_THROW(load_world("fixtures/no_such.wld"), ParseError);
}

TEST(WorldParser, ExportedBuiltinScenesParseBackIdentically) {
  for (const auto& name : builtin_scene_names()) {
    World w = load_scene_world(name);
    World back = w;
    for (auto& e : back.entities) e = parse_entity(format_entity(e), "e.ent");
    Scene a = flatten(w), b = flatten(back);
    ASSERT_EQ(a.counts(), b.counts()) << name;
    EXPECT_EQ(a.vertices, b.vertices) << name;  // shortest round-trip formatting: exact
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
      EXPECT_EQ(a.surfaces[i].reflectance, b.surfaces[i].reflectance);
      EXPECT_EQ(a.surfaces[i].exitance, b.surfaces[i].exitance);
    }
    for (std::size_t i = 0; i < a.elements.size(); ++i) EXPECT_EQ(a.elements[i].vertex, b.elements[i].vertex);
  }
}

TEST(Placement, MirroringKeepsTheFacingSide) {
  World w = load_world("fixtures/opposing_squares.wld");
  w.instances[0].placement.scale = {-1, 1, 1};  // mirrored in x: the square must still face +z
  Scene s = flatten(w);
  EXPECT_NEAR(s.patches[0].normal.z, 1, 1e-12);
  EXPECT_NEAR(s.elements[0].normal.z, 1, 1e-12);
}

TEST(WorldParser, ZeroScaleIsRejectedAtItsLine) {
  try {
    parse_world("WORLD w\nsquare.ent\n< 1 0 1 >\n< 0 0 0 >\n< 0 0 0 >\nEND_FILE\n", "z.wld", "fixtures");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), "z.wld:3: scaling vector has a zero component: the entity would be flattened");
  }
}

TEST(Placement, ScaleRotateTranslateInThatOrder) {
  Placement p;
  p.scale = {2, 1, 1};
  p.rotation_degrees = {0, 0, 90};
  p.translation = {0, 0, 5};
  Vec3 q = p.apply({1, 0, 0});  // scaled to (2,0,0), turned to (0,2,0), moved to (0,2,5)
  EXPECT_NEAR(q.x, 0, 1e-12);
  EXPECT_NEAR(q.y, 2, 1e-12);
  EXPECT_NEAR(q.z, 5, 1e-12);
}

}  // namespace
}  // namespace gcsim::radiosity
