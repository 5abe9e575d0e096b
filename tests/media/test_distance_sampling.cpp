// Segment integrals (eqs. 7, 18), distance samplers (eqs. 8–10, 19–20, equiangular, MIS):
// closed forms vs quadrature, densities integrate to 1, chi-square, zero variance, unbiasedness.
#include <gtest/gtest.h>

#include <algorithm>

#include "apps/common/rng.hpp"
#include "apps/common/media/distance_sampling.hpp"
#include "apps/common/media/medium.hpp"
#include "apps/common/media/segment_estimator.hpp"
#include "tests/media/quadrature.hpp"

namespace gcsim::media {
namespace {

struct Histogram {
  std::vector<double> edges, values;
};

Histogram example_histogram(double length, bool with_holes) {
  Histogram h;
  const double v[] = {0.5, 2.0, 0.0, 1.5, -0.3, 3.0, 0.7};
  for (int i = 0; i <= 7; ++i) h.edges.push_back(length * std::pow(i / 7.0, 1.3));
  for (double x : v) h.values.push_back(with_holes ? x : std::abs(x) + 0.1);
  return h;
}

double histogram_value(const Histogram& h, double t) {
  auto it = std::upper_bound(h.edges.begin() + 1, h.edges.end() - 1, t);
  return h.values[it - (h.edges.begin() + 1)];
}

// ∫ over a histogram's bins piece by piece (the integrand jumps at the edges).
double integrate_bins(const Histogram& h, const std::function<double(double)>& f) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < h.edges.size(); ++i) {
    double a = h.edges[i], b = h.edges[i + 1], eps = 1e-13 * (b - a);  // stay off the jump at b
    s += testing::integrate(f, a, b - eps, 1e-15, 8);
  }
  return s;
}

TEST(SegmentIntegrals, TransmittanceAndSMatchQuadrature) {
  EXPECT_DOUBLE_EQ(transmittance(2.0, 1.5), std::exp(-3.0));
  for (double st : {0.0, 1e-9, 0.3, 1.0, 50.0, 200.0})
    for (double dx : {1e-4, 0.1, 1.0, 3.0}) {
      double ref = testing::integrate([&](double t) { return std::exp(-st * t); }, 0, dx, 1e-16, 64);
      EXPECT_NEAR(segment_integral(st, dx), ref, 1e-9 * ref) << st << " " << dx;
    }
}

TEST(SegmentIntegrals, CorrectedShMatchesQuadratureAndThePaperFormDoesNot) {
  for (double st : {0.5, 2.0, 50.0}) {
    Histogram h = example_histogram(1.0, true);
    HistogramDistance sampler({1.0, st}, h.edges, h.values, 0.1);
    double ref = integrate_bins(h, [&](double t) { return histogram_value(h, t) * std::exp(-st * t); });
    EXPECT_NEAR(sampler.s_h(), ref, 1e-9 * std::abs(ref) + 1e-15) << st;
    double paper = 0.0;  // eq. (18) as printed: Σ h_i S(t_i, t_{i+1}) without e^{−t_i σt}
    for (std::size_t i = 0; i < h.values.size(); ++i)
      paper += h.values[i] * segment_integral(st, h.edges[i + 1] - h.edges[i]);
    EXPECT_GT(std::abs(paper - ref), 0.05 * std::abs(ref)) << st;
  }
}

TEST(DistanceSamplers, DensitiesIntegrateToOne) {
  const double dx = 2.0;
  for (double st : {0.0, 0.7, 5.0, 200.0}) {
    Segment s{dx, st};
    Histogram h = example_histogram(dx, true);
    UniformDistance uni(s);
    TransmittanceDistance tr(s);
    HistogramDistance hist(s, h.edges, h.values, 0.1);
    EquiangularDistance eq(s, 0.6, 0.05);
    EXPECT_NEAR(integrate_bins(h, [&](double t) { return uni.pdf(t); }), 1.0, 1e-9);
    EXPECT_NEAR(integrate_bins(h, [&](double t) { return tr.pdf(t); }), 1.0, 1e-8) << st;
    EXPECT_NEAR(integrate_bins(h, [&](double t) { return hist.pdf(t); }), 1.0, 1e-8) << st;
    double eq_total = testing::integrate([&](double t) { return eq.pdf(t); }, 0, 0.6, 1e-14, 64) +
                      testing::integrate([&](double t) { return eq.pdf(t); }, 0.6, dx, 1e-14, 64);
    EXPECT_NEAR(eq_total, 1.0, 1e-8);
  }
}

TEST(DistanceSamplers, TransmittanceSamplesHaveTheAnalyticMeanAndPassKs) {
  const double st = 1.7, dx = 1.3;
  TransmittanceDistance tr({dx, st});
  apps::Rng rng(42, 1);
  const int n = 100000;
  std::vector<double> t(n);
  double sum = 0.0, sum2 = 0.0;
  for (double& x : t) x = tr.sample(rng.uniform_double()), sum += x, sum2 += x * x;
  double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
  double expected = 1 / st - dx * std::exp(-dx * st) / (1 - std::exp(-dx * st));
  EXPECT_NEAR(mean, expected, 4 * se);
  std::sort(t.begin(), t.end());
  double d = 0.0;
  for (int i = 0; i < n; ++i) {
    double cdf = (1 - std::exp(-st * t[i])) / (1 - std::exp(-st * dx));
    d = std::max({d, std::abs(cdf - double(i) / n), std::abs(cdf - double(i + 1) / n)});
  }
  EXPECT_LT(d * std::sqrt(double(n)), 1.95);  // Kolmogorov–Smirnov at the 0.1 % level
}

TEST(DistanceSamplers, HistogramSamplerPassesChiSquare) {
  for (double st : {0.5, 4.0}) {
    Segment s{1.0, st};
    Histogram h = example_histogram(1.0, true);
    HistogramDistance hist(s, h.edges, h.values, 0.1);
    const int sub = 4, n = 200000;
    std::vector<double> edges;
    for (std::size_t i = 0; i + 1 < h.edges.size(); ++i)
      for (int j = 0; j < sub; ++j) edges.push_back(h.edges[i] + (h.edges[i + 1] - h.edges[i]) * j / sub);
    edges.push_back(1.0);
    std::vector<double> observed(edges.size() - 1, 0.0), prob(edges.size() - 1);
    for (std::size_t b = 0; b < prob.size(); ++b)
      prob[b] = testing::integrate([&](double t) { return hist.pdf(t); }, edges[b], edges[b + 1] - 1e-12, 1e-15, 4);
    apps::Rng rng(8, 8);
    for (int i = 0; i < n; ++i) {
      double t = hist.sample(rng.uniform_double());
      auto it = std::upper_bound(edges.begin() + 1, edges.end() - 1, t);
      observed[it - (edges.begin() + 1)] += 1;
    }
    auto [stat, dof] = testing::chi_square(observed, prob, n);
    EXPECT_LT(stat, testing::chi_square_critical_001(dof)) << st;
  }
}

TEST(ZeroVariance, ConstantRadianceUnderTransmittanceSampling) {
  for (double st : {0.01, 1.0, 200.0}) {
    TransmittanceDistance tr({0.8, st});
    apps::Rng rng(3, 3);
    for (int i = 0; i < 1000; ++i) {
      double u = rng.uniform_double();
      double est = estimate_in_scatter(tr, std::span<const double>(&u, 1), [](double) { return 2.5; });
      EXPECT_NEAR(est, 2.5 * segment_integral(st, 0.8), 1e-6 * 2.5 * segment_integral(st, 0.8));
    }
  }
}

TEST(ZeroVariance, RadianceEqualToTheHistogramUnderRadianceSampling) {
  for (double st : {0.01, 1.0, 200.0}) {
    Histogram h = example_histogram(0.8, false);  // all h > 0: the paper's pure density (α = 0)
    HistogramDistance hist({0.8, st}, h.edges, h.values, 0.0);
    apps::Rng rng(4, 4);
    for (int i = 0; i < 1000; ++i) {
      double u = rng.uniform_double();
      double est = estimate_in_scatter(hist, std::span<const double>(&u, 1), [&](double t) { return histogram_value(h, t); });
      ASSERT_NEAR(est, hist.s_h(), 1e-6 * hist.s_h()) << st << " u " << u;
    }
  }
}

TEST(ZeroVariance, EquiangularMatchesAnInverseSquareSource) {
  const double st = 0.4, delta = 0.7, d = 0.2;
  EquiangularDistance eq({2.0, st}, delta, d);
  auto li = [&](double t) { return std::exp(st * t) / (d * d + (t - delta) * (t - delta)); };
  double exact = testing::integrate([&](double t) { return std::exp(-st * t) * li(t); }, 0, delta, 1e-14, 64) +
                 testing::integrate([&](double t) { return std::exp(-st * t) * li(t); }, delta, 2.0, 1e-14, 64);
  apps::Rng rng(6, 6);
  for (int i = 0; i < 200; ++i) {
    double u = rng.uniform_double();
    EXPECT_NEAR(estimate_in_scatter(eq, std::span<const double>(&u, 1), li), exact, 1e-6 * exact);
  }
}

// Mean of many independent estimates against quadrature, within 4 standard errors.
template <class Estimate>
void expect_unbiased(Estimate&& estimate, double exact, int runs, const char* what) {
  double sum = 0.0, sum2 = 0.0;
  for (int r = 0; r < runs; ++r) {
    double e = estimate(r);
    ASSERT_TRUE(std::isfinite(e)) << what;
    sum += e, sum2 += e * e;
  }
  double mean = sum / runs, se = std::sqrt(std::max(sum2 / runs - mean * mean, 0.0) / runs);
  EXPECT_NEAR(mean, exact, 4 * se + 1e-12 * std::abs(exact)) << what;
}

TEST(Unbiased, EverySamplerOnEmptyCellsAndAPointLight) {
  // Li: a point light at distance d from the ray, plus light in the bins whose histogram is 0 or < 0.
  const double dx = 2.0, delta = 1.1, d = 0.15;
  for (double st : {0.5, 3.0, 200.0}) {
    Segment s{dx, st};
    Histogram h = example_histogram(dx, true);
    auto li = [&](double t) { return 1.0 / (d * d + (t - delta) * (t - delta)) + 0.5; };
    auto f = [&](double t) { return std::exp(-st * t) * li(t); };
    double exact = integrate_bins(h, [&](double t) { return f(t); });
    UniformDistance uni(s);
    TransmittanceDistance tr(s);
    HistogramDistance hist(s, h.edges, h.values, 0.1);
    EquiangularDistance eq(s, delta, d);
    const DistanceSampler* samplers[] = {&uni, &tr, &hist, &eq};
    for (const DistanceSampler* sampler : samplers) {
      apps::Rng rng(11, 2);
      expect_unbiased([&](int) {
        double jitter[8];
        for (double& j : jitter) j = rng.uniform_double();
        auto u = stratified(8, jitter);
        return estimate_in_scatter(*sampler, u, li);
      }, exact, 20000, "single sampler");
    }
    apps::Rng rng(12, 2);
    const DistanceSampler* mis[] = {&tr, &hist, &eq};
    expect_unbiased([&](int) {
      std::vector<double> u[3];
      for (auto& v : u) { double j[4]; for (double& x : j) x = rng.uniform_double(); v = stratified(4, j); }
      return estimate_in_scatter_mis(mis, u, li);
    }, exact, 20000, "mis");
  }
}

TEST(SampleCount, StochasticRoundingKeepsTheMean) {
  for (double m : {0.3, 1.0, 2.75, 10.5}) {
    double sum = 0.0;
    const int n = 10000;
    for (int i = 0; i < n; ++i) sum += stochastic_round(m, (i + 0.5) / n);
    EXPECT_NEAR(sum / n, m, 1e-9);
  }
}

}  // namespace
}  // namespace gcsim::media
