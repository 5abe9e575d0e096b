#pragma once
// What accuracy costs in time: each estimator renders a scene at equal budgets of
// simulated time (one CPU of the machine, from counted operations, so the budgets are deterministic),
// and its RMSE is taken against a high-sample reference on the same photon map, so the error is the
// estimator's alone. Also the noise spread over the image, the grid's share of the render time, and
// the photon count's effect at a fixed number of samples.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "apps/common/media/estimator.hpp"
#include "apps/media/frame.hpp"
#include "apps/media/media_scene.hpp"

namespace gcsim::media {

struct AccuracyOptions {
  int width = 96, height = 72;
  std::vector<Estimator> estimators{Estimator::uniform, Estimator::transmittance, Estimator::radiance,
                                    Estimator::equiangular, Estimator::mis};
  // Budgets as multiples of the unit: the transmittance estimator's time at M = unit_b · S.
  std::vector<double> budgets{1, 2, 4, 8};
  double unit_b = 1.0;
  // The reference's budget over the largest budget (radiance, two seeds). At 4 the reference's own
  // noise was 4.7 % of exp1's mean, as large as the errors it measures at budget 8; at 16, 2.8 %.
  double reference_factor = 16.0;
  // Renders per estimator for the noise spread, at budgets[spread_budget]. A per-pixel standard
  // deviation from n renders scatters like a chi variable with n − 1 degrees of freedom, which alone
  // gives a p95/median near 1.7 at n = 4 for any estimator; near 1.3 at n = 16.
  int spread_repeats = 16;
  // The radiance density's settings every render uses: defensive_alpha and max_voxel_optical_depth.
  MarchSettings density;
  std::size_t spread_budget = 1;
  std::vector<double> photon_fractions{0.25, 0.5, 1.0};  // of the scene's photons, at fixed samples
  double photon_reference_factor = 4.0;                  // photons of the photon study's reference
  int pilot_stride = 0;            // budget fitting renders every stride-th pixel (0: about 2000 pixels)
  std::uint64_t seed = 1;
  long photons = 0;                // 0: the scene's
};

struct BudgetRow {
  Estimator estimator;
  double budget;                 // in units
  bool fits = false;             // false: the estimator's fixed cost exceeds the budget
  double beta = 0.0;             // M = β S (radiance: M = β c S_h, c = ΣS / ΣS_h)
  double simulated_seconds = 0.0, wall_seconds = 0.0;
  std::uint64_t samples = 0;
  double rmse = 0.0;             // against the reference
  double rmse_net = 0.0;         // with the reference's own noise removed: sqrt(rmse² − σ_ref²)
  double relative_rmse = 0.0;    // rmse_net over the reference's mean
  apps::Image image;             // the render
};

struct PhotonRow {
  std::size_t emitted = 0, stored = 0;
  double wall_seconds = 0.0;
  double rmse = 0.0;             // against the render with photon_reference_factor × the photons
  double mean_bias = 0.0;        // mean(image) / mean(reference) − 1
};

struct SceneAccuracy {
  std::string scene;
  int width = 0, height = 0;
  std::size_t photons_emitted = 0, photons_stored = 0, k = 0;
  double unit_seconds = 0.0;          // the budget unit, simulated seconds
  double grid_build_seconds = 0.0;    // both SH grids, one CPU
  double reference_mean = 0.0, reference_noise = 0.0, reference_seconds = 0.0, reference_wall = 0.0;
  apps::Image reference;
  std::vector<BudgetRow> rows;
  std::vector<std::pair<Estimator, double>> noise_spread;  // p95 / median of per-pixel relative std
  std::vector<std::pair<Estimator, apps::Image>> noise_maps;  // the per-pixel relative std behind it
  std::vector<PhotonRow> photon_rows;
  std::size_t photon_reference_emitted = 0;
  double photon_study_b = 0.0;        // transmittance estimator, M = b S
  const BudgetRow* row(Estimator e, double budget) const;
};

// The march settings of an estimator at parameter β (see BudgetRow::beta), with base's density settings.
MarchSettings settings_at(Estimator e, double beta, double histogram_scale, const MarchSettings& base);

// Measures one scene; `progress` (may be empty) is told what is being rendered.
SceneAccuracy measure_accuracy(MediaScene scene, const AccuracyOptions& o, const machine::MachineConfig& m,
                               const std::function<void(const std::string&)>& progress = {});

}  // namespace gcsim::media
