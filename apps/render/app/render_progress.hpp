#pragma once
// One progress line for a whole render: the passes that run (the media's photons, radiosity, the
// view with its specular and shadow rays) each weighted by the plan's estimate of its time
// (plan_cost.hpp), so the line goes once from 0 to 100 % and names the pass that runs.
#include <array>
#include <string_view>

#include "apps/pipeline/progress.hpp"
#include "apps/render/plan.hpp"
#include "machine/machine_config.hpp"

namespace gcsim::render::app {

class RenderProgress {
 public:
  // runs: whether each pass runs (PassId order); photons: what the media pass emits.
  RenderProgress(const Plan& plan, const std::array<bool, 5>& runs, const machine::MachineConfig& machine, int nodes,
                 int photons);
  // The pass (media, radiosity or view) has done `fraction` of its work; detail: what it does now.
  void update(PassId pass, double fraction, std::string_view detail);

 private:
  static int stage_of(PassId pass);  // 0 media, 1 radiosity, 2 view
  pipeline::ProgressLine line_{"render", 0};
  std::array<double, 3> share_{};  // of the whole render's estimated time, by stage
  std::array<bool, 3> runs_{};
};

}  // namespace gcsim::render::app
