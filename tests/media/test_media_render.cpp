// The photon pass and the renderer of a scene: every photon accounted for, photons on the right side
// of the boundary, and results independent of how photons and rows are split (as over nodes).
#include <gtest/gtest.h>

#include <cstring>

#include "apps/media/lower_media_scene.hpp"
#include "apps/media/media_render.hpp"
#include "apps/media/photon_tracer.hpp"

namespace gcsim::media {
namespace {

MediaScene tiny_scene() {
  MediaScene s = load_media_scene("small");
  s.photons_emitted = 4000;
  s.k_nearest = 30;
  s.image.width = 16, s.image.height = 12;
  return s;
}

bool same_photons(const std::vector<Photon>& a, const std::vector<Photon>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Photon)) == 0;
}

TEST(PhotonPass, EveryPhotonEndsOnceAndLiesOnItsSideOfTheBoundary) {
  MediaScene s = tiny_scene();
  PhotonPassResult r = trace_photons(s, 0, s.photons_emitted);
  EXPECT_EQ(r.escaped + r.absorbed + r.capped, s.photons_emitted);
  EXPECT_EQ(r.outside.size() + r.inside.size(), r.flights - r.surface_events - r.escaped);
  EXPECT_GT(r.inside.size(), 0u);  // photons do get through the dielectric boundary
  EXPECT_GT(r.surface_events, 0u);
  const glm::dvec3 centre(0, -0.2, 0.3);
  const double radius = 0.8;
  for (const Photon& p : r.inside) EXPECT_LT(glm::length(glm::dvec3(p.position) - centre), radius + 1e-5);
  for (const Photon& p : r.outside) EXPECT_GT(glm::length(glm::dvec3(p.position) - centre), radius - 1e-5);
}

TEST(PhotonPass, SplittingThePhotonRangeGivesTheSamePhotons) {
  MediaScene s = tiny_scene();
  PhotonPassResult whole = trace_photons(s, 0, s.photons_emitted);
  PhotonPassResult a = trace_photons(s, 0, 1234), b = trace_photons(s, 1234, s.photons_emitted);
  a.outside.insert(a.outside.end(), b.outside.begin(), b.outside.end());
  a.inside.insert(a.inside.end(), b.inside.begin(), b.inside.end());
  EXPECT_TRUE(same_photons(whole.outside, a.outside));
  EXPECT_TRUE(same_photons(whole.inside, a.inside));
}

TEST(PhotonPass, HostThreadsGiveTheSamePhotonsAndCounts) {
  MediaScene s = tiny_scene();
  const PhotonPassResult one = trace_photons(s, 17, s.photons_emitted);
  for (int jobs : {2, 3, 5}) {
    const PhotonPassResult many = trace_photons(s, 17, s.photons_emitted, jobs);
    EXPECT_TRUE(same_photons(one.outside, many.outside)) << jobs << " threads";
    EXPECT_TRUE(same_photons(one.inside, many.inside)) << jobs << " threads";
    EXPECT_EQ(one.flights, many.flights);
    EXPECT_EQ(one.surface_events, many.surface_events);
    EXPECT_EQ(one.escaped + one.absorbed + one.capped, many.escaped + many.absorbed + many.capped);
    EXPECT_EQ(one.entered, many.entered);
  }
}

TEST(MediaRender, ImageIsFiniteLitAndIndependentOfTheRowSplit) {
  MediaScene s = tiny_scene();
  SceneCaches caches = build_caches(s, trace_photons(s, 0, s.photons_emitted));
  ASSERT_TRUE(caches.outside.map && caches.inside.map);
  for (Estimator e : kAllEstimators) {
    MarchSettings settings{e, 4.0};
    apps::Image whole(s.image.width, s.image.height), split(s.image.width, s.image.height);
    RenderCounters c1, c2;
    render_rows(s, caches, settings, 9, 0, s.image.height, whole, c1);
    render_rows(s, caches, settings, 9, 5, s.image.height, split, c2);
    render_rows(s, caches, settings, 9, 0, 5, split, c2);
    double total = 0.0;
    for (std::size_t i = 0; i < whole.pixels().size(); ++i) {
      ASSERT_TRUE(std::isfinite(whole.pixels()[i].x)) << estimator_name(e);
      EXPECT_EQ(whole.pixels()[i].x, split.pixels()[i].x) << estimator_name(e);
      total += whole.pixels()[i].x;
    }
    EXPECT_GT(total, 0.0) << estimator_name(e);
    EXPECT_EQ(c1.march.samples, c2.march.samples);
  }
}

}  // namespace
}  // namespace gcsim::media
