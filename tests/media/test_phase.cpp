// Phase functions: normalization, Legendre moments against closed forms, exact samplers (chi-square).
#include <gtest/gtest.h>

#include "apps/common/rng.hpp"
#include "apps/common/media/phase.hpp"
#include "tests/media/quadrature.hpp"

namespace gcsim::media {
namespace {

std::vector<Phase> all_phases() {
  std::vector<Phase> v{Phase::isotropic()};
  for (double p : {0.5, 0.6, -0.5, 0.9, -0.9, 0.99, -0.99}) {
    v.push_back(Phase::schlick(p));
    v.push_back(Phase::henyey_greenstein(p));
  }
  return v;
}

TEST(Phase, EveryPhaseIntegratesToOne) {
  for (const Phase& p : all_phases()) {
    double total = testing::integrate([&](double u) { return 2 * kPi * p.eval(u); }, -1, 1, 1e-13, 400);
    EXPECT_NEAR(total, 1.0, 1e-8) << "kind " << int(p.kind()) << " param " << p.parameter();
  }
}

TEST(Phase, HenyeyGreensteinMomentsAreGToTheL) {
  for (double g : {0.3, -0.5, 0.9, -0.99}) {
    Phase p = Phase::henyey_greenstein(g);
    for (int l = 0; l < kShBands; ++l)
      EXPECT_NEAR(legendre_moment_quadrature(p, l), std::pow(g, l), 1e-7) << "g " << g << " l " << l;
  }
}

TEST(Phase, SchlickMomentsMatchTheNotesAndTheMeanCosine) {
  const double k05[] = {1, .35208, .11249, .03432}, k06[] = {1, .43441, .17203, .06516};
  for (int l = 0; l < kShBands; ++l) {
    EXPECT_NEAR(Phase::schlick(0.5).legendre_moments()[l], k05[l], 5e-6);
    EXPECT_NEAR(Phase::schlick(0.6).legendre_moments()[l], k06[l], 5e-6);
  }
  for (double k : {0.5, -0.9, 0.99}) {  // ḡ = 1/k + (1 − k²)/(2k²) ln((1 − k)/(1 + k))
    double mean_cos = 1 / k + (1 - k * k) / (2 * k * k) * std::log((1 - k) / (1 + k));
    EXPECT_NEAR(Phase::schlick(k).legendre_moments()[1], mean_cos, 1e-7) << k;
  }
}

TEST(Phase, SamplersPassChiSquare) {
  const int n = 200000, bins = 64;
  for (const Phase& p : all_phases()) {
    apps::Rng rng(1234, 7);
    std::vector<double> observed(bins, 0.0), prob(bins, 0.0);
    for (int i = 0; i < n; ++i) {
      double u = p.sample_cos(rng.uniform_double());
      observed[std::min(bins - 1, int((u + 1) / 2 * bins))] += 1;
    }
    for (int b = 0; b < bins; ++b) {
      double lo = -1 + 2.0 * b / bins, hi = lo + 2.0 / bins;
      prob[b] = testing::integrate([&](double u) { return 2 * kPi * p.eval(u); }, lo, hi, 1e-14, 4);
    }
    auto [stat, dof] = testing::chi_square(observed, prob, n);
    EXPECT_LT(stat, testing::chi_square_critical_001(dof)) << "kind " << int(p.kind()) << " " << p.parameter();
  }
}

TEST(Phase, RejectsParametersOutsideTheOpenInterval) {
  EXPECT_THROW(Phase::schlick(1.0), std::invalid_argument);
  EXPECT_THROW(Phase::henyey_greenstein(-1.5), std::invalid_argument);
  EXPECT_THROW(Phase::schlick(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::media
