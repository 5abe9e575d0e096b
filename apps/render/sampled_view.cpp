#include "apps/render/sampled_view.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "apps/raytrace/raytrace.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

int view_tile_count(const scene::SceneDescription& d) {
  return raytrace::Tiling{d.image.width, d.image.height, raytrace::RenderSettings{}.tile}.count();
}

int sample_tile_stride(int tiles, int nodes) { return std::clamp(tiles / (16 * std::max(nodes, 1)), 1, 4); }

int march_tile_stride(int tiles, int nodes, bool fills_view) {
  const int n = std::max(nodes, 1), k = std::clamp(tiles / (8 * n), 1, 4);
  return fills_view ? std::max(k, std::clamp(tiles / (16 * n), 1, 8)) : k;
}

double SampledView::scaled() const {
  const double tile_scale = double(tiles) / double(std::max(rendered, 1));
  return seconds + (tile_scale - 1.0) * compute;
}

namespace {

media::GridBuildCounts scaled_counts(media::GridBuildCounts c, double f) {
  for (std::uint64_t* n : {&c.knn_queries, &c.knn_photons, &c.range_queries, &c.range_candidates, &c.projections,
                           &c.photon_adds})
    *n = std::uint64_t(double(*n) * f + 0.5);
  return c;
}

std::vector<int> tiles_of(const raytrace::ParallelRender& r) {
  std::vector<int> tiles;
  for (const auto& node : r.node_prims)
    for (const raytrace::TilePrims& t : node) tiles.push_back(t.tile);
  std::sort(tiles.begin(), tiles.end());
  return tiles;
}

// Holds node p's CPU until `at` (SampledViewInput::node_start), in raw cycles: a machine file
// without the `cycle` operation starts every node at 0.
void reach(parix::Processor& p, const parix::SimulationOptions& machine, double at) {
  if (at <= 0 || !machine.config.cycles_per_op.contains("cycle")) return;
  p.compute("cycle", std::llround(at * machine.config.clock_hz / machine.config.cycles_per_op.find("cycle")->second));
}

}  // namespace

SampledView run_sampled_view(const SampledViewInput& in, const parix::SimulationOptions& machine) {
  const RenderSetup& s = *in.setup;
  std::vector<double> start(std::size_t(machine.config.nodes), 0.0);
  std::unique_ptr<ViewPass> v;
  const parix::RunResult r = parix::run_simulated(machine, [&](parix::Processor& p) {
    GatheredPhotons g;
    if (in.media && !in.photons) g = photon_pass(p, *in.media);  // no photon pass: nothing charged, one empty list per medium
    if (!v) {  // as the render: the first node here builds the view
      v = make_view_pass(s.split.surfaces, s.mesh_or_null(), in.radiosity, in.view, p.count(), in.media,
                         in.photons ? *in.photons : std::move(g.per_region));
      v->job->sample_tiles(in.tile_stride);
      v->job->sample_pixel_rows(in.pixel_row_stride);
    }
    if (!in.node_start.empty()) reach(p, machine, in.node_start[std::size_t(p.id())]);
    if (v->medium) charge_grid_share(p, scaled_counts(v->medium->grid_build(), in.grid_scale));
    start[std::size_t(p.id())] = p.now_seconds();
    v->job->program(p, v->result, nullptr);
  });
  SampledView out;
  const double last_start = *std::max_element(start.begin(), start.end());
  out.grid_seconds = last_start - (in.node_start.empty() ? 0.0 : *std::max_element(in.node_start.begin(), in.node_start.end()));
  out.seconds = r.simulated_seconds() - last_start;
  // Before its view a node only computed (its node_start, its SH grid share; an absorbing medium's photon pass is empty).
  out.compute = r.mean_compute_seconds() - std::accumulate(start.begin(), start.end(), 0.0) / double(start.size());
  out.peak = r.memory_peak;
  out.tiles = v->result.tiles_total, out.rendered = v->job->tiles_rendered_per_run();
  out.rendered_tiles = tiles_of(v->result);
  out.exposure = v->exposure;
  return out;
}

}  // namespace gcsim::render
