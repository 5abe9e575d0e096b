#pragma once
// The thesis's three test environments (table 4.1) as builders of the shared scene description;
// `to_world` lowers each to the WORLD whose counts of instances, surfaces, patches, elements and
// vertices equal the table exactly:
//   ROOM     9 / 22 /  48 / 197 / 326   furnished room, two ceiling lights
//   PICROOM 10 / 27 / 176 / 205 / 343   furnished room, one light, three pictures on the walls
//   CORNELL  8 /  9 / 112 / 166 / 274   the published Cornell box (geometry in mm, its colours)
// Each shape's object is the thesis's entity, each material one of its surfaces.
#include "apps/common/scene/scene_description.hpp"

namespace gcsim::radiosity {

scene::SceneDescription room_description();
scene::SceneDescription picroom_description();
scene::SceneDescription cornell_description();

}  // namespace gcsim::radiosity
