#pragma once
// The media renderer's one lowering: a scene description (a built-in scene's, or any file the scene
// catalogue reads) becomes the renderer's MediaScene. What the renderer draws, and so what a scene
// must hold: one box of fog (a Box whose material has a medium, its boundary not refracting), at
// most one medium object inside it (a sphere or a closed mesh whose material has a medium, its
// boundary's index the object's), one point or disk light, and a camera. Media are grey: a colour
// whose channels agree is that value, any other its luminance.
#include <string>

#include "apps/common/scene/scene_description.hpp"
#include "apps/media/media_scene.hpp"

namespace gcsim::media {

// Throws std::invalid_argument naming the scene and what it lacks (no medium, no light, a shape the
// renderer cannot draw, ...).
MediaScene lower_media_scene(const scene::SceneDescription& d);

// The scene catalogue's scene (scene::load_scene: a built-in name or a scene file), lowered.
MediaScene load_media_scene(const std::string& name_or_path);

}  // namespace gcsim::media
