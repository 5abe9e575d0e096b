#pragma once
// The environment as the thesis stores it (section 4.3.2, figures 4.4 to 4.6): a WORLD of instances,
// each an ENTITY (vertices, surfaces, patches, elements) placed by scale, rotation and translation.
// Patches shoot light; elements, which subdivide patches, receive it. Scene is the flattened world
// the solver works on, with every index global.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "apps/common/geometry/polygon.hpp"
#include "apps/common/scene/world_format.hpp"
#include "apps/radiosity/geometry_names.hpp"

namespace gcsim::radiosity {

using scene::Entity;
using scene::Instance;
using scene::Placement;
using scene::PolygonRecord;
using scene::Surface;
using scene::World;
using scene::Camera;

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
