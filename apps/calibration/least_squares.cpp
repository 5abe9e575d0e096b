#include "apps/calibration/least_squares.hpp"

#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "parix/host/interruption.hpp"

namespace gcsim::calibration {
namespace {

struct Problem {
  const Residuals* f;
  std::size_t m;
  int evaluations = 0;
  std::string failure;  // what the last failed evaluation said
  std::exception_ptr interrupted;  // SIGINT/SIGTERM: not a failed point, the end of the fit
};

int gsl_residuals(const gsl_vector* x, void* data, gsl_vector* out) {
  auto* p = static_cast<Problem*>(data);
  std::vector<double> xs(x->size);
  for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = gsl_vector_get(x, i);
  std::vector<double> r;
  if (p->interrupted) return GSL_EDOM;  // GSL may try another point: refuse at once
  try {
    r = (*p->f)(xs);
  } catch (const parix::host::Interrupted&) {
    p->interrupted = std::current_exception();  // rethrown once GSL has returned (C frames in between)
    return GSL_EDOM;
  } catch (const std::exception& e) {
    p->failure = e.what();  // e.g. a simulated clock overflow at an extreme trial point
    return GSL_EDOM;
  }
  ++p->evaluations;
  if (r.size() != p->m) return GSL_EBADLEN;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (!std::isfinite(r[i])) return GSL_EDOM;
    gsl_vector_set(out, i, r[i]);
  }
  return GSL_SUCCESS;
}

}  // namespace

LeastSquaresResult least_squares(const Residuals& f, std::vector<double> x0, std::size_t m, double step,
                                 int max_iterations) {
  const std::size_t n = x0.size();
  if (n == 0 || m < n) throw std::invalid_argument("least squares: need at least as many measured figures as free parameters");
  Problem problem{&f, m, 0, {}, {}};
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = gsl_residuals;
  fdf.df = nullptr;  // forward differences
  fdf.n = m;
  fdf.p = n;
  fdf.params = &problem;
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  params.trs = gsl_multifit_nlinear_trs_lm;
  params.h_df = step;
  gsl_set_error_handler_off();
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, m, n);
  gsl_vector_view start = gsl_vector_view_array(x0.data(), n);
  gsl_multifit_nlinear_init(&start.vector, &fdf, w);
  int info = 0;
  const int status = gsl_multifit_nlinear_driver(max_iterations, 1e-6, 1e-8, 1e-8, nullptr, nullptr, &info, w);
  if (problem.interrupted) {
    gsl_multifit_nlinear_free(w);
    std::rethrow_exception(problem.interrupted);
  }

  LeastSquaresResult out;
  out.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w));
  out.converged = status == GSL_SUCCESS;
  out.reason = status == GSL_SUCCESS ? (info == 1 ? "small step" : "small gradient") : gsl_strerror(status);
  if (status != GSL_SUCCESS && !problem.failure.empty()) out.reason += " (" + problem.failure + ")";
  const gsl_vector* x = gsl_multifit_nlinear_position(w);
  const gsl_vector* r = gsl_multifit_nlinear_residual(w);
  for (std::size_t i = 0; i < n; ++i) out.x.push_back(gsl_vector_get(x, i));
  for (std::size_t i = 0; i < m; ++i) out.residuals.push_back(gsl_vector_get(r, i));
  gsl_blas_ddot(r, r, &out.cost);
  // Covariance of x: (J^T J)^-1 scaled by the residual variance per degree of freedom.
  gsl_matrix* covar = gsl_matrix_alloc(n, n);
  gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, covar);
  const double dof = m > n ? static_cast<double>(m - n) : 1.0;
  for (std::size_t i = 0; i < n; ++i) out.sigma.push_back(std::sqrt(std::max(0.0, gsl_matrix_get(covar, i, i) * out.cost / dof)));
  gsl_matrix_free(covar);
  gsl_multifit_nlinear_free(w);
  out.evaluations = problem.evaluations;
  return out;
}

}  // namespace gcsim::calibration
