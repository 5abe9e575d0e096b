// The media as the radiosity pass sees them: the transmittance of a segment through a box (closed
// form), nothing outside the media, media that change nothing left out, and a render's setup that
// hands them to radiosity only when it has a radiosity pass.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "apps/common/scene/scene_file.hpp"
#include "apps/render/plan.hpp"
#include "apps/render/radiosity_media.hpp"
#include "apps/render/render_setup.hpp"

namespace gcsim::render {
namespace {

MediumRegion unit_box(glm::dvec3 sigma_s, glm::dvec3 sigma_a) {
  MediumRegion r;
  r.material = "fog";
  r.shape = scene::Box{glm::dvec3(0.0), glm::dvec3(1.0)};
  r.medium.sigma_s = sigma_s;
  r.medium.sigma_a = sigma_a;
  return r;
}

TEST(RadiosityMedia, ASegmentThroughABoxKeepsExpOfMinusSigmaTimesTheLengthInside) {
  const RadiosityMedia media({unit_box({0.5, 1.0, 1.5}, {0.5, 1.0, 1.5})});  // sigma_t = 1, 2, 3
  const radiosity::Rgb t = media.between({-1.0, 0.5, 0.5}, {2.0, 0.5, 0.5});  // 1 inside of 3
  EXPECT_NEAR(t.r, std::exp(-1.0), 1e-15);
  EXPECT_NEAR(t.g, std::exp(-2.0), 1e-15);
  EXPECT_NEAR(t.b, std::exp(-3.0), 1e-15);
  const radiosity::Rgb half = media.between({0.5, 0.5, 0.25}, {0.5, 0.5, 0.75});  // wholly inside
  EXPECT_NEAR(half.b, std::exp(-1.5), 1e-15);
  EXPECT_EQ(media.between({-1.0, 2.0, 0.5}, {2.0, 2.0, 0.5}), radiosity::Rgb(1.0));  // passes it by
  EXPECT_EQ(media.between({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}), radiosity::Rgb(1.0));  // no length
}

TEST(RadiosityMedia, MediaThatChangeNothingAreLeftOut) {
  EXPECT_TRUE(RadiosityMedia({unit_box(glm::dvec3(0.0), glm::dvec3(0.0))}).empty());
  EXPECT_FALSE(RadiosityMedia({unit_box(glm::dvec3(0.0), glm::dvec3(0.1))}).empty());  // absorbing only
}

TEST(RadiosityMedia, ARenderHandsItsMediaToTheRadiosityPass) {
  const auto fog = scene::load_scene_file(std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "cornell-fog.toml");
  const Plan plan = make_plan(fog);
  ASSERT_TRUE(plan.pass(PassId::radiosity).on);
  EXPECT_NE(prepare_render(fog, plan, "cornell-fog.toml").radiosity_media_or_null(), nullptr);
  // An error budget that drops the media drops them from radiosity too.
  EXPECT_EQ(prepare_render(fog, plan, "cornell-fog.toml", {}, kDefaultPhotons, false).radiosity_media_or_null(), nullptr);
  const auto clear = scene::load_scene_file(std::filesystem::path(GCSIM_SOURCE_DIR) / "scenes" / "cornell.toml");
  EXPECT_EQ(prepare_render(clear, make_plan(clear), "cornell.toml").radiosity_media_or_null(), nullptr);
}

}  // namespace
}  // namespace gcsim::render
