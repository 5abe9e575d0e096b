#pragma once
// The ray tracer's commands beyond run and sweep.
#include "apps/pipeline/command_groups.hpp"

namespace gcsim::raytrace::app {

void add_table_command(pipeline::CommandGroups& g);  // gcsim table raytrace
void add_bench_command(pipeline::CommandGroups& g);  // gcsim bench raytrace

}  // namespace gcsim::raytrace::app
