#include "apps/common/media/spherical_harmonics.hpp"

#include <cmath>

namespace gcsim::media {

namespace {
// Normalization constants of the real Y_lm, from their closed forms (full double precision).
const double kC00 = 0.5 * std::sqrt(1.0 / kPi);
const double kC1 = std::sqrt(3.0 / (4.0 * kPi));
const double kC2a = 0.5 * std::sqrt(15.0 / kPi);
const double kC20 = 0.25 * std::sqrt(5.0 / kPi);
const double kC22 = 0.25 * std::sqrt(15.0 / kPi);
const double kC33 = 0.25 * std::sqrt(35.0 / (2.0 * kPi));
const double kC32 = 0.5 * std::sqrt(105.0 / kPi);
const double kC32h = 0.25 * std::sqrt(105.0 / kPi);
const double kC31 = 0.25 * std::sqrt(21.0 / (2.0 * kPi));
const double kC30 = 0.25 * std::sqrt(7.0 / kPi);
}  // namespace

ShBasis sh_basis(const glm::dvec3& w) {
  const double x = w.x, y = w.y, z = w.z;
  const double x2 = x * x, y2 = y * y, z2 = z * z;
  return {
      kC00,                           // l=0
      kC1 * y,                       // l=1, m=-1
      kC1 * z,                       //      m= 0
      kC1 * x,                       //      m= 1
      kC2a * x * y,                   // l=2, m=-2
      kC2a * y * z,                   //      m=-1
      kC20 * (3.0 * z2 - 1.0),        //      m= 0
      kC2a * x * z,                   //      m= 1
      kC22 * (x2 - y2),               //      m= 2
      kC33 * y * (3.0 * x2 - y2),     // l=3, m=-3
      kC32 * x * y * z,               //      m=-2
      kC31 * y * (5.0 * z2 - 1.0),    //      m=-1
      kC30 * z * (5.0 * z2 - 3.0),    //      m= 0
      kC31 * x * (5.0 * z2 - 1.0),    //      m= 1
      kC32h * z * (x2 - y2),           //      m= 2
      kC33 * x * (x2 - 3.0 * y2),     //      m= 3
  };
}

double sh_reconstruct(const ShCoefficients& f, const ShBasis& y) {
  double sum = 0.0;
  for (int i = 0; i < kShCoefficients; ++i) sum += static_cast<double>(f[i]) * y[i];
  return sum;
}

ShCoefficients sh_project_photon(const Phase& phase, double sigma_t, double power, const glm::dvec3& photon_direction) {
  const ShBasis y = sh_basis(photon_direction);
  const auto& w = phase.legendre_moments();
  const double scale = power / sigma_t;
  ShCoefficients c;
  for (int i = 0; i < kShCoefficients; ++i) c[i] = static_cast<float>(w[sh_band(i)] * scale * y[i]);
  return c;
}

void sh_add_photon(ShCoefficients& f, const Phase& phase, double sigma_t, double flux_over_volume,
                   const glm::dvec3& photon_direction) {
  const ShCoefficients c = sh_project_photon(phase, sigma_t, flux_over_volume, photon_direction);
  for (int i = 0; i < kShCoefficients; ++i) f[i] += c[i];
}

}  // namespace gcsim::media
