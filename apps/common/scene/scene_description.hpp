#pragma once
// The scene description every renderer reads, in double precision (as pbrt separates the parsed
// scene from its primitives): shapes with a material each, lights, one camera and the image.
// Radiosity lowers it to its patch/element mesh, the ray tracer to float primitive arrays, the
// media renderer to its fog box, medium object and light. Loaders (WORLD/ENTITY, OBJ, built-ins) build it.
#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "apps/common/scene/camera.hpp"
#include "apps/common/scene/triangle_mesh.hpp"
#include "apps/common/scene/world_format.hpp"

namespace gcsim::scene {

using Rgb = glm::dvec3;

// The largest of a colour's three channels: zero means the colour is black.
inline double largest(const Rgb& c) { return std::max({c.r, c.g, c.b}); }

// A participating medium inside a closed bounding surface (the shape that carries the material).
enum class PhaseKind { isotropic, henyey_greenstein, schlick };
struct Medium {
  Rgb sigma_s{0.0};  // scattering coefficient, per unit length
  Rgb sigma_a{0.0};  // absorption coefficient, per unit length
  PhaseKind phase = PhaseKind::isotropic;
  double phase_g = 0.0;  // Henyey-Greenstein asymmetry g, or Schlick's k, in (-1, 1)
  double boundary_ior = 1.0;  // index of the bounding surface (1: no refraction at the boundary)
};

struct Material {
  std::string name;
  Rgb diffuse{0.8};     // reflectance rho per channel, in [0, 1)
  Rgb emission{0.0};    // self-emitted exitance: a shape with it is an area light
  double specular = 0.0, shininess = 32.0;  // Phong highlight (ray tracing)
  double mirror = 0.0;  // mirror weight
  double transmittance = 0.0;  // > 0: glass refracting with index ior
  double ior = 1.5;
  bool fresnel = true;  // glass splits reflection and refraction by the Fresnel equations
  std::optional<Rgb> checker_other{};  // second checkerboard colour
  double checker_size = 1.0;
  std::optional<Medium> medium{};  // the shape bounds a participating medium
};

// An element given explicitly (a WORLD file's ELEMENT record, placed): 3 or 4 vertices.
struct ExplicitElement {
  std::array<glm::dvec3, 4> vertex{};
  int count = 4;
};

// A planar convex polygon of 3 or 4 vertices, its front the side from which the vertices run
// counter-clockwise. For radiosity a quad is a grid of patch_columns x patch_rows patches (columns
// along vertex 0 -> 1, rows along 0 -> 3), each a grid of element_columns x element_rows elements.
struct Polygon {
  std::array<glm::dvec3, 4> vertex{};
  int count = 4;
  int element_rows = 1, element_columns = 1;  // elements per patch, for radiosity
  int patch_rows = 1, patch_columns = 1;
  // Given: the patches and elements keep the grid's vertex order where their front looks along this
  // direction and are reversed otherwise (as the thesis's entity builder orients its records).
  std::optional<glm::dvec3> facing;
  std::vector<ExplicitElement> elements;  // non-empty: these elements instead of the grid
  // Radiosity: one patch with one element on the corners in their order instead of a grid (as a
  // triangle always is); the thesis's single records (a box face, the Cornell light).
  bool single_patch = false;
  // With single_patch: the corners are these vertices of the object's layout (ObjectLayout::vertices),
  // shared with other polygons of the object; `vertex` still holds their positions.
  std::optional<std::array<int, 4>> layout_vertex;
  // Non-empty: the material of each patch of the grid, row by row (patch_rows x patch_columns), e.g.
  // a picture; `Shape::material` is then the first patch's. Radiosity only.
  std::vector<int> patch_materials;
};
struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 1.0;
};
struct Box {
  glm::dvec3 lo{0.0}, hi{1.0};
};
struct Mesh {
  TriangleMesh mesh;
  std::vector<std::array<glm::dvec3, 3>> vertex_normals;  // empty, or one triple per triangle
};

struct Shape {
  std::variant<Polygon, Sphere, Box, Mesh> geometry;
  int material = 0;  // index into SceneDescription::materials
  // A polygon's back side as a second patch on the same vertices (-1: none), e.g. a lamp's housing.
  int back_material = -1;
  // The object (the thesis's ENTITY) the shape belongs to; shapes of one object share its vertices'
  // numbering and one surface per material. Empty: an object of its own.
  std::string object{};
  int source_line = 0;  // the line of the shape's [[table]] in its scene file (0: not from a file)
};

// How an object becomes the thesis's ENTITY where the defaults (surfaces in order of first use, each
// polygon on vertices of its own, one unmoved instance) do not say enough: the radiosity app's
// built-in scenes, whose entities are placed several times (chairs, lights, pictures). Read by
// `to_world` only; the other renderers' lowerings do not place objects yet.
struct ObjectLayout {
  std::string object;
  std::vector<int> surface_materials;  // the entity's first surfaces, in this order
  // Vertices shared by index (Polygon::layout_vertex); they enter the entity in this order, each
  // no later than the first polygon that uses it (unused ones at the end).
  std::vector<glm::dvec3> vertices;
  std::vector<Placement> instances;    // empty: one instance, unmoved
};

struct PointLight {
  glm::dvec3 position{0.0};
  Rgb intensity{1.0};  // radiant intensity; falls off with the square of the distance
};
struct SpotLight {
  glm::dvec3 position{0.0}, direction{0.0, -1.0, 0.0};
  Rgb intensity{1.0};
  double cone_degrees = 30.0;  // half-angle of the cone
};
// A disk emitting radiance ∝ cos^(exponent − 1) θ about its normal (photons leave ∝ cos^exponent;
// exponent 1: Lambertian), `power` the total flux: the media renderer's directional light.
struct DiskLight {
  glm::dvec3 position{0.0}, normal{0.0, -1.0, 0.0};  // the disk's centre and the way it faces
  double radius = 1.0, exponent = 1.0;
  Rgb power{1.0};
};
using Light = std::variant<PointLight, SpotLight, DiskLight>;  // area lights are shapes with emission

// The media renderer's photon-pass settings of a scene (its built-in scenes carry their own).
struct MediaSettings {
  std::size_t photons_emitted = 20000;
  std::size_t k_nearest = 50;      // nearest photons per estimate
  int max_photon_events = 64;      // scatterings plus surface events per photon
  int max_specular_depth = 6;      // camera-path surface events ("split at Fresnel surfaces to depth 6")
};

struct ImageSettings {
  int width = 512, height = 512;
  int samples_per_pixel = 1;
  Rgb background{0.05, 0.06, 0.09};
  Rgb ambient{0.12};
};

struct SceneDescription {
  std::string name;
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  std::vector<Light> lights;
  std::vector<ObjectLayout> layouts;  // per object, optional (radiosity's built-in scenes)
  std::optional<Camera> camera;  // none: each renderer frames the scene itself
  // The format has no lights of its own (OBJ): a renderer that frames the scene puts a point light
  // above its camera (the ray tracer's lowering does).
  bool light_above_camera = false;
  ImageSettings image;
  std::optional<MediaSettings> media;  // none: the media renderer's defaults
  // Read from a WORLD file: the file's own entities, which to_world returns as they are (their
  // patches and elements are the file's, not a grid's); the shapes above are the same patches
  // placed, for the other renderers. Whoever edits the shapes must drop it.
  std::optional<World> source_world;

  int add_material(const Material& m) {
    materials.push_back(m);
    return static_cast<int>(materials.size()) - 1;
  }
};

}  // namespace gcsim::scene
