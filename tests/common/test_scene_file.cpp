// The TOML scene file: what it reads into the description, and one error case per kind of mistake,
// each naming the file and the line of the offending key and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "apps/common/scene/scene_file.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::scene {
namespace {

namespace fs = std::filesystem;

// A scratch folder per test, for referenced files.
class SceneFileTest : public ::testing::Test {
 protected:
  void write(const std::string& name, const std::string& text) const { scratch_.write(name, text); }
  SceneDescription parse(const std::string& text) const { return parse_scene_file(text, "t.toml", dir_); }
  // The text must fail at `line` with a message holding `expected`.
  void expect_error(const std::string& text, int line, const std::string& expected) const {
    try {
      parse(text);
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const SceneFileError& e) {
      EXPECT_EQ(e.line, line) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("t.toml:" + std::to_string(line) + ": ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  test_support::ScratchDir scratch_{"gcsim-scene-file-"};
  const fs::path& dir_ = scratch_.path();
};

const char* kMaterials = R"(
[materials.white]
reflectance = 0.5
)";

TEST_F(SceneFileTest, ReadsEveryKindOfShapeLightAndSetting) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("one.ent", "ENTITY one\nVERTEX\n< 0 0 0 >\n< 1 0 0 >\n< 1 1 0 >\n< 0 1 0 >\nEND_VERT\n"
                   "SURFACE\n[ 0.5 0.5 0.5 ] [ 0 0 0 ]\nEND_SURF\n"
                   "PATCH\n0 { 0 1 2 3 }\nEND_PATCH\nELEMENT\n0 { 0 1 2 3 }\nEND_ELEM\nEND_ENTITY\n");
  write("one.wld", "WORLD one\none.ent\n< 1 1 1 >\n< 0 0 0 >\n< 0 0 5 >\nEND_FILE\n");
  const SceneDescription d = parse(R"(
name = "all"
[camera]
eye = [0, 1, -5]
target = [0, 1, 0]
fov = 50
[image]
width = 32
height = 16
spp = 4
[materials.white]
reflectance = [0.7, 0.6, 0.5]
[materials.lamp]
emission = 10
[materials.glass]
glass = 0.9
ior = 1.33
fresnel = true
[materials.fog.medium]
sigma_s = 0.2
sigma_a = [0.01, 0.02, 0.03]
phase = "hg"
g = 0.6
ior = 1.2
[[polygon]]
material = "white"
vertices = [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]
patches = [2, 3]
elements = [4, 5]
[[box]]
material = "white"
min = [0, 0, 0]
max = [1, 2, 3]
[[sphere]]
material = "glass"
center = [0, 1, 0]
radius = 0.5
[[sphere]]
material = "fog"
center = [0, 1, 0]
radius = 2
[[mesh]]
material = "lamp"
file = "tri.obj"
scale = 2
translate = [0, 0, 1]
[[world]]
file = "one.wld"
[[point_light]]
position = [0, 5, 0]
intensity = 3
[[spot_light]]
position = [0, 5, 0]
direction = [0, -2, 0]
cone = 20
)");
  EXPECT_EQ(d.name, "all");
  ASSERT_TRUE(d.camera);
  EXPECT_EQ(d.camera->fov_y_degrees, 50.0);
  EXPECT_EQ(d.image.width, 32);
  EXPECT_EQ(d.image.samples_per_pixel, 4);
  ASSERT_EQ(d.shapes.size(), 6u);  // polygon, box, two spheres, mesh, the WORLD's one patch
  const auto& poly = std::get<Polygon>(d.shapes[0].geometry);
  EXPECT_EQ(poly.patch_columns * poly.patch_rows * poly.element_columns * poly.element_rows, 2 * 3 * 4 * 5);
  const auto& mesh = std::get<Mesh>(d.shapes[4].geometry);
  EXPECT_EQ(mesh.mesh.positions[1], glm::dvec3(2, 0, 1));  // scaled, then translated
  const auto& placed = std::get<Polygon>(d.shapes[5].geometry);
  EXPECT_EQ(placed.vertex[2], glm::dvec3(1, 1, 5));
  ASSERT_EQ(placed.elements.size(), 1u);
  const Material& fog = d.materials[d.shapes[3].material];
  ASSERT_TRUE(fog.medium);
  EXPECT_EQ(fog.medium->phase, PhaseKind::henyey_greenstein);
  EXPECT_EQ(fog.medium->phase_g, 0.6);
  EXPECT_EQ(fog.medium->sigma_a.b, 0.03);
  EXPECT_EQ(d.materials[d.shapes[2].material].ior, 1.33);
  ASSERT_EQ(d.lights.size(), 2u);
  EXPECT_EQ(std::get<SpotLight>(d.lights[1]).direction, glm::dvec3(0, -1, 0));
}

TEST_F(SceneFileTest, LoadsFromDiskWithPathsRelativeToTheSceneFolder) {
  fs::create_directories(dir_ / "sub" / "meshes");
  write("sub/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("sub/s.toml", std::string(kMaterials) + "[[mesh]]\nmaterial = \"white\"\nfile = \"meshes/tri.obj\"\n");
  const SceneDescription d = load_scene_file(dir_ / "sub" / "s.toml");
  EXPECT_EQ(d.name, "s");  // the file's stem without a name key
  EXPECT_EQ(d.shapes.size(), 1u);
}

TEST_F(SceneFileTest, InvalidToml) { expect_error("a = 1\nb = [1, 2\n", 2, "not valid TOML"); }

TEST_F(SceneFileTest, UnknownKeys) {
  expect_error("name = \"x\"\nlights = 1\n", 2, "unknown key 'lights' in the scene");
  expect_error("[materials.white]\nreflectence = 0.5\n", 2, "unknown key 'reflectence' in [materials.white]");
  expect_error(std::string(kMaterials) + "[[sphere]]\nmaterial = \"white\"\ncentre = [0, 0, 0]\nradius = 1\n", 6,
               "unknown key 'centre' in [[sphere]] (expected one of: material, object, center, radius)");
}

TEST_F(SceneFileTest, WrongTypes) {
  expect_error("[materials.white]\nreflectance = \"red\"\n", 2, "must be a number or an array of three numbers");
  expect_error("[camera]\neye = [0, 0]\ntarget = [0, 0, 1]\n", 2, "must be an array of three numbers");
  expect_error("[image]\nwidth = 1.5\n", 2, "'width' in [image] must be an integer");
  expect_error("camera = 3\n", 1, "'camera' in the scene must be a table");
  expect_error("[sphere]\nradius = 1\n", 1, "must be an array of tables, written [[sphere]]");
}

TEST_F(SceneFileTest, NegativeAndNonFiniteNumbers) {
  expect_error("[materials.fog.medium]\nsigma_s = -0.1\n", 2, "expected finite values in [0, 1000000]");
  expect_error("[materials.lamp]\nemission = inf\n", 2, "'emission' in [materials.lamp] has inf");
  expect_error("[materials.white]\nmirror = nan\n", 2, "expected a finite value in [0, 1]");
  expect_error(std::string(kMaterials) + "[[sphere]]\nmaterial = \"white\"\ncenter = [0, 0, 0]\nradius = -2\n", 7,
               "'radius' in [[sphere]] is -2");
  expect_error(std::string(kMaterials) + "[[sphere]]\nmaterial = \"white\"\ncenter = [0, 1e300, 0]\nradius = 1\n", 6,
               "expected a finite number within");
}

TEST_F(SceneFileTest, ReflectanceAboveOneAndEnergyGain) {
  expect_error("[materials.white]\nreflectance = [0.5, 1.2, 0.5]\n", 2, "expected finite values in [0, 1]");
  expect_error("[materials.shiny]\nreflectance = 0.6\nmirror = 0.6\n", 1, "reflects more than it receives");
}

TEST_F(SceneFileTest, DegenerateCamera) {
  expect_error("[camera]\neye = [1, 2, 3]\ntarget = [1, 2, 3]\n", 3, "'target' equals 'eye'");
  expect_error("[camera]\neye = [0, 0, 0]\ntarget = [0, 5, 0]\nup = [0, 1, 0]\n", 4, "parallel to the view direction");
  expect_error("[camera]\neye = [0, 0, 0]\ntarget = [0, 0, 1]\nfov = 180\n", 4, "strictly between 0 and 180");
  expect_error("[camera]\neye = [0, 0, 0]\ntarget = [0, 0, 1]\nup = [0, 0, 0]\n", 4, "zero vector");
}

TEST_F(SceneFileTest, DegenerateShapes) {
  const std::string m = kMaterials;
  expect_error(m + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0, 0, 0], [1, 1, 1], [2, 2, 2]]\n", 6,
               "degenerate [[polygon]]");
  expect_error(m + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0, 0, 0], [1, 0, 0]]\n", 6, "3 or 4 points");
  expect_error(m + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\npatches = [2, 1]\n",
               7, "a triangle is one patch");
  expect_error(m + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]\npatches = [0, 1]\n",
               7, "two integers in [1, 1000]");
  expect_error(m + "[[box]]\nmaterial = \"white\"\nmin = [0, 0, 0]\nmax = [1, 0, 1]\n", 7, "flat or inverted along axis y");
  expect_error(m + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]\npatches = [2, 1]\n"
                   "single_patch = true\n",
               7, "'single_patch' in [[polygon]] is one patch of one element");
}

TEST_F(SceneFileTest, SinglePatchPolygon) {
  const SceneDescription d =
      parse(std::string(kMaterials) + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]\n"
                                      "single_patch = true\n");
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_TRUE(std::get<Polygon>(d.shapes[0].geometry).single_patch);
  expect_error(std::string(kMaterials) + "[[polygon]]\nmaterial = \"white\"\nvertices = [[0,0,0],[1,0,0],[1,1,0]]\n"
                                         "single_patch = 1\n",
               7, "single_patch");
}

TEST_F(SceneFileTest, UnknownMaterialIsNamedWithTheKnownOnes) {
  expect_error(std::string(kMaterials) + "[[sphere]]\nmaterial = \"wite\"\ncenter = [0, 0, 0]\nradius = 1\n", 5,
               "material 'wite', which is not defined; expected one of the [materials.NAME] tables (white)");
}

TEST_F(SceneFileTest, MediumPhase) {
  expect_error("[materials.fog.medium]\nphase = \"rayleigh\"\n", 2, "expected \"isotropic\", \"schlick\" or \"hg\"");
  expect_error("[materials.fog.medium]\nphase = \"hg\"\ng = 1\n", 3, "strictly between -1 and 1");
  expect_error("[materials.fog.medium]\nphase = \"schlick\"\n", 1, "missing key 'g'");
  expect_error("[materials.fog.medium]\ng = 0.3\n", 2, "needs phase = \"schlick\" or \"hg\"");
  expect_error("[materials.fog.medium]\ndensity = \"grid.raw\"\n", 2, "unknown key 'density'");
}

TEST_F(SceneFileTest, MissingAndBrokenReferencedFiles) {
  const std::string m = kMaterials;
  expect_error(m + "[[mesh]]\nmaterial = \"white\"\nfile = \"teapot.obj\"\n", 6, "file 'teapot.obj' is missing");
  expect_error("[[world]]\nfile = \"room.wld\"\n", 2, "file 'room.wld' is missing");
  write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  expect_error(m + "[[mesh]]\nmaterial = \"white\"\nfile = \"bad.obj\"\n", 6, "bad.obj:3:");
  fs::create_directories(dir_ / "folder.obj");
  expect_error(m + "[[mesh]]\nmaterial = \"white\"\nfile = \"folder.obj\"\n", 6, "is not a regular file");
}

TEST_F(SceneFileTest, MissingSceneFile) {
  try {
    load_scene_file(dir_ / "nope.toml");
    ADD_FAILURE();
  } catch (const SceneFileError& e) {
    EXPECT_NE(std::string(e.what()).find("nope.toml: cannot read the scene file: it does not exist"), std::string::npos) << e.what();
  }
}

TEST_F(SceneFileTest, SpotLight) {
  expect_error("[[spot_light]]\nposition = [0, 0, 0]\ndirection = [0, 0, 0]\n", 3, "zero vector");
  expect_error("[[spot_light]]\nposition = [0, 0, 0]\ndirection = [0, -1, 0]\ncone = 95\n", 4, "[0, 90]");
}

}  // namespace
}  // namespace gcsim::scene
