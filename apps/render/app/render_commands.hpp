#pragma once
// The render app's commands beyond `run render` (registered in render_app.cpp).
#include "apps/pipeline/command_groups.hpp"

namespace gcsim::render::app {

void add_plan_command(pipeline::CommandGroups& g);             // gcsim plan SCENE.toml
void add_render_accuracy_command(pipeline::CommandGroups& g);  // gcsim accuracy render SCENE.toml
void add_plan_accuracy_command(pipeline::CommandGroups& g);    // gcsim accuracy plan

}  // namespace gcsim::render::app
