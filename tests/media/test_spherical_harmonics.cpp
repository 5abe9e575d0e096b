// Real SH to band 3: orthonormality, exact projection/reconstruction, addition theorem, Funk–Hecke.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "apps/common/rng.hpp"
#include "apps/common/media/spherical_harmonics.hpp"
#include "tests/media/quadrature.hpp"

namespace gcsim::media {
namespace {

// ∫_{S²} f(ω) dω by Gauss–Legendre in z times the trapezoid rule in φ.
template <class F>
double sphere_integral(F&& f, int nz, int nphi) {
  std::vector<double> x, w;
  testing::gauss_legendre(nz, x, w);
  double sum = 0.0;
  for (int i = 0; i < nz; ++i) {
    double r = std::sqrt(1 - x[i] * x[i]);
    for (int j = 0; j < nphi; ++j) {
      double phi = 2 * kPi * (j + 0.5) / nphi;
      sum += w[i] * (2 * kPi / nphi) * f(glm::dvec3(r * std::cos(phi), r * std::sin(phi), x[i]));
    }
  }
  return sum;
}

ShBasis project(const std::function<double(const glm::dvec3&)>& f, int nz = 8, int nphi = 16) {
  ShBasis c{};
  for (int i = 0; i < kShCoefficients; ++i)
    c[i] = sphere_integral([&](const glm::dvec3& w) { return f(w) * sh_basis(w)[i]; }, nz, nphi);
  return c;
}

TEST(SphericalHarmonics, BasisIsOrthonormal) {
  for (int i = 0; i < kShCoefficients; ++i)
    for (int j = 0; j < kShCoefficients; ++j) {
      double dot = sphere_integral([&](const glm::dvec3& w) { auto y = sh_basis(w); return y[i] * y[j]; }, 8, 16);
      EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-12) << i << "," << j;
    }
}

TEST(SphericalHarmonics, ConstantAndCosineProjectToKnownCoefficients) {
  const double c = 2.5;
  ShBasis f = project([&](const glm::dvec3&) { return c; });
  EXPECT_NEAR(f[0], c * std::sqrt(4 * kPi), 1e-12);
  ShBasis g = project([](const glm::dvec3& w) { return w.z; });
  EXPECT_NEAR(g[sh_index(1, 0)], std::sqrt(4 * kPi / 3), 1e-12);
  for (int i = 1; i < kShCoefficients; ++i) EXPECT_NEAR(f[i], 0.0, 1e-12);
}

TEST(SphericalHarmonics, ProjectionThenReconstructionIsExactUpToBandThree) {
  apps::Rng rng(99, 3);
  ShCoefficients coeffs{};
  for (float& v : coeffs) v = rng.uniform(-1.0f, 1.0f);
  ShBasis back = project([&](const glm::dvec3& w) { return sh_reconstruct(coeffs, sh_basis(w)); });
  for (int i = 0; i < kShCoefficients; ++i) EXPECT_NEAR(back[i], coeffs[i], 1e-6 * std::abs(coeffs[i]) + 1e-12);
}

TEST(SphericalHarmonics, AdditionTheoremHolds) {  // Σ_m Y_lm(a) Y_lm(b) = (2l+1)/(4π) P_l(a·b)
  apps::Rng rng(5, 5);
  for (int trial = 0; trial < 50; ++trial) {
    auto random_dir = [&] {
      double z = 2 * rng.uniform_double() - 1, phi = 2 * kPi * rng.uniform_double(), r = std::sqrt(1 - z * z);
      return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    glm::dvec3 a = random_dir(), b = random_dir();
    ShBasis ya = sh_basis(a), yb = sh_basis(b);
    for (int l = 0; l < kShBands; ++l) {
      double sum = 0.0;
      for (int m = -l; m <= l; ++m) sum += ya[sh_index(l, m)] * yb[sh_index(l, m)];
      EXPECT_NEAR(sum, (2 * l + 1) / (4 * kPi) * legendre(l, glm::dot(a, b)), 1e-12);
    }
  }
}

TEST(SphericalHarmonics, PhotonCoefficientsEqualFunkHeckeProjection) {
  const glm::dvec3 wp = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  for (Phase phase : {Phase::henyey_greenstein(0.3), Phase::schlick(0.5), Phase::isotropic()}) {
    ShCoefficients f{};
    const double sigma_t = 2.0, flux_over_volume = 3.0;
    sh_add_photon(f, phase, sigma_t, flux_over_volume, wp);
    ShBasis ref = project([&](const glm::dvec3& w) { return phase.eval(glm::dot(wp, w)) * flux_over_volume / sigma_t; },
                          96, 192);
    for (int i = 0; i < kShCoefficients; ++i) EXPECT_NEAR(f[i], ref[i], 1e-6) << i;
  }
}

TEST(SphericalHarmonics, TruncatedPeakedPhaseRingsNegativeAtBackscatter) {
  // One unit photon with HG g: the band-3 reconstruction at u = −1 is Σ (2l+1)/(4π) g^l (−1)^l.
  const glm::dvec3 wp(0, 0, 1);
  for (double g : {0.5, 0.9, 0.99}) {
    ShCoefficients f{};
    sh_add_photon(f, Phase::henyey_greenstein(g), 1.0, 1.0, wp);
    double back = sh_reconstruct(f, sh_basis(-wp));
    double expected = (1 - 3 * g + 5 * g * g - 7 * g * g * g) / (4 * kPi);
    EXPECT_NEAR(back, expected, 1e-6);
    EXPECT_LT(back, 0.0);
  }
}

}  // namespace
}  // namespace gcsim::media
