// Every estimator of a camera-ray segment is unbiased against a 65,536-sample reference that uses the
// same photon map (notes acceptance 2), also at σt = 200 and with empty grid cells; the grid mode is σs S_h;
// voxels many mean free paths thick make radiance sampling draw from the transmittance.
#include <gtest/gtest.h>

#include <limits>
#include <utility>

#include <glm/geometric.hpp>

#include "apps/media/photon_tracer_infinite.hpp"
#include "apps/common/media/segment_march.hpp"

namespace gcsim::media {
namespace {

struct FogSetup {
  HomogeneousMedium medium;
  PointLight light;
  std::unique_ptr<PhotonMap> map;
  std::unique_ptr<RadianceGrid> grid;
};

FogSetup make_setup(double sigma_t, double albedo, Phase phase, const UniformGrid& box) {
  FogSetup s{{sigma_t, sigma_t * albedo, 0.0, phase}, {{0.1, 0.15, 0.05}, 1.0}, nullptr, nullptr};
  auto traced = trace_point_light_infinite(s.medium, s.light.position, 4 * kPi, 20000, 10, 77);
  s.map = std::make_unique<PhotonMap>(std::move(traced.photons));
  s.grid = std::make_unique<RadianceGrid>(box, *s.map, s.medium, 40);
  return s;
}

void expect_estimators_unbiased(const FogSetup& s, const SegmentQuery& q, int runs) {
  auto li = [&](const glm::dvec3& x) { return s.map->in_scattered(x, -q.direction, s.medium, 40); };
  MarchSettings ref_settings{Estimator::uniform, 65536.0 / segment_integral(s.medium.sigma_t, q.length)};
  apps::Rng ref_rng(1, 1);
  MarchCounters c;
  const double reference = march_segment_in_scatter(q, ref_settings, li, ref_rng, c);
  ASSERT_GT(reference, 0.0);
  const double inf = std::numeric_limits<double>::infinity();
  // Radiance sampling twice: with the thick-voxel rule (the default) and with the paper's density everywhere.
  const std::pair<Estimator, double> cases[] = {{Estimator::uniform, inf},     {Estimator::transmittance, inf},
                                                {Estimator::radiance, 1.0},    {Estimator::radiance, inf},
                                                {Estimator::equiangular, inf}, {Estimator::mis, inf}};
  for (const auto& [e, max_depth] : cases) {
    MarchSettings settings{e, 4.0 / segment_integral(s.medium.sigma_t, q.length) * 0.75};  // M = 3 samples
    settings.max_voxel_optical_depth = max_depth;
    double sum = 0.0, sum2 = 0.0;
    for (int r = 0; r < runs; ++r) {
      apps::Rng rng(1000 + r, 5);
      double v = march_segment_in_scatter(q, settings, li, rng, c);
      ASSERT_TRUE(std::isfinite(v));
      sum += v, sum2 += v * v;
    }
    double mean = sum / runs, se = std::sqrt(std::max(0.0, sum2 / runs - mean * mean) / runs);
    // The reference has its own (tiny) noise: allow 0.1 % on top of 4 standard errors.
    EXPECT_NEAR(mean, reference, 4 * se + 1e-3 * reference) << estimator_name(e) << " max voxel depth " << max_depth;
  }
}

TEST(SegmentMarch, EveryEstimatorIsUnbiasedAgainstTheSamePhotonMap) {
  UniformGrid box{{-1, -1, -1}, {1, 1, 1}, {6, 6, 6}};
  FogSetup s = make_setup(1.0, 0.8, Phase::schlick(0.5), box);
  const glm::dvec3 o(-1, 0.1, 0.0), d = glm::normalize(glm::dvec3(1, 0.02, 0.01));
  expect_estimators_unbiased(s, {o, d, 1.9, &s.medium, s.grid.get(), s.light}, 400);
}

TEST(SegmentMarch, OpticallyThickAndPeakedPhasesStayFiniteAndUnbiased) {
  UniformGrid box{{-0.2, -0.2, -0.2}, {0.4, 0.4, 0.4}, {8, 8, 8}};  // τ per voxel = 15 at σt = 200
  for (double k : {0.99, -0.9}) {
    FogSetup s = make_setup(200.0, 0.6, Phase::schlick(k), box);
    const glm::dvec3 o(0.0, 0.12, 0.04), d = glm::normalize(glm::dvec3(1, 0.05, 0.0));
    expect_estimators_unbiased(s, {o, d, 0.3, &s.medium, s.grid.get(), s.light}, 400);
  }
}

// Voxels 15 mean free paths thick: radiance sampling draws its distances from the transmittance (the
// same samples, so the same value, as the transmittance estimator with the same M and stream); with
// the rule off, or in voxels a third of a mean free path thick, it uses the histogram and differs.
TEST(SegmentMarch, ThickVoxelsSampleTheTransmittance) {
  auto estimate = [](const FogSetup& s, const SegmentQuery& q, Estimator e, double max_depth) {
    auto li = [&](const glm::dvec3& x) { return s.map->in_scattered(x, -q.direction, s.medium, 40); };
    MarchSettings settings{e, 5.0 / segment_integral(s.medium.sigma_t, q.length)};
    settings.max_voxel_optical_depth = max_depth;
    apps::Rng rng(3, 9);
    MarchCounters c;
    return march_segment_in_scatter(q, settings, li, rng, c);
  };
  const double inf = std::numeric_limits<double>::infinity();
  UniformGrid thick_box{{-0.2, -0.2, -0.2}, {0.4, 0.4, 0.4}, {8, 8, 8}};  // τ per voxel = 15
  FogSetup thick = make_setup(200.0, 0.6, Phase::schlick(0.5), thick_box);
  const SegmentQuery tq{{0.0, 0.12, 0.04}, glm::normalize(glm::dvec3(1, 0.05, 0.0)), 0.3, &thick.medium, thick.grid.get(), thick.light};
  EXPECT_EQ(estimate(thick, tq, Estimator::radiance, 1.0), estimate(thick, tq, Estimator::transmittance, 1.0));
  EXPECT_NE(estimate(thick, tq, Estimator::radiance, inf), estimate(thick, tq, Estimator::transmittance, 1.0));
  EXPECT_NE(estimate(thick, tq, Estimator::radiance, 20.0), estimate(thick, tq, Estimator::transmittance, 1.0));

  UniformGrid thin_box{{-1, -1, -1}, {1, 1, 1}, {6, 6, 6}};  // τ per voxel = 1/3 at σt = 1
  FogSetup thin = make_setup(1.0, 0.8, Phase::schlick(0.5), thin_box);
  const SegmentQuery q{{-1, 0.1, 0.0}, glm::normalize(glm::dvec3(1, 0.02, 0.01)), 1.9, &thin.medium, thin.grid.get(), thin.light};
  EXPECT_NE(estimate(thin, q, Estimator::radiance, 1.0), estimate(thin, q, Estimator::transmittance, 1.0));
  EXPECT_EQ(estimate(thin, q, Estimator::radiance, 1.0), estimate(thin, q, Estimator::radiance, inf));
}

TEST(SegmentMarch, EmptyGridCellsWithLightDoNotBiasRadianceSampling) {
  UniformGrid box{{-1, -1, -1}, {1, 1, 1}, {6, 6, 6}};
  FogSetup s = make_setup(1.0, 0.8, Phase::isotropic(), box);
  for (std::size_t i = 0; i < s.grid->voxels().size(); i += 2) s.grid->voxels()[i] = {};  // h = 0 in half
  const glm::dvec3 o(-1, 0.1, 0.0), d = glm::normalize(glm::dvec3(1, 0.02, 0.01));
  expect_estimators_unbiased(s, {o, d, 1.9, &s.medium, s.grid.get(), s.light}, 400);
}

TEST(SegmentMarch, GridModeIsSigmaSTimesTheCorrectedSh) {
  UniformGrid box{{-1, -1, -1}, {1, 1, 1}, {6, 6, 6}};
  FogSetup s = make_setup(1.0, 0.8, Phase::schlick(0.5), box);
  const glm::dvec3 o(-1, 0.1, 0.0), d = glm::normalize(glm::dvec3(1, 0.02, 0.01));
  SegmentQuery q{o, d, 1.9, &s.medium, s.grid.get(), s.light};
  RayHistogram h = s.grid->histogram(o, d, 0, 1.9);
  double sh = 0.0;
  for (std::size_t i = 0; i < h.values.size(); ++i)
    sh += h.values[i] * std::exp(-h.edges[i]) * -std::expm1(-(h.edges[i + 1] - h.edges[i]));
  apps::Rng rng(1, 1);
  MarchCounters c;
  EXPECT_NEAR(march_segment_in_scatter(q, {Estimator::grid}, [](const glm::dvec3&) { return 0.0; }, rng, c),
              s.medium.sigma_s * sh, 1e-12 * std::abs(sh));
}

}  // namespace
}  // namespace gcsim::media
