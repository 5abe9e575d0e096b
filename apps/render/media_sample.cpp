#include "apps/render/media_sample.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "apps/render/render_setup.hpp"
#include "apps/render/sampled_view.hpp"
#include "apps/render/view_sample.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

namespace {

// The photon pass on the simulated machine: its end (the last node's) and what node 0 gathered, kept
// past the run (not its memory reservations: they die with the run).
struct PhotonRun {
  double end = 0;
  std::vector<double> node_end;  // each node's end
  std::vector<std::vector<media::Photon>> per_region;  // every node's, as each node holds them
  std::vector<radiosity::Rgb> wall_power;               // every node's are the same
  std::size_t stored = 0;                               // photons in the map
};

PhotonRun run_photons(const MediaSetup& media, const parix::SimulationOptions& machine) {
  PhotonRun out;
  out.node_end.assign(std::size_t(machine.config.nodes), 0.0);
  const parix::RunResult r = parix::run_simulated(machine, [&](parix::Processor& p) {
    GatheredPhotons g = photon_pass(p, media);
    out.node_end[std::size_t(p.id())] = p.now_seconds();
    if (p.id() != 0) return;
    out.per_region = g.per_region, out.wall_power = g.wall_power;
    for (const auto& region : g.per_region) out.stored += region.size();
  });
  out.end = r.simulated_seconds();
  return out;
}

}  // namespace

int march_row_stride(int tile_stride, int tiles, int nodes, long pixels) {
  const int k = std::max(tile_stride, 1);
  const bool many_tiles = tiles >= 4 * std::max(nodes, 1);
  int share = 4;  // one pixel in `share` of the image marched
  if (many_tiles && pixels / (8L * k) >= kMinPixelsMarchedThin) share = 8;
  if (many_tiles && pixels / 16 >= kMinPixelsMarchedSixteenth) share = 16;
  return std::max(1, share / k);
}

MediaSample sample_media(const scene::SceneDescription& d, const Plan& plan, const std::string& file,
                         const parix::SimulationOptions& machine, const MediaSampleOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  RenderSetup setup = prepare_render(d, plan, file, {}, o.photons);
  if (!setup.media || !setup.media->photon_pass) throw std::invalid_argument(file + ": the plan has no photon pass");
  MediaSetup& media = *setup.media;
  media.view.look_up_li = false;  // the samples are timed, not shown: their counts need no Li
  const std::size_t n = o.photons, big = std::max<std::size_t>(1, n / std::size_t(std::max(o.photon_divisor, 1)));
  const double scale = double(n) / double(big);

  MediaSample m;
  media.traced = big < n ? big : 0;
  const PhotonRun photons = run_photons(media, machine);
  m.photon_seconds = photons.end;
  std::vector<double> node_end = photons.node_end;  // where each node's view starts, extrapolated alike
  if (big < n) {  // the second point of the line: half the photons
    const std::size_t small = std::max<std::size_t>(1, big / 2);
    media.traced = small;
    const PhotonRun fewer = run_photons(media, machine);
    const double slope = double(n - big) / double(big - small);
    m.photon_seconds += (photons.end - fewer.end) * slope;
    for (std::size_t i = 0; i < node_end.size(); ++i) node_end[i] += (photons.node_end[i] - fewer.node_end[i]) * slope;
  }
  // The view's sampled tiles with the media (their SH grid's counts scaled to every photon) and
  // without: the difference is the marching (the set-up cancels).
  const std::vector<radiosity::Rgb> b = setup.radiosity ? emitted_radiosity(setup.mesh) : std::vector<radiosity::Rgb>{};
  SampledViewInput in;
  in.setup = &setup;
  in.radiosity = setup.radiosity ? &b : nullptr;
  in.view.secondary = plan.pass(PassId::specular).on, in.view.shadows = plan.pass(PassId::shadows).on;
  in.media = &media, in.photons = &photons.per_region, in.grid_scale = scale;
  // Without a radiosity pass between, a node's view starts where its photon pass ends, as in the
  // render: started together, MEDIA-SMALL's 48 tiles on 64 nodes went out paired otherwise and one
  // node got two of the sphere's (its view 3.87 s against the render's 2.41 s).
  if (!setup.radiosity) in.node_start = node_end;
  const int tiles = view_tile_count(d);
  in.tile_stride = o.tile_stride > 0 ? o.tile_stride : march_tile_stride(tiles, machine.config.nodes, plan.facts.media_coverage >= 1.0);
  in.pixel_row_stride = o.row_stride > 0 ? o.row_stride
                                         : march_row_stride(in.tile_stride, tiles, machine.config.nodes, long(d.image.width) * d.image.height);
  const SampledView with = run_sampled_view(in, machine);
  in.view.exposure = with.exposure;
  in.media = nullptr, in.photons = nullptr;
  const SampledView without = run_sampled_view(in, machine);

  m.grid_seconds = with.grid_seconds;
  m.view_seconds = with.scaled();
  m.march_seconds = std::max(0.0, with.scaled() - without.scaled());
  m.map_bytes = std::int64_t(double(photons.stored) * scale) * std::int64_t(sizeof(media::Photon));
  m.wall_power = photons.wall_power;
  for (radiosity::Rgb& w : m.wall_power) w *= scale;
  m.traced = big < n ? big : n;
  m.tile_stride = in.tile_stride, m.row_stride = in.pixel_row_stride, m.tiles = with.tiles, m.tiles_rendered = with.rendered;
  m.rendered_tiles = with.rendered_tiles;
  m.host_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

}  // namespace gcsim::render
