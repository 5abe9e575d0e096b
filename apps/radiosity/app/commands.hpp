#pragma once
// The radiosity application's commands beyond run and sweep.
#include "apps/pipeline/command_groups.hpp"

namespace gcsim::radiosity::app {

void add_accuracy_command(pipeline::CommandGroups& g);    // gcsim accuracy radiosity
void add_table_command(pipeline::CommandGroups& g);       // gcsim table radiosity
void add_scene_info_command(pipeline::CommandGroups& g);  // gcsim scene info

}  // namespace gcsim::radiosity::app
