#pragma once
// One sequential render of a scene's image on the host, with what it would cost on one CPU of the
// simulated machine (its counted operations at the machine file's [ops] costs) and on the host.
#include <cstdint>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/media/media_render.hpp"
#include "machine/machine_config.hpp"
#include "parix/processor.hpp"

namespace gcsim::media {

struct Frame {
  apps::Image image;
  RenderCounters counters;
  double simulated_seconds = 0.0;  // one CPU of the machine: the counted render operations
  double wall_seconds = 0.0;       // host
};

// Cycles of a mesh object's tree nodes and triangle tests (zero for the sphere, whose ops are not read).
double boundary_cycles(const BoundaryTally& t, const machine::MachineConfig& m);
// Seconds of one CPU for the camera rays, march samples (each a k-NN estimate) and SH evaluations.
double render_seconds(const RenderCounters& c, std::size_t k, const machine::MachineConfig& m);
// Seconds of one CPU to build SH grids (the k nearest photons per voxel, Funk–Hecke per photon).
double grid_build_seconds(const GridBuildCounts& c, const machine::MachineConfig& m);
// The same work as the [ops] counts parix::Processor::compute charges.
std::vector<parix::OpCount> grid_build_ops(const GridBuildCounts& c);

// Renders every stride-th pixel in x and y (stride 1: the whole image; others: a pilot whose cost,
// scaled by stride², predicts the whole image's). Pixels not rendered stay zero.
Frame render_frame(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                   std::uint64_t seed, const machine::MachineConfig& m, int stride = 1);

}  // namespace gcsim::media
