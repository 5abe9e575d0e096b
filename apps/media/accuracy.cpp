#include "apps/media/accuracy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "apps/media/image_error.hpp"
#include "apps/media/photon_tracer.hpp"

namespace gcsim::media {

const BudgetRow* SceneAccuracy::row(Estimator e, double budget) const {
  for (const BudgetRow& r : rows)
    if (r.estimator == e && r.budget == budget) return &r;
  return nullptr;
}

MarchSettings settings_at(Estimator e, double beta, double histogram_scale, const MarchSettings& base) {
  MarchSettings s = base;
  s.estimator = e, s.b = beta, s.b_histogram = 0.0;
  s.at_least_one_sample = true;  // M < 1: one sample; stochastic rounding leaves 1/M weights of 50 on the object
  if (e == Estimator::radiance) s.b_histogram = beta * histogram_scale;  // eq. (22), as the paper's (c)
  return s;
}

namespace {

constexpr std::uint64_t kPilotSeed = 0x70696c6f74ULL;

// Predicts a whole image's simulated seconds from a pilot over every stride-th pixel: the part that
// does not grow with β (camera rays, histograms) and the total.
struct CostModel {
  const MediaScene& scene;
  const SceneCaches& caches;
  const machine::MachineConfig& m;
  int stride;
  MarchSettings density;

  struct Cost {
    double fixed, total;
    RenderCounters counters;
  };
  Cost predict(const MarchSettings& s) const {
    const Frame f = render_frame(scene, caches, s, kPilotSeed, m, stride);
    const double across = std::ceil(scene.image.width / double(stride));
    const double down = std::ceil(scene.image.height / double(stride));
    const double scale = double(scene.image.width) * scene.image.height / (across * down);
    RenderCounters fixed = f.counters;
    fixed.march.samples = 0;
    return {scale * render_seconds(fixed, scene.k_nearest, m), scale * f.simulated_seconds, f.counters};
  }
  // The β at which estimator e costs `target` seconds; nothing if its fixed cost is too high. The
  // sample count is not linear in β (at least one sample per segment, MIS's per-technique counts rounded
  // up): secant steps on the pilot until the prediction settles.
  std::optional<double> fit(Estimator e, double target, double histogram_scale) const {
    double beta = 1.0, predicted = 0.0;
    for (int step = 0; step < 6; ++step) {
      const Cost c = predict(settings_at(e, beta, histogram_scale, density));
      predicted = c.total;
      if (target <= c.fixed * 1.01) return std::nullopt;
      if (std::abs(c.total / target - 1.0) < 0.01) break;
      beta = c.total > c.fixed ? beta * (target - c.fixed) / (c.total - c.fixed) : beta * 4.0;
    }
    if (predicted > 1.1 * target) return std::nullopt;  // one sample per segment already costs more
    return beta;
  }
};

SceneCaches caches_for(const MediaScene& scene, bool with_grids) {
  return build_caches(scene, trace_photons(scene, 0, scene.photons_emitted), with_grids);
}

std::size_t stored(const SceneCaches& c) {
  return (c.outside.map ? c.outside.map->photons().size() : 0) + (c.inside.map ? c.inside.map->photons().size() : 0);
}

void measure_photon_effect(const MediaScene& scene, const AccuracyOptions& o, const machine::MachineConfig& m,
                           double b, SceneAccuracy& out, const std::function<void(const std::string&)>& progress) {
  MediaScene ref_scene = scene;
  ref_scene.photons_emitted = static_cast<std::size_t>(double(scene.photons_emitted) * o.photon_reference_factor);
  out.photon_reference_emitted = ref_scene.photons_emitted;
  out.photon_study_b = b;
  if (progress) progress(fmt::format("photon reference, {} photons", ref_scene.photons_emitted));
  const SceneCaches ref_caches = caches_for(ref_scene, false);
  const Frame ref = render_frame(ref_scene, ref_caches, settings_at(Estimator::transmittance, 4.0 * b, 0.0, o.density),
                                 o.seed + 3, m);
  for (double fraction : o.photon_fractions) {
    MediaScene s = scene;
    s.photons_emitted = std::max<std::size_t>(1, static_cast<std::size_t>(double(scene.photons_emitted) * fraction));
    if (progress) progress(fmt::format("{} photons", s.photons_emitted));
    const auto start = std::chrono::steady_clock::now();
    const SceneCaches caches = caches_for(s, false);
    const Frame f = render_frame(s, caches, settings_at(Estimator::transmittance, b, 0.0, o.density), o.seed + 4, m);
    PhotonRow r;
    r.emitted = s.photons_emitted;
    r.stored = stored(caches);
    r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.rmse = rmse(f.image, ref.image);
    r.mean_bias = mean_value(f.image) / mean_value(ref.image) - 1.0;
    out.photon_rows.push_back(r);
  }
}

}  // namespace

SceneAccuracy measure_accuracy(MediaScene scene, const AccuracyOptions& o, const machine::MachineConfig& m,
                               const std::function<void(const std::string&)>& progress) {
  scene.image.width = o.width, scene.image.height = o.height;
  if (o.photons > 0) scene.photons_emitted = static_cast<std::size_t>(o.photons);
  scene.seed = o.seed;
  SceneAccuracy out;
  out.scene = scene.name, out.width = o.width, out.height = o.height;
  out.photons_emitted = scene.photons_emitted, out.k = scene.k_nearest;
  if (progress) progress("photon pass and SH grids");
  const SceneCaches caches = caches_for(scene, true);
  out.photons_stored = stored(caches);
  out.grid_build_seconds = grid_build_seconds(caches.grid_build, m);

  const int stride = o.pilot_stride > 0 ? o.pilot_stride
                                         : std::max(1, int(std::sqrt(double(o.width) * o.height / 2000.0)));
  const CostModel model{scene, caches, m, stride, o.density};
  const CostModel::Cost radiance_pilot = model.predict(settings_at(Estimator::radiance, 1.0, 0.0, o.density));
  const double histogram_scale = radiance_pilot.counters.march.integral_s_h > 0.0
                                     ? radiance_pilot.counters.march.integral_s / radiance_pilot.counters.march.integral_s_h
                                     : 0.0;
  out.unit_seconds = model.predict(settings_at(Estimator::transmittance, o.unit_b, 0.0, o.density)).total;
  const double largest = *std::max_element(o.budgets.begin(), o.budgets.end());

  // The reference: radiance sampling (the lowest variance per time in every scene we tried; any
  // unbiased estimator converges to the same image) at reference_factor × the largest budget, as two
  // halves with their own seeds, whose difference measures the reference's own noise.
  if (progress) progress("reference");
  const double half = 0.5 * o.reference_factor * largest * out.unit_seconds;
  const MarchSettings ref_settings =
      settings_at(Estimator::radiance, model.fit(Estimator::radiance, half, histogram_scale).value_or(1.0), histogram_scale,
                  o.density);
  const Frame ref_a = render_frame(scene, caches, ref_settings, o.seed + 1000, m);
  const Frame ref_b = render_frame(scene, caches, ref_settings, o.seed + 2000, m);
  out.reference = mean_image({ref_a.image, ref_b.image});
  const apps::Image& reference = out.reference;
  out.reference_mean = mean_value(reference);
  out.reference_noise = rmse(ref_a.image, ref_b.image) / 2.0;
  out.reference_seconds = ref_a.simulated_seconds + ref_b.simulated_seconds;
  out.reference_wall = ref_a.wall_seconds + ref_b.wall_seconds;

  for (Estimator e : o.estimators) {
    std::vector<apps::Image> repeats;
    for (std::size_t bi = 0; bi < o.budgets.size(); ++bi) {
      BudgetRow r;
      r.estimator = e, r.budget = o.budgets[bi];
      if (progress) progress(fmt::format("{} at {} units", estimator_name(e), r.budget));
      const auto beta = model.fit(e, r.budget * out.unit_seconds, histogram_scale);
      if (beta) {
        r.fits = true, r.beta = *beta;
        const MarchSettings s = settings_at(e, *beta, histogram_scale, o.density);
        const Frame f = render_frame(scene, caches, s, o.seed, m);
        r.simulated_seconds = f.simulated_seconds, r.wall_seconds = f.wall_seconds, r.samples = f.counters.march.samples;
        r.rmse = rmse(f.image, reference);
        r.rmse_net = std::sqrt(std::max(0.0, r.rmse * r.rmse - out.reference_noise * out.reference_noise));
        r.relative_rmse = out.reference_mean > 0.0 ? r.rmse_net / out.reference_mean : 0.0;
        r.image = f.image;
        if (bi == o.spread_budget) {
          repeats.push_back(f.image);
          for (int k = 1; k < o.spread_repeats; ++k)
            repeats.push_back(render_frame(scene, caches, s, o.seed + 7919 * std::uint64_t(k), m).image);
        }
      }
      out.rows.push_back(r);
    }
    if (repeats.size() >= 2) {
      out.noise_spread.emplace_back(e, relative_noise_spread(repeats, reference));
      out.noise_maps.emplace_back(e, relative_noise_map(repeats, reference));
    }
  }
  if (!o.photon_fractions.empty()) measure_photon_effect(scene, o, m, o.unit_b * largest, out, progress);
  return out;
}

}  // namespace gcsim::media
