// The paper scenes: the two readings of experiment 1's inside σs = (0.8, 0.9, 0.8) [notes A14] and the
// property that tells them apart, and the uniformly lit fog case.
#include <gtest/gtest.h>

#include "apps/media/builtin_scenes.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/media/photon_tracer.hpp"

namespace gcsim::media {
namespace {

constexpr double kLuminance = 0.2126 * 0.8 + 0.7152 * 0.9 + 0.0722 * 0.8;

TEST(Experiment1, TheTwoReadingsDifferOnlyInTheInsideScatteringCoefficient) {
  const MediaScene albedo = load_media_scene("exp1"), literal = load_media_scene("exp1-literal");
  EXPECT_EQ(albedo.inside.sigma_t, 50.0);
  EXPECT_EQ(literal.inside.sigma_t, 50.0);
  EXPECT_NEAR(albedo.inside.albedo(), kLuminance, 1e-12);         // (0.8, 0.9, 0.8) read as the albedo
  EXPECT_NEAR(literal.inside.sigma_s, kLuminance, 1e-12);         // read as σs: albedo 0.0174
  EXPECT_EQ(albedo.outside.sigma_s, literal.outside.sigma_s);
  EXPECT_EQ(albedo.photons_emitted, 100000u);
  EXPECT_EQ(albedo.image.width, 640);
  EXPECT_EQ(albedo.image.height, 480);
}

// What distinguishes the readings in the photon pass: a photon entering the object interacts
// 1/(1 − albedo) times on average in an infinite medium, and fewer in the sphere (escapes only end
// walks early). Literally read, nearly every entering photon interacts exactly once and is absorbed
// (the object is a dark absorber); read as the albedo, it scatters several times (it glows).
TEST(Experiment1, InteractionsPerEnteringPhotonAreBoundedByTheAlbedo) {
  for (Exp1Reading reading : {Exp1Reading::literal, Exp1Reading::albedo}) {
    MediaScene s = lower_media_scene(experiment1_description(reading));
    s.photons_emitted = 80000;  // about 1 in 75 enters the sphere
    const PhotonPassResult r = trace_photons(s, 0, s.photons_emitted);
    ASSERT_GT(r.entered, 500u);
    const double per_entry = double(r.inside.size()) / double(r.entered);
    const double bound = 1.0 / (1.0 - s.inside.albedo());
    // 3 standard errors of a mean of r.entered walks (walk lengths have variance below bound²).
    const double slack = 3.0 * bound / std::sqrt(double(r.entered));
    EXPECT_LT(per_entry, bound + slack) << s.name;
    if (reading == Exp1Reading::literal) {
      EXPECT_GT(per_entry, 0.95) << "σt = 50: the first flight ends inside";
    } else {
      EXPECT_GT(per_entry, 2.0) << "albedo 0.87: several scatterings per entering photon";
    }
  }
}

TEST(UniformFog, InScatteredRadianceVariesLittleAlongAViewRay) {
  MediaScene s = load_media_scene("fog");
  s.photons_emitted = 20000;
  EXPECT_FALSE(s.object);
  const PhotonPassResult r = trace_photons(s, 0, s.photons_emitted);
  PhotonMap map(r.outside);
  // Along the central view ray, Li at the nearest and farthest third stay within a factor 2.
  double lo = 1e300, hi = 0;
  for (double z : {-1.2, -0.6, 0.0, 0.6, 1.2}) {
    const double li = map.in_scattered(glm::dvec3(0, 0, z), glm::dvec3(0, 0, -1), s.outside, s.k_nearest);
    lo = std::min(lo, li), hi = std::max(hi, li);
  }
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi / lo, 2.0);
}

}  // namespace
}  // namespace gcsim::media
