#pragma once
// Nonlinear least squares: minimise sum_i r_i(x)^2 by GSL's trust-region Levenberg-Marquardt
// (gsl_multifit_nlinear, Debian's libgsl-dev). GSL is a kept, documented solver with covariance
// estimates; the residuals here are simulations, so the Jacobian is taken by forward differences
// with a step large enough to see past the picosecond rounding of simulated time.
#include <functional>
#include <string>
#include <vector>

namespace gcsim::calibration {

struct LeastSquaresResult {
  std::vector<double> x;
  std::vector<double> sigma;  // standard errors of x from the covariance at the optimum
  std::vector<double> residuals;
  double cost = 0;            // sum of squared residuals
  int iterations = 0;
  int evaluations = 0;
  bool converged = false;
  std::string reason;
};

using Residuals = std::function<std::vector<double>(const std::vector<double>& x)>;

// `m` residuals of `x0.size()` unknowns; needs m >= x0.size(). `step` is the relative (or, for
// a zero component, absolute) finite-difference step.
LeastSquaresResult least_squares(const Residuals& f, std::vector<double> x0, std::size_t m, double step = 1e-3,
                                 int max_iterations = 50);

}  // namespace gcsim::calibration
