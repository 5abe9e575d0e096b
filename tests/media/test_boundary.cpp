// The dielectric boundary: Fresnel limits, Snell's law, total internal reflection, sphere hits.
#include <gtest/gtest.h>

#include "apps/common/rng.hpp"
#include "apps/media/boundary.hpp"
#include "apps/media/fresnel.hpp"
#include "apps/common/media/sampling.hpp"

namespace gcsim::media {
namespace {

TEST(Fresnel, NormalIncidenceGrazingAndTotalInternalReflection) {
  const double r0 = (1.5 - 1.0) / (1.5 + 1.0);
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.5), r0 * r0, 1e-15);
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.5, 1.0), r0 * r0, 1e-15);  // reciprocity at normal incidence
  EXPECT_NEAR(fresnel_dielectric(0.0, 1.0, 1.5), 1.0, 1e-12);
  const double critical = std::sqrt(1.0 - 1.0 / (1.5 * 1.5));  // cos of the critical angle from inside
  EXPECT_EQ(fresnel_dielectric(critical - 1e-6, 1.5, 1.0), 1.0);
  EXPECT_LT(fresnel_dielectric(critical + 1e-3, 1.5, 1.0), 1.0);
  // Brewster's angle: tan θ_B = η_t/η_i zeroes r_p, so R = r_s²/2.
  const double theta_b = std::atan(1.5), ci = std::cos(theta_b), ct = std::cos(kPi / 2 - theta_b);
  const double rs = (ci - 1.5 * ct) / (ci + 1.5 * ct);
  EXPECT_NEAR(fresnel_dielectric(ci, 1.0, 1.5), 0.5 * rs * rs, 1e-12);
}

TEST(Fresnel, RefractionObeysSnellAndTirHasNoRefractedRay) {
  apps::Rng rng(3, 3);
  const glm::dvec3 n(0, 0, 1);
  for (int i = 0; i < 1000; ++i) {
    glm::dvec3 d = uniform_sphere(rng.uniform_double(), rng.uniform_double());
    if (d.z >= 0) d.z = -d.z;
    if (d.z > -1e-6) continue;
    for (auto [ei, et] : {std::pair{1.0, 1.5}, std::pair{1.5, 1.0}}) {
      auto t = refract_direction(d, n, ei, et);
      const double sin_i = std::sqrt(1 - d.z * d.z);
      if (ei * sin_i / et >= 1.0) {
        EXPECT_FALSE(t.has_value());
        EXPECT_EQ(fresnel_dielectric(-d.z, ei, et), 1.0);
        continue;
      }
      ASSERT_TRUE(t.has_value());
      EXPECT_NEAR(ei * sin_i, et * std::sqrt(1 - t->z * t->z), 1e-9);
      EXPECT_LT(t->z, 0.0);
      EXPECT_NEAR(glm::length(*t), 1.0, 1e-12);
    }
    glm::dvec3 r = reflect_direction(d, n);
    EXPECT_NEAR(r.z, -d.z, 1e-15);
  }
}

TEST(SphereBoundary, EntersFromOutsideLeavesFromInsideAndMissesTangentially) {
  SphereBoundary s({1, 2, 3}, 0.5);
  auto in = s.intersect({1, 2, 0}, {0, 0, 1}, 0, 100);
  ASSERT_TRUE(in);
  EXPECT_NEAR(in->t, 2.5, 1e-12);
  EXPECT_TRUE(in->entering);
  EXPECT_NEAR(in->normal.z, -1.0, 1e-12);
  auto out = s.intersect({1, 2, 3}, {0, 0, 1}, 0, 100);
  ASSERT_TRUE(out);
  EXPECT_NEAR(out->t, 0.5, 1e-12);
  EXPECT_FALSE(out->entering);
  EXPECT_NEAR(out->normal.z, -1.0, 1e-12);  // faces the ray coming from inside
  EXPECT_FALSE(s.intersect({1.5 + 1e-9, 2, 0}, {0, 0, 1}, 0, 100));
  EXPECT_FALSE(s.intersect({1, 2, 0}, {0, 0, 1}, 0, 2.0));  // hit beyond t_max
  // Far away origin: the stable quadratic keeps the hit exact.
  auto far = s.intersect({1, 2, -1e6}, {0, 0, 1}, 0, 1e7);
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->t, 1e6 + 2.5, 1e-6);
  EXPECT_TRUE(s.inside({1, 2, 3.4}));
  EXPECT_FALSE(s.inside({1, 2, 3.6}));
}

}  // namespace
}  // namespace gcsim::media
