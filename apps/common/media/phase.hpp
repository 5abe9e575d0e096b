#pragma once
// Phase functions of the media (paper section 2; Schlick inside the object, isotropic outside), plus
// Henyey–Greenstein. Convention [A2]/[A3]: u = cos θ between the photon's travel direction and the
// direction the light leaves toward the eye (−ray direction); k, g > 0 scatter forward.
// Every phase is normalized, 2π ∫_{-1}^{1} p(u) du = 1, and sampled exactly by inverting its CDF in u.
#include <array>

namespace gcsim::media {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr int kShBands = 4;  // l = 0..3: 16 coefficients (paper section 3.2)

enum class PhaseKind { isotropic, schlick, henyey_greenstein };

class Phase {
 public:
  static Phase isotropic() { return Phase(PhaseKind::isotropic, 0.0); }
  // Schlick: p(u) = (1 − k²) / (4π (1 − k u)²), |k| < 1.
  static Phase schlick(double k);
  // Henyey–Greenstein: p(u) = (1 − g²) / (4π (1 + g² − 2 g u)^{3/2}), |g| < 1.
  static Phase henyey_greenstein(double g);

  PhaseKind kind() const { return kind_; }
  double parameter() const { return param_; }
  double eval(double u) const;
  // Maps a uniform xi in [0, 1) to u with density 2π p(u) on [−1, 1].
  double sample_cos(double xi) const;
  // w'_l = 2π ∫ p(u) P_l(u) du (eq. 29), the Funk–Hecke weights of bands 0..3.
  const std::array<double, kShBands>& legendre_moments() const { return moments_; }

 private:
  Phase(PhaseKind kind, double param);
  PhaseKind kind_;
  double param_;
  std::array<double, kShBands> moments_{};
};

// P_l(u) for l = 0..3.
double legendre(int l, double u);
// 2π ∫ p(u) P_l(u) du by adaptive Simpson quadrature (used for Schlick, and by tests for any phase).
double legendre_moment_quadrature(const Phase& phase, int l);

}  // namespace gcsim::media
