#pragma once
// The work of building SH radiance grids as the [ops] counts parix::Processor::compute charges (the
// k nearest photons per voxel, Funk–Hecke per photon), for every renderer that builds them.
#include <vector>

#include "apps/common/media/radiance_grid.hpp"
#include "parix/processor.hpp"

namespace gcsim::media {

std::vector<parix::OpCount> grid_build_ops(const GridBuildCounts& c);

}  // namespace gcsim::media
