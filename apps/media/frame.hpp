#pragma once
// One sequential render of a scene's image on the host, with what it would cost on one CPU of the
// simulated machine (its counted operations at the machine file's [ops] costs) and on the host.
#include <cstdint>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/media/grid_build_ops.hpp"
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

// The [ops] counts of camera paths (rays, march samples with their k-NN estimates, SH evaluations),
// as the host-side cost model reads them and parix::Processor::compute charges them.
std::vector<parix::OpCount> render_ops(const RenderCounters& c, std::size_t k);
// A mesh object's tree nodes and triangle tests; empty for the sphere (its test is in the ray costs).
std::vector<parix::OpCount> boundary_ops(const BoundaryTally& t);
// Seconds of one CPU for render_ops and boundary_ops.
double render_seconds(const RenderCounters& c, std::size_t k, const machine::MachineConfig& m);
// Seconds of one CPU to build SH grids (the k nearest photons per voxel, Funk–Hecke per photon).
double grid_build_seconds(const GridBuildCounts& c, const machine::MachineConfig& m);

// Renders every stride-th pixel in x and y (stride 1: the whole image; others: a pilot whose cost,
// scaled by stride², predicts the whole image's). Pixels not rendered stay zero.
Frame render_frame(const MediaScene& scene, const SceneCaches& caches, const MarchSettings& settings,
                   std::uint64_t seed, const machine::MachineConfig& m, int stride = 1);

}  // namespace gcsim::media
