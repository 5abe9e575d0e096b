#include "apps/render/app/render_progress.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/render/plan_cost.hpp"

namespace gcsim::render::app {

namespace {

constexpr std::array<const char*, 3> kStageNames = {"media pass: photons", "radiosity pass", "view pass"};

}  // namespace

int RenderProgress::stage_of(PassId pass) {
  if (pass == PassId::media) return 0;
  if (pass == PassId::radiosity) return 1;
  return 2;  // the view, with the specular and shadow rays it traces
}

RenderProgress::RenderProgress(const Plan& plan, const std::array<bool, 5>& runs, const machine::MachineConfig& machine,
                               int nodes, int photons) {
  CostModel model;
  model.photons = photons;
  std::array<double, 3> seconds{};
  for (const PassPlan& p : plan.passes) {
    if (!runs[static_cast<std::size_t>(p.id)]) continue;
    runs_[static_cast<std::size_t>(stage_of(p.id))] = true;
    PassPlan on = p;
    on.on = true;  // a forced pass costs what it would if the plan had it on
    try {
      const double s = estimate_pass(on, plan.facts, machine, nodes, model).seconds_per_node;
      if (p.id != PassId::media) {
        seconds[static_cast<std::size_t>(stage_of(p.id))] += s;
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
      // The machine file lacks an operation the estimate counts: the passes then weigh alike.
    }
  }
  double total = 0;
  for (double s : seconds) total += s;
  int running = 0;
  for (bool r : runs_) running += r;
  for (std::size_t i = 0; i < 3; ++i)
    share_[i] = !runs_[i] ? 0.0 : total > 0 ? seconds[i] / total : 1.0 / std::max(running, 1);
}

void RenderProgress::update(PassId pass, double fraction, std::string_view detail) {
  const int stage = stage_of(pass);
  double done = 0;
  for (int i = 0; i < stage; ++i) done += share_[static_cast<std::size_t>(i)];
  done += share_[static_cast<std::size_t>(stage)] * std::clamp(fraction, 0.0, 1.0);
  int number = 0, of = 0;
  for (int i = 0; i < 3; ++i) {
    if (!runs_[static_cast<std::size_t>(i)]) continue;
    ++of;
    if (i <= stage) number = of;
  }
  const std::string what = fmt::format("{}, {} of {}", kStageNames[static_cast<std::size_t>(stage)], number, of);
  line_.update_fraction(std::min(done, 1.0), detail.empty() ? what : fmt::format("{}: {}", what, detail));
}

}  // namespace gcsim::render::app
