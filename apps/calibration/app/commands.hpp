#pragma once
// The calibration family's commands, one file each; calibration_commands.cpp registers them.
#include "apps/pipeline/command_groups.hpp"

namespace gcsim::calibration::app {

// gcsim calibrate: fit a machine file's free keys to measured tables.
void add_calibrate_command(pipeline::CommandGroups& g);
// gcsim validate: predict the tables a fit did not use and compare.
void add_validate_command(pipeline::CommandGroups& g);
// gcsim accuracy network: every network model's error against its host time.
void add_network_accuracy_command(pipeline::CommandGroups& g);

}  // namespace gcsim::calibration::app
