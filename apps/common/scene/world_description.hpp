#pragma once
// The thesis's WORLD/ENTITY files as scene descriptions: every placed patch a polygon with its
// elements, each entity's surfaces materials "PREFIX/ENTITY/surface K", each instance an object.
// Read by the scene file's [[world]] table and by the WORLD format of the scene catalogue.
#include <filesystem>
#include <string>

#include "apps/common/scene/scene_description.hpp"
#include "apps/common/scene/world_format.hpp"

namespace gcsim::scene {

// Why a WORLD's records cannot be placed (an entity it does not define, a bad vertex list, a patch
// of an unknown surface, an element of an unknown patch), or "" when they can. `of` follows the
// entity's name in the message (" of [[world]]" for the scene file).
std::string world_problem(const World& w, const std::string& of);

// Adds the placed patches of a WORLD whose world_problem is "" to the description.
void add_world(const World& w, const std::string& prefix, SceneDescription& out);

// A WORLD file (.wld) read as a scene: the description above, holding the World itself as
// `source_world`, which to_world returns as it is. Throws ParseError.
SceneDescription load_world_description(const std::filesystem::path& file);

}  // namespace gcsim::scene
