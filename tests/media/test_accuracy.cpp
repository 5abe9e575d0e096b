// The pieces of `gcsim accuracy media` and of the PNG output: error measures, auto exposure, and the
// budget fitting (an estimator given a budget of simulated time spends about that budget).
#include <gtest/gtest.h>

#include <cmath>

#include "apps/common/rng.hpp"
#include "apps/media/accuracy.hpp"
#include "apps/media/image_error.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/common/tone_map.hpp"

namespace gcsim::media {
namespace {

apps::Image filled(int w, int h, float v) {
  apps::Image im(w, h);
  for (auto& p : im.pixels()) p = glm::vec3(v);
  return im;
}

TEST(ImageError, RmseAndMeanOfKnownImages) {
  apps::Image a = filled(4, 3, 1.0f), b = filled(4, 3, 1.0f);
  b.at(0, 0) = glm::vec3(4.0f);  // one error of 3 among 12 pixels
  EXPECT_NEAR(rmse(a, b), std::sqrt(9.0 / 12.0), 1e-12);
  EXPECT_NEAR(mean_value(b), 15.0 / 12.0, 1e-12);
  EXPECT_THROW(rmse(a, filled(3, 4, 1.0f)), std::invalid_argument);
}

// Noise proportional to the reference everywhere has spread near 1; noise of constant size over a
// reference that spans two orders of magnitude has a much larger spread.
TEST(ImageError, NoiseSpreadSeesUnevenRelativeNoise) {
  const int w = 64, h = 64, repeats = 16;
  apps::Image ref(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) ref.at(x, y) = glm::vec3(std::pow(10.0f, -2.0f * float(x) / float(w - 1)) + 0.0f);
  apps::Rng rng(3, 4);
  auto gauss = [&rng] { return std::sqrt(-2 * std::log(1 - rng.uniform_double())) * std::cos(6.283185307 * rng.uniform_double()); };
  std::vector<apps::Image> proportional, constant;
  for (int r = 0; r < repeats; ++r) {
    apps::Image p = ref, c = ref;
    for (std::size_t i = 0; i < ref.pixels().size(); ++i) {
      p.pixels()[i] += glm::vec3(float(0.1 * ref.pixels()[i].x * gauss()));
      c.pixels()[i] += glm::vec3(float(0.01 * gauss()));
    }
    proportional.push_back(p), constant.push_back(c);
  }
  const double even = relative_noise_spread(proportional, ref, 0.0), uneven = relative_noise_spread(constant, ref, 0.0);
  EXPECT_LT(even, 1.6);    // p95/median of a chi distribution with 16 degrees of freedom: about 1.4
  EXPECT_GT(uneven, 5.0);  // relative noise ∝ 1/ref: p95/median near 10^(2·0.45) ≈ 8
}

// The per-pixel std is taken about the renders' own mean: renders that agree with each other show no
// noise however far the (noisy) reference is from them, and the std is the unbiased sample std.
TEST(ImageError, NoiseMapIsAboutTheRendersOwnMean) {
  const apps::Image ref = filled(4, 3, 2.0f);
  const std::vector<apps::Image> same{filled(4, 3, 3.0f), filled(4, 3, 3.0f)};
  const apps::Image agree = relative_noise_map(same, ref, 0.0);
  for (const glm::vec3& p : agree.pixels()) EXPECT_EQ(p.x, 0.0f);
  const std::vector<apps::Image> two{filled(4, 3, 1.0f), filled(4, 3, 3.0f)};  // sample std sqrt(2)
  const apps::Image spread = relative_noise_map(two, ref, 0.0);
  for (const glm::vec3& p : spread.pixels()) EXPECT_NEAR(p.x, std::sqrt(2.0) / 2.0, 1e-6);
  EXPECT_THROW(relative_noise_map({ref}, ref), std::invalid_argument);
  // Unlit pixels (reference at most `lit` x the mean) are left out: 0 in the map.
  apps::Image dim = ref;
  dim.at(0, 0) = glm::vec3(0.01f);
  EXPECT_EQ(relative_noise_map(two, dim, 0.05).at(0, 0).x, 0.0f);
}

TEST(ToneMap, ThePercentileMapsToWhiteAndFaintValuesKeepTheirRatio) {
  apps::Image im(100, 1);
  for (int x = 0; x < 100; ++x) im.at(x, 0) = glm::vec3(float(x + 1));  // 1 .. 100
  const apps::ToneMap t{0.99, 4.0};
  const double exposure = apps::auto_exposure(im, t);
  EXPECT_NEAR(exposure, 4.0 / 99.0, 1e-9);  // the 99th percentile of 1..100 (index 98) is 99
  const apps::Image out = apps::tone_mapped(im, exposure, t);
  EXPECT_NEAR(out.at(98, 0).x, 1.0, 1e-6);  // x = white → 1
  for (int x = 1; x < 100; ++x) EXPECT_GT(out.at(x, 0).x, out.at(x - 1, 0).x);  // monotone
  EXPECT_EQ(apps::auto_exposure(filled(3, 3, 0.0f), t), 1.0);  // all black: no division by zero
}

MediaScene tiny(const std::string& name) {
  MediaScene s = load_media_scene(name);
  s.photons_emitted = 3000, s.k_nearest = 30;
  return s;
}

// Each estimator's β is fitted on a pilot of every 4th pixel, then the whole image renders: its
// simulated seconds (from counted operations) must land near the budget, so the comparison is at
// equal time. The sample counts are random (stochastic rounding of M), hence the tolerance.
TEST(Accuracy, EveryEstimatorSpendsItsBudget) {
  AccuracyOptions o;
  o.width = 32, o.height = 24, o.budgets = {2, 4}, o.reference_factor = 2, o.spread_repeats = 2;
  o.photon_fractions = {};
  const SceneAccuracy a = measure_accuracy(tiny("small"), o, machine::published_machine_config());
  ASSERT_EQ(a.rows.size(), o.budgets.size() * o.estimators.size());
  for (const BudgetRow& r : a.rows) {
    ASSERT_TRUE(r.fits) << estimator_name(r.estimator);
    EXPECT_NEAR(r.simulated_seconds, r.budget * a.unit_seconds, 0.15 * r.budget * a.unit_seconds)
        << estimator_name(r.estimator) << " at " << r.budget;
    EXPECT_TRUE(std::isfinite(r.rmse));
  }
  EXPECT_EQ(a.noise_spread.size(), o.estimators.size());
  EXPECT_GT(a.grid_build_seconds, 0.0);
  EXPECT_GT(a.reference_mean, 0.0);
}

}  // namespace
}  // namespace gcsim::media
