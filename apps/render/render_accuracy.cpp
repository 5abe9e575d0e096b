#include "apps/render/render_accuracy.hpp"

#include <cmath>
#include <stdexcept>

#include "apps/radiosity/radiosity.hpp"
#include "apps/render/render_setup.hpp"
#include "apps/render/unified_render.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::render {

RenderControls reference_controls() { return {512, 0.9999, 10, 200000, 128}; }

RenderRun render_with(const scene::SceneDescription& d, const Plan& plan, const RenderControls& c, double exposure,
                      const parix::SimulationOptions& machine) {
  RenderSetup setup = prepare_render(d, plan, d.name, {}, c.photons, c.media, c.seed);
  if (setup.media) setup.media->view.samples_per_free_path = c.march;
  radiosity::ParallelOptions options;
  options.solver.hemicube.resolution = c.hemicube;
  options.solver.energy = c.energy;
  options.solver.media = setup.radiosity_media_or_null();
  const radiosity::ParallelOptions shared = radiosity::with_shared_projections(options);
  ViewSettings view;
  view.secondary = plan.pass(PassId::specular).on;
  view.shadows = plan.pass(PassId::shadows).on;
  view.max_depth = c.max_depth;
  view.exposure = exposure;
  UnifiedRender out(machine.config.nodes);
  const parix::RunResult run = parix::run_simulated(machine, [&](parix::Processor& p) {
    unified_render_program(p, setup.split.surfaces, setup.mesh_or_null(), shared, view, setup.media.get(), out);
  });
  finish(out);
  return {std::move(out.view->result.image), out.view->exposure, run.simulated_seconds(), run.wall_seconds};
}

double relative_rmse(const apps::Image& image, const apps::Image& reference) {
  if (image.width() != reference.width() || image.height() != reference.height())
    throw std::invalid_argument("relative_rmse: images of different sizes");
  double sum_sq = 0, sum_ref = 0;
  for (std::size_t i = 0; i < reference.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels()[i][c], d = image.pixels()[i][c] - r;
      sum_sq += d * d;
      sum_ref += r;
    }
  const double n = 3.0 * double(reference.pixels().size());
  return sum_ref > 0 ? std::sqrt(sum_sq / n) / (sum_ref / n) : std::sqrt(sum_sq / n);
}

std::vector<ControlSweep> control_sweeps(const Plan& plan, bool quick) {
  std::vector<ControlSweep> sweeps;
  if (plan.pass(PassId::radiosity).on) {
    sweeps.push_back({PassId::radiosity, "hemicube", quick ? std::vector<double>{32, 128} : std::vector<double>{32, 64, 128, 256}});
    sweeps.push_back({PassId::radiosity, "energy", quick ? std::vector<double>{0.9, 0.99} : std::vector<double>{0.9, 0.99, 0.999}});
  }
  if (plan.pass(PassId::specular).on)
    sweeps.push_back({PassId::specular, "depth", quick ? std::vector<double>{1, 3} : std::vector<double>{1, 2, 3, 5}});
  if (plan.pass(PassId::media).on) {
    sweeps.push_back({PassId::media, "photons", quick ? std::vector<double>{10000, 50000} : std::vector<double>{10000, 20000, 50000}});
    sweeps.push_back({PassId::media, "march", quick ? std::vector<double>{8, 32} : std::vector<double>{8, 16, 32}});
  }
  return sweeps;
}

RenderControls with_control(RenderControls c, const std::string& control, double value) {
  if (control == "hemicube") c.hemicube = int(value);
  else if (control == "energy") c.energy = value;
  else if (control == "depth") c.max_depth = int(value);
  else if (control == "photons") c.photons = std::size_t(value);
  else if (control == "march") c.march = value;
  else throw std::invalid_argument("unknown render control '" + control + "'");
  return c;
}

}  // namespace gcsim::render
