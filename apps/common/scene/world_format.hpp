#pragma once
// The thesis's WORLD/ENTITY format as data (section 4.3.2, figures 4.4 to 4.6): a WORLD of
// instances, each an ENTITY (vertices, surfaces, patches, elements) placed by scale, rotation and
// translation. Patches shoot light; elements, which subdivide patches, receive it.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "apps/common/geometry/polygon.hpp"
#include "apps/common/scene/camera.hpp"

namespace gcsim::scene {

using geometry::Rgb;
using geometry::Vec3;

struct Surface {
  Rgb reflectance{0.0};  // rho per channel, in [0, 1)
  Rgb exitance{0.0};     // initial (self-emitted) exitance E
  int material = -1;     // the scene description's material it lowers (-1: read from a WORLD file)
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

struct World {
  std::string name;
  std::vector<Entity> entities;
  std::vector<Instance> instances;
  std::optional<Camera> camera;  // the WORLD file's CAMERA record
};

}  // namespace gcsim::scene
