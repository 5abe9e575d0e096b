#include "apps/render/view_sample.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "apps/render/media_sample.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/view_pass.hpp"

namespace gcsim::render {

std::vector<radiosity::Rgb> emitted_radiosity(const radiosity::Scene& mesh) {
  std::vector<radiosity::Rgb> b(mesh.elements.size());
  for (std::size_t e = 0; e < b.size(); ++e) b[e] = mesh.surface_of_element(int(e)).exitance;
  return b;
}

int view_tile_stride(int tiles, int nodes) { return std::min(sample_tile_stride(tiles, nodes), 4); }

namespace {

struct ViewRun {
  double seconds = 0;       // the view as the render reports it: the end less the last node's start
  double compute = 0;       // the nodes' mean CPU time in it
  std::int64_t peak = 0;    // the largest node's memory
  int tiles = 0, rendered = 0;
  double exposure = 0;      // the view's, kept so the next run need not compute it again
};

// The view part of the render's program (unified_render.cpp) on the sampled tiles. media: an
// absorbing medium the view applies without photons, or null.
ViewRun run_view(const RenderSetup& s, const std::vector<radiosity::Rgb>* b, const ViewSettings& view,
                 const MediaSetup* media, int stride, const parix::SimulationOptions& machine) {
  std::vector<double> start(std::size_t(machine.config.nodes), 0.0);
  std::unique_ptr<ViewPass> v;
  const parix::RunResult r = parix::run_simulated(machine, [&](parix::Processor& p) {
    GatheredPhotons g;
    if (media) g = photon_pass(p, *media);  // no photon pass: nothing charged, one empty list per medium
    if (!v) {  // as the render: the first node here builds the view
      v = make_view_pass(s.split.surfaces, s.mesh_or_null(), b, view, p.count(), media, std::move(g.per_region));
      v->job->sample_tiles(stride, true);  // runs of tiles as the whole image's share row planes
    }
    if (v->medium) charge_grid_share(p, v->medium->grid_build());
    start[std::size_t(p.id())] = p.now_seconds();
    v->job->program(p, v->result, nullptr);
  });
  ViewRun out;
  out.seconds = r.simulated_seconds() - *std::max_element(start.begin(), start.end());
  out.compute = r.mean_compute_seconds();
  out.peak = r.memory_peak;
  out.tiles = v->result.tiles_total, out.rendered = v->job->tiles_rendered_per_run();
  out.exposure = v->exposure;
  return out;
}

// The run scaled to every tile: the nodes' mean work grows with the tiles, the rest (the last tiles'
// imbalance, the start and the final messages) stays. Scaling the whole time scaled the imbalance
// of a short run too: 8 nodes, one tile in 8, +31 to +47 % on CORNELL and CORNELL-MIRROR-GLASS.
double scaled(const ViewRun& r, double tile_scale) { return r.seconds + (tile_scale - 1.0) * r.compute; }

}  // namespace

ViewSample sample_view(const scene::SceneDescription& d, const Plan& plan, const std::string& file,
                       const parix::SimulationOptions& machine, const ViewSampleOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool media_pass = plan.pass(PassId::media).on;
  const RenderSetup setup = prepare_render(d, plan, file, {}, kDefaultPhotons, !media_pass);
  const std::vector<radiosity::Rgb> b = setup.radiosity ? emitted_radiosity(setup.mesh) : std::vector<radiosity::Rgb>{};
  const int stride = o.tile_stride > 0 ? o.tile_stride : view_tile_stride(view_tile_count(d), machine.config.nodes);
  const MediaSetup* media = setup.media.get();  // only an absorbing medium here (with_media false otherwise)
  const std::vector<radiosity::Rgb>* shown = setup.radiosity ? &b : nullptr;

  // Primary rays, then the plan's secondary and shadow rays added one kind at a time.
  ViewSettings view;
  view.secondary = view.shadows = false;
  ViewSample out;
  const ViewRun primary = run_view(setup, shown, view, media, stride, machine);
  view.exposure = primary.exposure;
  ViewRun last = primary, with_secondary = primary;
  out.runs = 1;
  if (plan.pass(PassId::specular).on) {
    view.secondary = true;
    last = with_secondary = run_view(setup, shown, view, media, stride, machine);
    ++out.runs;
  }
  if (plan.pass(PassId::shadows).on) {
    view.shadows = true;
    last = run_view(setup, shown, view, media, stride, machine);
    ++out.runs;
  }
  // Differences of a dynamic schedule can come out below zero; the rows still add up to the last run.
  const double tile_scale = double(last.tiles) / double(std::max(last.rendered, 1));
  const double all = scaled(last, tile_scale), before_shadows = scaled(with_secondary, tile_scale);
  out.shadow_seconds = std::max(0.0, all - before_shadows);
  out.specular_seconds = std::max(0.0, before_shadows - scaled(primary, tile_scale));
  out.view_seconds = all - out.shadow_seconds - out.specular_seconds;
  out.bytes_per_node = last.peak;
  out.tile_stride = stride, out.tiles = last.tiles, out.tiles_rendered = last.rendered;
  out.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace gcsim::render
