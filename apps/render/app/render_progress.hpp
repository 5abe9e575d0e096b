#pragma once
// One progress line for a whole render: the passes that run, in their order (the media's photons,
// radiosity, then the view with its specular and shadow rays and its marching through media), each
// weighted by `gcsim plan`'s estimate of its time (plan_cost.hpp), with the time left from those
// estimates scaled by how the passes so far ran against theirs (pipeline/pass_progress.hpp). The
// line names the pass that runs and shows 100 % once, when the render is done.
#include <array>
#include <string_view>
#include <vector>

#include "apps/pipeline/pass_progress.hpp"
#include "apps/pipeline/progress.hpp"
#include "apps/render/plan.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::render::app {

enum class RenderStage { photons, radiosity, view };

// The stages that run, in order, with their names and predicted seconds per node. runs: whether
// each pass runs (PassId order); photons: what the media pass emits.
struct RenderStages {
  std::vector<RenderStage> order;
  std::vector<pipeline::PassEstimate> estimates;
};
RenderStages render_stages(const Plan& plan, const std::array<bool, 5>& runs, const machine::MachineConfig& machine,
                           int nodes, int photons);

class RenderProgress {
 public:
  explicit RenderProgress(const RenderStages& stages);
  // `stage` has done `fraction` of its work; detail: what it does now (e.g. "tile 12 of 80").
  void update(RenderStage stage, double fraction, std::string_view detail);
  void finish();  // the render is done: 100 %, once

 private:
  std::vector<RenderStage> order_;
  pipeline::PassProgress model_;
  pipeline::ProgressLine line_{"render", 0};
};

}  // namespace gcsim::render::app
