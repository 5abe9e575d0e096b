#pragma once
// The table of scene formats the scene layer itself reads (a format is one line here and its
// loader file); formats elsewhere register with a SceneFormatRegistrar instead.
#include <vector>

#include "apps/common/scene/scene_catalogue.hpp"

namespace gcsim::scene {

const std::vector<SceneFormat>& table_formats();

}  // namespace gcsim::scene
