#include "apps/render/unified_render.hpp"

#include <algorithm>
#include <cmath>

namespace gcsim::render {

double UnifiedRender::radiosity_seconds() const {
  return radiosity_end_s.empty() ? 0.0 : *std::max_element(radiosity_end_s.begin(), radiosity_end_s.end());
}

double UnifiedRender::media_seconds() const {
  return media_end_s.empty() ? 0.0 : *std::max_element(media_end_s.begin(), media_end_s.end());
}

double UnifiedRender::view_start_seconds() const {
  return view_start_s.empty() ? 0.0 : *std::max_element(view_start_s.begin(), view_start_s.end());
}

void unified_render_program(parix::Processor& p, const scene::SceneDescription& description,
                            const radiosity::Scene* mesh, const radiosity::ParallelOptions& options, ViewSettings view,
                            const MediaSetup* media, UnifiedRender& out) {
  GatheredPhotons photons;
  if (media) {
    PhotonsTraced traced;
    if (out.on_photons)
      traced = [&out, total = std::uint64_t(media->traced > 0 ? media->traced : media->photons)](std::size_t n) {
        out.photons_traced += n;
        out.on_photons(out.photons_traced, total);
      };
    photons = photon_pass(p, *media, traced, view.host_threads);
    out.photon_flights += photons.flights, out.photon_surface_events += photons.surface_events;
    out.media_absorbed += photons.media_absorbed;
  }
  out.media_end_s[std::size_t(p.id())] = p.now_seconds();
  radiosity::ParallelOutcome mine;
  if (mesh) {
    radiosity::ParallelOptions o = options;
    if (!photons.wall_power.empty()) o.solver.received = &photons.wall_power;  // before the first shot
    mine = radiosity::solve_replica(p, *mesh, o);
  }
  out.radiosity_end_s[std::size_t(p.id())] = p.now_seconds();
  if (!out.view) {  // every node gathered the same photons: the first to get here builds the view
    const radiosity::Scene* shown = view.shows_radiosity ? mesh : nullptr;
    out.view = make_view_pass(description, shown, shown ? &mine.element_radiosity : nullptr, view, p.count(), media,
                              std::move(photons.per_region));
    out.view->result.on_tile = out.on_view_tile;
  }
  if (out.view->medium) charge_grid_share(p, out.view->medium->grid_build());
  out.view_start_s[std::size_t(p.id())] = p.now_seconds();
  if (p.id() == 0) {
    out.radiosity = std::move(mine);
    out.wall_power = std::move(photons.wall_power);
    out.wall_deposits = photons.wall_deposits, out.wall_missed = photons.wall_missed;
  }
  out.view->job->program(p, out.view->result, out.view->prefetch.get());
}

void finish(UnifiedRender& out) {
  if (out.view) out.view->job->finish(out.view->result);
}

ReflectedLight reflected_light(const radiosity::Scene& mesh, const std::vector<radiosity::Rgb>& element_radiosity) {
  ReflectedLight r;
  for (std::size_t e = 0; e < element_radiosity.size(); ++e) {
    const radiosity::Rgb reflected = element_radiosity[e] - mesh.surface_of_element(int(e)).exitance;
    const double largest = std::max({std::abs(reflected.r), std::abs(reflected.g), std::abs(reflected.b)});
    if (largest > r.largest || (largest != 0.0 && r.element < 0)) {
      r.largest = largest;
      r.element = int(e);
      r.material = mesh.surface_of_element(int(e)).material;
    }
  }
  return r;
}

double mean_wall_radiosity(const radiosity::Scene& mesh, const std::vector<radiosity::Rgb>& element_radiosity) {
  double sum = 0.0, area = 0.0;
  for (std::size_t e = 0; e < element_radiosity.size() && e < mesh.elements.size(); ++e) {
    if (mesh.surface_of_element(int(e)).exitance != radiosity::Rgb(0.0)) continue;
    sum += radiosity::channel_sum(element_radiosity[e]) / 3.0 * mesh.elements[e].area;
    area += mesh.elements[e].area;
  }
  return area > 0 ? sum / area : 0.0;
}

}  // namespace gcsim::render
