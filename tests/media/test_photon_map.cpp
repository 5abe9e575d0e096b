// The volume photon map against analytic fluence, and single scattering against closed forms.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "apps/common/rng.hpp"
#include "apps/common/media/photon_map.hpp"
#include "apps/media/photon_tracer_infinite.hpp"
#include "apps/common/media/single_scattering.hpp"
#include "tests/media/quadrature.hpp"

namespace gcsim::media {
namespace {

// Uncollided fluence of a point source Φ: φ(r) = Φ e^{−σt r} / (4π r²). With first-collision photons
// the k-NN estimate has relative standard deviation about 1/√k, and a smoothing bias of about
// (r_k²/10) |∇²φ/φ| (the second-order term of a sphere average); both bound the error below.
TEST(PhotonMap, FluenceOfAPointSourceInAnInfiniteMedium) {
  HomogeneousMedium m{1.0, 0.6, 0.0, Phase::henyey_greenstein(0.3)};
  const double power = 10.0;
  const std::size_t k = 200;
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), power, 200000, 1, 2024);
  PhotonMap map(std::move(traced.photons));
  apps::Rng rng(1, 9);
  for (double r : {0.5, 1.0, 1.5}) {
    for (int trial = 0; trial < 3; ++trial) {
      glm::dvec3 dir = glm::normalize(glm::dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
      glm::dvec3 x = r * dir;
      const double exact = power * std::exp(-m.sigma_t * r) / (4 * kPi * r * r);
      const double r_k = std::sqrt(map.nearest(x, k).radius_squared);
      // ∇²φ/φ for φ = e^{−σ r}/r²: φ''/φ + (2/r) φ'/φ with φ'/φ = −σ − 2/r, φ''/φ = (σ + 2/r)² + 2/r².
      const double lp = -m.sigma_t - 2 / r, lpp = lp * lp + 2 / (r * r);
      const double bias = r_k * r_k / 10 * std::abs(lpp + 2 / r * lp);
      EXPECT_NEAR(map.fluence(x, m.sigma_t, k), exact, exact * (3 / std::sqrt(double(k)) + bias)) << r;
      // In-scattered radiance toward a viewer looking back at the light: p(ω_p·ω_o) φ with ω_o = radial.
      const double li_exact = m.phase.eval(1.0) * exact;
      EXPECT_NEAR(map.in_scattered(x, dir, m, k), li_exact, li_exact * (3 / std::sqrt(double(k)) + bias + 0.05))
          << "angular smear of the photon directions within r_k/r is bounded by 5 % here";
    }
  }
}

TEST(PhotonMap, StoresOnePhotonPerInteractionAndSurvivesAMove) {
  HomogeneousMedium m{2.0, 1.0, 0.0, Phase::isotropic()};
  auto traced = trace_point_light_infinite(m, glm::dvec3(0), 1.0, 1000, 50, 7);
  EXPECT_EQ(traced.photons.size(), traced.flights);
  // Mean number of interactions per photon with albedo 1/2 is 1/(1 − 1/2) = 2 (geometric), here ±4 SE.
  EXPECT_NEAR(traced.photons.size() / 1000.0, 2.0, 4 * std::sqrt(2.0 / 1000));
  PhotonMap a(std::move(traced.photons));
  PhotonMap b(std::move(a));
  EXPECT_EQ(b.nearest(glm::dvec3(0), 5).indices.size(), 5u);
}

TEST(SingleScattering, PointLightWithoutAttenuationMatchesTheClosedForm) {
  HomogeneousMedium m{0.0, 0.3, 0.0, Phase::isotropic()};  // σt = 0: the closed form of notes test 6
  const PointLight light{{0.0, 0.4, 0.0}, 1.0};
  const double h = 0.4, x0 = -1.0, len = 3.0;
  const glm::dvec3 o(x0, 0, 0), dir(1, 0, 0);
  const double exact = m.sigma_s / (4 * kPi * h) * (std::atan((x0 + len) / h) - std::atan(x0 / h));
  Segment s{len, 0.0};
  auto eq = equiangular_for(light, o, dir, s);
  apps::Rng rng(5, 5);
  for (int i = 0; i < 100; ++i) {  // equiangular is exact for every sample here
    double u = rng.uniform_double();
    EXPECT_NEAR(single_scatter(m, light, o, dir, eq, std::span<const double>(&u, 1)), exact, 1e-9 * exact);
  }
  UniformDistance uni(s);
  double sum = 0.0, sum2 = 0.0;
  const int runs = 20000;
  for (int i = 0; i < runs; ++i) {
    double j[4] = {rng.uniform_double(), rng.uniform_double(), rng.uniform_double(), rng.uniform_double()};
    double e = single_scatter(m, light, o, dir, uni, stratified(4, j));
    sum += e, sum2 += e * e;
  }
  double mean = sum / runs, se = std::sqrt((sum2 / runs - mean * mean) / runs);
  EXPECT_NEAR(mean, exact, 4 * se);
}

TEST(SingleScattering, AttenuatedPointLightFiveMeanFreePathsAwayMatchesQuadrature) {
  HomogeneousMedium m{1.0, 0.7, 0.0, Phase::henyey_greenstein(0.5)};
  const PointLight light{{5.0, 0.2, 0.0}, 2.0};
  const glm::dvec3 o(0, 0, 0), dir(1, 0, 0);
  const Segment s{8.0, m.sigma_t};
  auto f = [&](double t) { return m.sigma_s * std::exp(-m.sigma_t * t) * point_light_in_scatter(m, light, o, dir, t); };
  const double exact = testing::integrate(f, 0, 5.0, 1e-14, 64) + testing::integrate(f, 5.0, 8.0, 1e-14, 64);
  TransmittanceDistance tr(s);
  auto eq = equiangular_for(light, o, dir, s);
  for (const DistanceSampler* sampler : {static_cast<const DistanceSampler*>(&tr), static_cast<const DistanceSampler*>(&eq)}) {
    apps::Rng rng(21, 4);
    double sum = 0.0, sum2 = 0.0;
    const int runs = 40000;
    for (int i = 0; i < runs; ++i) {
      double j[4] = {rng.uniform_double(), rng.uniform_double(), rng.uniform_double(), rng.uniform_double()};
      double e = single_scatter(m, light, o, dir, *sampler, stratified(4, j));
      ASSERT_TRUE(std::isfinite(e));
      sum += e, sum2 += e * e;
    }
    double mean = sum / runs, se = std::sqrt((sum2 / runs - mean * mean) / runs);
    EXPECT_NEAR(mean, exact, 4 * se);
  }
}

}  // namespace
}  // namespace gcsim::media
