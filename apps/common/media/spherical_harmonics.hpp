#pragma once
// Real spherical harmonics to band 3 (16 coefficients, paper section 3.2 and appendix), in the usual
// index order i = l(l+1) + m. Real SH are an orthonormal basis like the complex Y_lm of the paper,
// so eqs. (15) and (23–30) hold unchanged with Y* replaced by Y.
#include <array>

#include <glm/vec3.hpp>

#include "apps/common/media/phase.hpp"

namespace gcsim::media {

inline constexpr int kShCoefficients = kShBands * kShBands;
using ShCoefficients = std::array<float, kShCoefficients>;
using ShBasis = std::array<double, kShCoefficients>;

inline constexpr int sh_index(int l, int m) { return l * (l + 1) + m; }
inline constexpr int sh_band(int index) { return index < 1 ? 0 : index < 4 ? 1 : index < 9 ? 2 : 3; }

// Y_lm(ω) for all 16 (l, m); ω must be a unit vector.
ShBasis sh_basis(const glm::dvec3& w);

// Σ f_lm Y_lm(ω) (eq. 15): a 16-term dot product once the basis of the ray direction is known.
double sh_reconstruct(const ShCoefficients& f, const ShBasis& y);

// One photon's Funk–Hecke coefficients (eqs. 23–30), (w'_l / σt) ΔΦ Y_lm(ω_p), before the 1/dV of
// the voxel that counts it: the grid build projects each photon once and reuses it.
ShCoefficients sh_project_photon(const Phase& phase, double sigma_t, double power, const glm::dvec3& photon_direction);

// Adds one photon to a voxel's coefficients via Funk–Hecke (eqs. 23–30):
// f_lm += (w'_l / σt) (ΔΦ / dV) Y_lm(ω_p), with ω_p the photon's travel direction [A9].
void sh_add_photon(ShCoefficients& f, const Phase& phase, double sigma_t, double flux_over_volume,
                   const glm::dvec3& photon_direction);

}  // namespace gcsim::media
