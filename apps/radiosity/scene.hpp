#pragma once
// The environment as the thesis stores it (section 4.3.2, figures 4.4 to 4.6): a WORLD of instances,
// each an ENTITY (vertices, surfaces, patches, elements) placed by scale, rotation and translation.
// Patches shoot light; elements, which subdivide patches, receive it. Scene is the flattened world
// the solver works on, with every index global.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "apps/radiosity/geometry.hpp"

namespace gcsim::radiosity {

struct Surface {
  Rgb reflectance{0.0};  // rho per channel, in [0, 1)
  Rgb exitance{0.0};     // initial (self-emitted) exitance E
};

// A polygon given by 3 or 4 vertex indices and the record it belongs to: for a patch its surface,
// for an element its patch (indices local to the entity).
struct PolygonRecord {
  int owner = 0;
  std::array<int, 4> vertex{};
  int count = 4;
};

struct Entity {
  std::string name;
  std::vector<Vec3> vertices;
  std::vector<Surface> surfaces;
  std::vector<PolygonRecord> patches;   // owner = surface
  std::vector<PolygonRecord> elements;  // owner = patch
};

// Scale, then rotate about x, y and z in that order (degrees), then translate.
struct Placement {
  Vec3 scale{1.0};
  Vec3 rotation_degrees{0.0};
  Vec3 translation{0.0};
  Vec3 apply(const Vec3& p) const;
};

struct Instance {
  int entity = 0;  // index into World::entities
  Placement placement;
};

struct Camera {
  Vec3 eye{0.0};
  Vec3 target{0.0, 0.0, 1.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fov_y_degrees = 40.0;
};

struct World {
  std::string name;
  std::vector<Entity> entities;
  std::vector<Instance> instances;
  std::optional<Camera> camera;
};

// Flattened scene: global indices, geometry precomputed.
struct ScenePatch {
  int surface = 0;
  int first_element = 0;  // elements of a patch are contiguous
  int element_count = 0;
  Polygon polygon;
  Vec3 center, normal;
  double area = 0;
};
struct SceneElement {
  int patch = 0;
  std::array<int, 4> vertex{};  // global vertex indices
  int count = 4;
  Polygon polygon;
  Vec3 center, normal;
  double area = 0;
};

struct SceneCounts {
  int instances = 0, surfaces = 0, patches = 0, elements = 0, vertices = 0;
  bool operator==(const SceneCounts&) const = default;
};

struct Scene {
  std::string name;
  int instance_count = 0;
  std::vector<Vec3> vertices;
  std::vector<Surface> surfaces;
  std::vector<ScenePatch> patches;
  std::vector<SceneElement> elements;
  std::optional<Camera> camera;

  SceneCounts counts() const {
    return {instance_count, int(surfaces.size()), int(patches.size()), int(elements.size()), int(vertices.size())};
  }
  const Surface& surface_of_element(int e) const { return surfaces[patches[elements[e].patch].surface]; }
  // Length of the bounding box diagonal: the scene's scale, for scale-relative tolerances.
  double extent() const;
};

// Flattens the world; throws std::invalid_argument naming the entity and record if an index is out
// of range or a polygon is degenerate, so that a bad file never reaches the solver.
Scene flatten(const World& world);

// A camera that sees the whole scene from outside its bounding box (for scenes without one).
Camera default_camera(const Scene& scene);

}  // namespace gcsim::radiosity
