#include "apps/render/unified_render.hpp"

#include <algorithm>

namespace gcsim::render {

double UnifiedRender::radiosity_seconds() const {
  return radiosity_end_s.empty() ? 0.0 : *std::max_element(radiosity_end_s.begin(), radiosity_end_s.end());
}

double UnifiedRender::media_seconds() const {
  return media_end_s.empty() ? 0.0 : *std::max_element(media_end_s.begin(), media_end_s.end());
}

void unified_render_program(parix::Processor& p, const scene::SceneDescription& description,
                            const radiosity::Scene* mesh, const radiosity::ParallelOptions& options, ViewSettings view,
                            const MediaSetup* media, UnifiedRender& out) {
  radiosity::ParallelOutcome mine;
  if (mesh) mine = radiosity::solve_replica(p, *mesh, options);
  out.radiosity_end_s[std::size_t(p.id())] = p.now_seconds();
  GatheredPhotons photons;
  if (media) {
    photons = photon_pass(p, *media);
    out.photon_flights += photons.flights, out.photon_surface_events += photons.surface_events;
  }
  if (!out.view) {  // every node gathered the same photons: the first to get here builds the view
    out.view = make_view_pass(description, mesh, mesh ? &mine.element_radiosity : nullptr, view, p.count(), media,
                              std::move(photons.per_region));
    out.view->result.on_tile = out.on_view_tile;
  }
  if (out.view->medium) charge_grid_share(p, out.view->medium->grid_build());
  out.media_end_s[std::size_t(p.id())] = p.now_seconds();
  if (p.id() == 0) out.radiosity = std::move(mine);
  out.view->job->program(p, out.view->result);
}

void finish(UnifiedRender& out) {
  if (out.view) out.view->job->finish(out.view->result);
}

}  // namespace gcsim::render
