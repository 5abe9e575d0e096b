#include "apps/common/media/phase.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

namespace gcsim::media {
namespace {

// Parameters this close to 0 are isotropic: the closed forms divide by k or g.
constexpr double kNearlyIsotropic = 1e-6;

double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm,
                        double fb, double whole, double eps, int depth) {
  double m = 0.5 * (a + b);
  double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  double flm = f(lm), frm = f(rm);
  double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15.0 * eps)
    return left + right + (left + right - whole) / 15.0;
  return adaptive_simpson(f, a, m, fa, flm, fm, left, eps / 2, depth - 1) +
         adaptive_simpson(f, m, b, fm, frm, fb, right, eps / 2, depth - 1);
}

void check_parameter(const char* name, double value) {
  if (!(std::abs(value) < 1.0))
    throw std::invalid_argument(std::string("phase: ") + name + " must lie in (-1, 1), got " +
                                std::to_string(value));
}

}  // namespace

double legendre(int l, double u) {
  switch (l) {
    case 0: return 1.0;
    case 1: return u;
    case 2: return 0.5 * (3.0 * u * u - 1.0);
    case 3: return 0.5 * (5.0 * u * u * u - 3.0 * u);
    default: throw std::invalid_argument("legendre: only bands 0..3 are used");
  }
}

double legendre_moment_quadrature(const Phase& phase, int l) {
  auto f = [&](double u) { return 2.0 * kPi * phase.eval(u) * legendre(l, u); };
  // Split at u = ±0.5 and near the forward/backward peaks so that the recursion sees them.
  const double cuts[] = {-1.0, -0.99, -0.9, -0.5, 0.0, 0.5, 0.9, 0.99, 1.0};
  double sum = 0.0;
  for (int i = 0; i + 1 < 9; ++i) {
    double a = cuts[i], b = cuts[i + 1], m = 0.5 * (a + b);
    double fa = f(a), fm = f(m), fb = f(b);
    sum += adaptive_simpson(f, a, b, fa, fm, fb, (b - a) / 6.0 * (fa + 4 * fm + fb), 1e-13, 20);
  }
  return sum;
}

Phase Phase::schlick(double k) {
  check_parameter("Schlick k", k);
  return Phase(PhaseKind::schlick, k);
}

Phase Phase::henyey_greenstein(double g) {
  check_parameter("Henyey-Greenstein g", g);
  return Phase(PhaseKind::henyey_greenstein, g);
}

Phase::Phase(PhaseKind kind, double param) : kind_(kind), param_(param) {
  if (std::abs(param_) < kNearlyIsotropic) kind_ = PhaseKind::isotropic, param_ = 0.0;
  switch (kind_) {
    case PhaseKind::isotropic: moments_ = {1.0, 0.0, 0.0, 0.0}; break;
    case PhaseKind::henyey_greenstein:  // w'_l = g^l, the classic closed form
      moments_ = {1.0, param_, param_ * param_, param_ * param_ * param_};
      break;
    case PhaseKind::schlick: {
      // The quadrature costs about 160 K instructions, and every node's photon pass makes its media's
      // phases anew (a 64-node plan of MEDIA-SMALL made 516, 8 % of its host time): one per k.
      static std::mutex guard;
      static std::map<double, std::array<double, kShBands>> known;
      const std::lock_guard<std::mutex> lock(guard);
      auto [at, added] = known.try_emplace(param_);
      if (added)
        for (int l = 0; l < kShBands; ++l) at->second[l] = legendre_moment_quadrature(*this, l);
      moments_ = at->second;
      break;
    }
  }
}

double Phase::eval(double u) const {
  switch (kind_) {
    case PhaseKind::isotropic: return 1.0 / (4.0 * kPi);
    case PhaseKind::schlick: {
      double d = 1.0 - param_ * u;
      return (1.0 - param_ * param_) / (4.0 * kPi * d * d);
    }
    case PhaseKind::henyey_greenstein: {
      double g = param_;
      double d = 1.0 + g * g - 2.0 * g * u;
      return (1.0 - g * g) / (4.0 * kPi * d * std::sqrt(d));
    }
  }
  return 0.0;
}

double Phase::sample_cos(double xi) const {
  double u = 0.0;
  switch (kind_) {
    case PhaseKind::isotropic: u = 2.0 * xi - 1.0; break;
    case PhaseKind::schlick: {  // inverse CDF: u = (2ξ + k − 1) / (2kξ − k + 1)
      double k = param_;
      u = (2.0 * xi + k - 1.0) / (2.0 * k * xi - k + 1.0);
      break;
    }
    case PhaseKind::henyey_greenstein: {
      double g = param_;
      double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * xi);
      u = (1.0 + g * g - s * s) / (2.0 * g);
      break;
    }
  }
  return std::clamp(u, -1.0, 1.0);
}

}  // namespace gcsim::media
