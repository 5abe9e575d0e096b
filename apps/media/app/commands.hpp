#pragma once
// The media application's commands beyond `run` and `sweep`.
#include "apps/pipeline/command_groups.hpp"

namespace gcsim::media::app {

// gcsim accuracy media
void add_accuracy_command(pipeline::CommandGroups& g);

}  // namespace gcsim::media::app
