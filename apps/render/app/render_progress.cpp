#include "apps/render/app/render_progress.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/render/plan_cost.hpp"

namespace gcsim::render::app {

namespace {

// The view's name says what it traces besides camera rays.
std::string view_name(const std::array<bool, 5>& runs) {
  std::vector<std::string> with;
  for (PassId id : {PassId::specular, PassId::shadows, PassId::media})
    if (runs[static_cast<std::size_t>(id)]) with.emplace_back(pass_name(id));
  return with.empty() ? "view" : fmt::format("view ({})", fmt::join(with, ", "));
}

}  // namespace

RenderStages render_stages(const Plan& plan, const std::array<bool, 5>& runs, const machine::MachineConfig& machine,
                           int nodes, int photons) {
  CostModel model;
  model.photons = photons;
  std::array<double, 3> seconds{};  // by RenderStage; 0: unknown (weighs as the others' mean)
  std::array<bool, 3> running{false, false, true};
  for (const PassPlan& p : plan.passes) {
    if (!runs[static_cast<std::size_t>(p.id)]) continue;
    const RenderStage stage = p.id == PassId::media ? RenderStage::photons
                              : p.id == PassId::radiosity ? RenderStage::radiosity : RenderStage::view;
    running[static_cast<std::size_t>(stage)] = true;
    PassPlan on = p;
    on.on = true;  // a forced pass costs what it would if the plan had it on
    try {
      const double s = estimate_pass(on, plan.facts, machine, nodes, model).seconds_per_node;
      if (p.id != PassId::media) {
        seconds[static_cast<std::size_t>(stage)] += s;
        continue;
      }
      // The media pass's estimate holds the photons and the view's marching through the media:
      // the photons alone are its estimate where camera rays march nothing.
      SceneFacts no_marching = plan.facts;
      no_marching.media_opacity = 0.0;
      const double photons_s = estimate_pass(on, no_marching, machine, nodes, model).seconds_per_node;
      seconds[0] += photons_s;
      seconds[2] += s - photons_s;
    } catch (const std::invalid_argument&) {
      // The machine file lacks an operation the estimate counts: this pass weighs as the others.
    }
  }
  constexpr std::array<const char*, 2> kNames = {"media: photons", "radiosity"};
  RenderStages out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!running[i]) continue;
    out.order.push_back(RenderStage(i));
    out.estimates.push_back({i < 2 ? std::string(kNames[i]) : view_name(runs), seconds[i]});
  }
  return out;
}

RenderProgress::RenderProgress(const RenderStages& stages) : order_(stages.order), model_(stages.estimates) {}

void RenderProgress::update(RenderStage stage, double fraction, std::string_view detail) {
  const auto at = std::ranges::find(order_, stage);
  if (at == order_.end()) return;  // a stage that does not run reports nothing
  const pipeline::PassProgressState s = model_.report(int(at - order_.begin()), fraction, line_.elapsed_seconds());
  const std::string what = fmt::format("{}, pass {} of {}", s.pass, s.number, s.of);
  line_.update_fraction(s.fraction, detail.empty() ? what : fmt::format("{}: {}", what, detail), s.seconds_left);
}

void RenderProgress::finish() {
  const pipeline::PassProgressState s = model_.finish();
  line_.finish(fmt::format("{} passes done", s.of));
}

}  // namespace gcsim::render::app
