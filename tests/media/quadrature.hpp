#pragma once
// Reference quadratures for the media tests, independent of the code under test.
#include <cmath>
#include <functional>
#include <vector>

namespace gcsim::media::testing {

inline double simpson_rec(const std::function<double(double)>& f, double a, double b, double fa, double fm,
                          double fb, double whole, double eps, int depth) {
  double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  double flm = f(lm), frm = f(rm);
  double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * eps) return left + right + (left + right - whole) / 15;
  return simpson_rec(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) +
         simpson_rec(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

// ∫_a^b f, adaptive Simpson on `pieces` equal sub-intervals.
inline double integrate(const std::function<double(double)>& f, double a, double b, double eps = 1e-13,
                        int pieces = 16) {
  double sum = 0.0, h = (b - a) / pieces;
  for (int i = 0; i < pieces; ++i) {
    double x0 = a + i * h, x1 = x0 + h, xm = 0.5 * (x0 + x1);
    double f0 = f(x0), fm = f(xm), f1 = f(x1);
    sum += simpson_rec(f, x0, x1, f0, fm, f1, h / 6 * (f0 + 4 * fm + f1), eps / pieces, 20);
  }
  return sum;
}

// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n).
inline void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0), w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5)), pp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p1 = 1.0, p2 = 0.0;
      for (int j = 1; j <= n; ++j) {
        double p3 = p2;
        p2 = p1;
        p1 = ((2.0 * j - 1.0) * z * p2 - (j - 1.0) * p3) / j;
      }
      pp = n * (z * p1 - p2) / (z * z - 1.0);
      double z1 = z;
      z = z1 - p1 / pp;
      if (std::abs(z - z1) < 1e-15) break;
    }
    x[i] = z, w[i] = 2.0 / ((1.0 - z * z) * pp * pp);
  }
}

// Chi-square statistic of observed counts against expected probabilities, merging neighbouring bins
// until each expects at least 5 samples; returns {statistic, degrees of freedom}.
inline std::pair<double, int> chi_square(const std::vector<double>& observed, const std::vector<double>& prob,
                                         double n) {
  double stat = 0.0, obs = 0.0, expd = 0.0;
  int bins = 0;
  for (std::size_t i = 0; i < observed.size(); ++i) {
    obs += observed[i], expd += prob[i] * n;
    if (expd >= 5.0 || i + 1 == observed.size()) {
      stat += (obs - expd) * (obs - expd) / std::max(expd, 1e-300);
      ++bins, obs = 0.0, expd = 0.0;
    }
  }
  return {stat, bins - 1};
}

// Upper 0.1 % critical value of chi-square with k degrees of freedom (Wilson–Hilferty).
inline double chi_square_critical_001(int k) {
  const double z = 3.090232;  // standard normal 99.9 % quantile
  double a = 2.0 / (9.0 * k);
  double c = 1.0 - a + z * std::sqrt(a);
  return k * c * c * c;
}

}  // namespace gcsim::media::testing
