#pragma once
// A homogeneous medium (paper section 2: homogeneous per region, inside and outside the object) and
// the closed forms of the transfer equation along one segment of length Δx.
#include <cmath>

#include "apps/common/media/phase.hpp"

namespace gcsim::media {

struct HomogeneousMedium {
  double sigma_t = 1.0;  // extinction σt
  double sigma_s = 0.0;  // scattering σs (≤ σt); σa = σt − σs
  double emission = 0.0; // Le
  Phase phase = Phase::isotropic();

  double sigma_a() const { return sigma_t - sigma_s; }
  double albedo() const { return sigma_t > 0 ? sigma_s / sigma_t : 0.0; }
};

// γ(x0, x) = exp(−σt d) in a homogeneous medium (eq. 2).
inline double transmittance(double sigma_t, double distance) { return std::exp(-sigma_t * distance); }

// S = ∫_0^{Δx} e^{−σt t} dt = (1 − e^{−Δx σt}) / σt (eq. 7); expm1 keeps it exact for small σt Δx,
// and S → Δx as σt → 0.
inline double segment_integral(double sigma_t, double length) {
  if (sigma_t * length < 1e-300) return length;
  return -std::expm1(-sigma_t * length) / sigma_t;
}

}  // namespace gcsim::media
