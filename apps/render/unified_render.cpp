#include "apps/render/unified_render.hpp"

#include <algorithm>

namespace gcsim::render {

double UnifiedRender::radiosity_seconds() const {
  return radiosity_end_s.empty() ? 0.0 : *std::max_element(radiosity_end_s.begin(), radiosity_end_s.end());
}

void unified_render_program(parix::Processor& p, const scene::SceneDescription& description,
                            const radiosity::Scene* mesh, const radiosity::ParallelOptions& options, ViewSettings view,
                            UnifiedRender& out) {
  radiosity::ParallelOutcome mine;
  if (mesh) mine = radiosity::solve_replica(p, *mesh, options);
  out.radiosity_end_s[std::size_t(p.id())] = p.now_seconds();
  if (!out.view) {
    out.view = make_view_pass(description, mesh, mesh ? &mine.element_radiosity : nullptr, view, p.count());
    out.view->result.on_tile = out.on_view_tile;
  }
  if (p.id() == 0) out.radiosity = std::move(mine);
  out.view->job->program(p, out.view->result);
}

void finish(UnifiedRender& out) {
  if (out.view) out.view->job->finish(out.view->result);
}

}  // namespace gcsim::render
