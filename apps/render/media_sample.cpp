#include "apps/render/media_sample.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "apps/raytrace/render.hpp"
#include "apps/raytrace/render_settings.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/view_pass.hpp"
#include "apps/render/view_sample.hpp"

namespace gcsim::render {

int sample_tile_stride(int tiles, int nodes) { return std::clamp(tiles / (16 * std::max(nodes, 1)), 1, 8); }

int view_tile_count(const scene::SceneDescription& d) {
  return raytrace::Tiling{d.image.width, d.image.height, raytrace::RenderSettings{}.tile}.count();
}

namespace {

media::GridBuildCounts scaled(media::GridBuildCounts c, double f) {
  for (std::uint64_t* n : {&c.knn_queries, &c.knn_photons, &c.range_queries, &c.range_candidates, &c.projections,
                           &c.photon_adds})
    *n = std::uint64_t(double(*n) * f + 0.5);
  return c;
}

struct Timings {
  double photons_end = 0, grid_end = 0, view_start = 0, end = 0;  // the last node's
  std::vector<radiosity::Rgb> wall_power;  // node 0's (every node's are the same)
  std::size_t stored = 0;   // photons in the map
  int tiles = 0, tiles_rendered = 0;
};

// What node 0 gathered, kept past the run (not its memory reservations: they die with the run).
void keep(GatheredPhotons& g, Timings& t) {
  t.wall_power = g.wall_power;
  for (const auto& region : g.per_region) t.stored += region.size();
}

// The render's program (unified_render.cpp) on a sample: `traced` photons and, with a row stride,
// the SH grid's share (its counts times grid_scale) and the view's sampled tiles. media null: the
// view alone, without the media.
class Sampler {
 public:
  Sampler(RenderSetup& s, const Plan& plan, const parix::SimulationOptions& machine)
      : s_(s), machine_(machine), b_(s.radiosity ? emitted_radiosity(s.mesh) : std::vector<radiosity::Rgb>{}) {
    view_.secondary = plan.pass(PassId::specular).on;
    view_.shadows = plan.pass(PassId::shadows).on;
  }

  Timings run(const MediaSetup* media, int row_stride, double grid_scale) const {
    const int nodes = machine_.config.nodes;
    Timings t;
    std::vector<double> photons_end(std::size_t(nodes), 0.0), grid_end(std::size_t(nodes), 0.0), view_start(std::size_t(nodes), 0.0);
    std::unique_ptr<ViewPass> view;
    const parix::RunResult r = parix::run_simulated(machine_, [&](parix::Processor& p) {
      GatheredPhotons g;
      if (media) g = photon_pass(p, *media);
      photons_end[std::size_t(p.id())] = p.now_seconds();
      if (p.id() == 0) keep(g, t);
      if (row_stride <= 0) return;
      if (!view) {  // as the render: the first node here builds the view
        view = make_view_pass(s_.split.surfaces, s_.mesh_or_null(), s_.radiosity ? &b_ : nullptr, view_, p.count(),
                              media, std::vector<std::vector<media::Photon>>(g.per_region));
        view->job->sample_tiles(row_stride);
      }
      if (view->medium) charge_grid_share(p, scaled(view->medium->grid_build(), grid_scale));
      grid_end[std::size_t(p.id())] = view_start[std::size_t(p.id())] = p.now_seconds();
      view->job->program(p, view->result, nullptr);
    });
    auto last = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    t.photons_end = last(photons_end), t.grid_end = last(grid_end), t.view_start = last(view_start);
    t.end = r.simulated_seconds();
    if (view) t.tiles = view->result.tiles_total, t.tiles_rendered = view->job->tiles_rendered_per_run();
    return t;
  }

 private:
  RenderSetup& s_;
  const parix::SimulationOptions& machine_;
  std::vector<radiosity::Rgb> b_;
  ViewSettings view_;
};

}  // namespace

MediaSample sample_media(const scene::SceneDescription& d, const Plan& plan, const std::string& file,
                         const parix::SimulationOptions& machine, const MediaSampleOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  RenderSetup setup = prepare_render(d, plan, file, {}, o.photons);
  if (!setup.media || !setup.media->photon_pass) throw std::invalid_argument(file + ": the plan has no photon pass");
  MediaSetup& media = *setup.media;
  const Sampler sampler(setup, plan, machine);
  const std::size_t n = o.photons, big = std::max<std::size_t>(1, n / std::size_t(std::max(o.photon_divisor, 1)));
  const double scale = double(n) / double(big);
  const int stride = o.tile_stride > 0 ? o.tile_stride : sample_tile_stride(view_tile_count(d), machine.config.nodes);

  MediaSample m;
  media.traced = big < n ? big : 0;
  const Timings with = sampler.run(&media, stride, scale);
  m.photon_seconds = with.photons_end;
  if (big < n) {  // the second point of the line: half the photons
    const std::size_t small = std::max<std::size_t>(1, big / 2);
    media.traced = small;
    const double t_small = sampler.run(&media, 0, 1.0).photons_end;
    m.photon_seconds += (with.photons_end - t_small) * double(n - big) / double(big - small);
  }
  const Timings without = sampler.run(nullptr, stride, 1.0);
  const double tile_scale = double(with.tiles) / double(std::max(with.tiles_rendered, 1));
  m.grid_seconds = with.grid_end - with.photons_end;
  m.view_seconds = (with.end - with.view_start) * tile_scale;
  m.march_seconds = std::max(0.0, (with.end - with.view_start) - without.end) * tile_scale;
  m.map_bytes = std::int64_t(double(with.stored) * scale) * std::int64_t(sizeof(media::Photon));
  m.wall_power = with.wall_power;
  for (radiosity::Rgb& w : m.wall_power) w *= scale;
  m.traced = big < n ? big : n;
  m.tile_stride = stride, m.tiles = with.tiles, m.tiles_rendered = with.tiles_rendered;
  m.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

}  // namespace gcsim::render
