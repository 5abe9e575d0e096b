// The scene catalogue, the one scene entry: built-in names (any case), dispatch by extension (any
// case) to the table's formats and to registered ones, errors for an unknown name or extension that
// list what exists, and every loader's error caught as the one SceneError.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "apps/common/scene/description_to_world.hpp"
#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/common/scene/scene_error.hpp"
#include "apps/common/scene/world_loader.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::scene {
namespace {

namespace fs = std::filesystem;

SceneDescription test_box() {
  SceneDescription d;
  d.name = "test box";
  const int white = d.add_material({.name = "white"});
  d.shapes.push_back({.geometry = Box{}, .material = white});
  return d;
}

// A built-in scene and a format registered as an application's or a format's own file would.
const BuiltinSceneRegistrar kTestBox({"Catalogue-Test-Box", "common_tests", test_box});
int loads_of_the_test_format = 0;
const SceneFormatRegistrar kTestFormat({"catalogue test format", {".CatTest"}, [](const fs::path& file) {
                                          ++loads_of_the_test_format;
                                          SceneDescription d = test_box();
                                          d.name = file.filename().string();
                                          return d;
                                        }});

class SceneCatalogue : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    return scratch_.write(name, text);
  }
  // The message of the error load_scene throws for name_or_path (of type E), "" if none.
  template <class E>
  static std::string error_of(const std::string& name_or_path) {
    try {
      load_scene(name_or_path);
    } catch (const E& e) {
      return e.what();
    }
    return "";
  }
  test_support::ScratchDir scratch_{"gcsim-scene-catalogue-"};
  const fs::path& dir_ = scratch_.path();
};

TEST_F(SceneCatalogue, FindsABuiltInSceneByNameInAnyCase) {
  EXPECT_TRUE(is_builtin_scene("catalogue-test-box"));
  EXPECT_TRUE(is_builtin_scene("CATALOGUE-TEST-BOX"));
  EXPECT_FALSE(is_builtin_scene("catalogue-test-box2"));
  const SceneDescription d = load_scene("Catalogue-test-BOX");
  EXPECT_EQ(d.name, "test box");
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Box>(d.shapes[0].geometry));
  bool listed = false;
  for (const BuiltinScene& s : builtin_scenes())
    if (s.name == "catalogue-test-box") listed = s.provider == "common_tests";
  EXPECT_TRUE(listed);
}

TEST_F(SceneCatalogue, DispatchesByExtensionInAnyCase) {
  const SceneDescription toml = load_scene(write("a.TOML", "name = \"from toml\"\n[materials.m]\n"
                                                           "[[sphere]]\nmaterial = \"m\"\ncenter = [0, 0, 0]\nradius = 1\n"));
  EXPECT_EQ(toml.name, "from toml");
  ASSERT_EQ(toml.shapes.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Sphere>(toml.shapes[0].geometry));

  const SceneDescription obj = load_scene(write("tri.Obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_EQ(obj.shapes.size(), 1u);
  EXPECT_EQ(std::get<Mesh>(obj.shapes[0].geometry).mesh.triangles.size(), 1u);
  EXPECT_TRUE(obj.light_above_camera);
  EXPECT_TRUE(obj.lights.empty());

  const int before = loads_of_the_test_format;
  EXPECT_EQ(load_scene("no/such/folder/x.cattest").name, "x.cattest");  // the registered loader decides
  EXPECT_EQ(loads_of_the_test_format, before + 1);
}

TEST_F(SceneCatalogue, AWorldFileGivesItsOwnWorldAndItsPlacedPatches) {
  const std::string file = std::string(GCSIM_SOURCE_DIR) + "/tests/radiosity/fixtures/opposing_squares.wld";
  const SceneDescription d = load_scene(file);
  EXPECT_EQ(d.shapes.size(), 2u);  // two instances of a one-patch square
  ASSERT_TRUE(d.source_world.has_value());
  const World direct = load_world(file), lowered = to_world(d);
  EXPECT_EQ(lowered.name, direct.name);
  ASSERT_EQ(lowered.instances.size(), direct.instances.size());
  for (std::size_t i = 0; i < direct.instances.size(); ++i)
    EXPECT_EQ(lowered.instances[i].placement.translation, direct.instances[i].placement.translation);
  EXPECT_EQ(lowered.entities.at(0).vertices, direct.entities.at(0).vertices);
}

TEST_F(SceneCatalogue, AnUnknownNameListsTheBuiltInScenesAndTheFormats) {
  const std::string e = error_of<UnknownSceneError>("no-such-scene");
  EXPECT_NE(e.find("unknown scene 'no-such-scene'"), std::string::npos) << e;
  EXPECT_NE(e.find("catalogue-test-box"), std::string::npos) << e;
  for (const char* listed : {".toml (TOML scene file)", ".obj (Wavefront OBJ)", ".wld/.world (WORLD/ENTITY)", ".cattest"})
    EXPECT_NE(e.find(listed), std::string::npos) << listed << " in " << e;
}

TEST_F(SceneCatalogue, AnUnknownExtensionListsTheFormats) {
  const std::string e = error_of<UnknownSceneError>(write("mesh.ply", "ply\n"));
  EXPECT_NE(e.find("no format reads '.ply'"), std::string::npos) << e;
  EXPECT_NE(e.find(".toml (TOML scene file)"), std::string::npos) << e;
  EXPECT_NE(error_of<UnknownSceneError>("folder/no-extension").find("no extension names its format"), std::string::npos);
  EXPECT_THROW(format_for("x.ply"), UnknownSceneError);
  EXPECT_EQ(format_for("x.WORLD").name, "WORLD/ENTITY");
}

TEST_F(SceneCatalogue, ListsTheTableFormatsFirstThenTheRegisteredOnes) {
  const std::vector<SceneFormat> formats = scene_formats();
  ASSERT_GE(formats.size(), 4u);
  EXPECT_EQ(formats[0].name, "TOML scene file");
  EXPECT_EQ(formats[1].name, "Wavefront OBJ");
  EXPECT_EQ(formats[2].name, "WORLD/ENTITY");
  bool registered = false;
  for (std::size_t i = 3; i < formats.size(); ++i)
    if (formats[i].name == "catalogue test format") registered = formats[i].extensions == std::vector<std::string>{".cattest"};
  EXPECT_TRUE(registered);  // its extension stored in lower case
}

// Every format's mistakes are one type with the file and the line, whatever the loader.
TEST_F(SceneCatalogue, EveryLoadersErrorIsASceneErrorWithFileAndLine) {
  struct Case {
    std::string file;
    int line;
    std::string says;
  };
  const Case cases[] = {
      {write("bad.toml", "name = \"x\"\nbogus = 1\n"), 2, "bogus"},
      {write("bad.obj", "v 0 0 0\nv 1 0 zero\n"), 2, "expected a finite number"},
      {write("bad.wld", "WORLD w\nsquare.ent\n< 1 1 >\n"), 3, "expected"},
      {(dir_ / "missing.toml").string(), 0, "does not exist"},
  };
  for (const Case& c : cases) {
    try {
      load_scene(c.file);
      ADD_FAILURE() << c.file << " loaded";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.file, c.file);
      EXPECT_EQ(e.line, c.line) << e.what();
      EXPECT_NE(e.message.find(c.says), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(c.file, 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace gcsim::scene
