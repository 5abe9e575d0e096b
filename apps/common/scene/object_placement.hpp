#pragma once
// Objects placed as their layouts say (ObjectLayout::instances), for the renderers that do not place
// them themselves (the ray tracer's lowering; to_world places them as the thesis's instances).
#include "apps/common/scene/scene_description.hpp"

namespace gcsim::scene {

// True when some object's layout places it (one or more instances).
bool places_objects(const SceneDescription& d);

// The description with every shape of a placed object once per instance, in world coordinates
// (Placement::apply; a mirroring placement reverses the vertex order, as radiosity's flatten does),
// and the layouts dropped. A placed box becomes its six faces as polygons, wound outwards; a
// sphere moves and scales (uniform scales only); a mesh's positions move. Per-patch materials are
// radiosity's: the shape keeps its first patch's. Throws std::invalid_argument for a sphere under a
// non-uniform scale or a mesh with vertex normals under a placement.
SceneDescription with_objects_placed(const SceneDescription& d);

}  // namespace gcsim::scene
