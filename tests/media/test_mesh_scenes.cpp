// The bunny scenes (exp1-bunny, exp2-bunny): photons pass through the mesh and those stored inside
// are inside it, the image does not depend on the node count, and the mesh's tree nodes and
// triangle tests are charged (while the sphere scenes charge none).
#include <gtest/gtest.h>

#include "apps/media/frame.hpp"
#include "apps/media/lower_media_scene.hpp"
#include "apps/media/parallel_media.hpp"
#include "machine/machine_config.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::media {
namespace {

MediaScene few_photon_bunny() {
  MediaScene s = load_media_scene("exp1-bunny");
  s.photons_emitted = 4000, s.k_nearest = 30, s.image.width = 24, s.image.height = 18;
  return s;
}

TEST(BunnyScenes, NamedLikeTheirSphereScenesWithTheMeshAsObject) {
  for (const char* name : {"exp1", "exp2"}) {
    const MediaScene sphere = load_media_scene(name), bunny = load_media_scene(std::string(name) + "-bunny");
    EXPECT_EQ(bunny.name, std::string(name) + "-bunny");
    EXPECT_NE(dynamic_cast<const MeshBoundary*>(bunny.object.get()), nullptr);
    EXPECT_NE(dynamic_cast<const SphereBoundary*>(sphere.object.get()), nullptr);
    EXPECT_EQ(bunny.photons_emitted, sphere.photons_emitted);
    EXPECT_EQ(bunny.inside.sigma_t, sphere.inside.sigma_t);
    EXPECT_EQ(bunny.camera.eye, sphere.camera.eye);
  }
}

TEST(BunnyScenes, PhotonsStoredInsideTheBunnyAreInsideIt) {
  const MediaScene s = few_photon_bunny();
  const PhotonPassResult r = trace_photons(s, 0, s.photons_emitted);
  EXPECT_EQ(r.escaped + r.absorbed + r.capped, s.photons_emitted);
  EXPECT_GT(r.entered, 0u);
  ASSERT_GT(r.inside.size(), 50u);
  EXPECT_GT(r.boundary.node_tests, 0u);
  EXPECT_GT(r.boundary.triangle_tests, 0u);
  for (const Photon& p : r.inside) ASSERT_TRUE(s.object->inside(glm::dvec3(p.position)));
  std::size_t outside_but_in = 0;
  for (const Photon& p : r.outside) outside_but_in += s.object->inside(glm::dvec3(p.position));
  EXPECT_EQ(outside_but_in, 0u);
}

TEST(BunnyScenes, ImageIsBitIdenticalOnOneAndTwoNodesAndTheMeshIsCharged) {
  const MediaScene s = few_photon_bunny();
  const MarchSettings settings{Estimator::radiance, 4.0};
  const ParallelMediaResult one = render_media_parallel(s, settings, 3, test_support::published_machine(1));
  const ParallelMediaResult two = render_media_parallel(s, settings, 3, test_support::published_machine(2));
  ASSERT_EQ(one.image.pixels().size(), two.image.pixels().size());
  double lit = 0.0;
  for (std::size_t i = 0; i < one.image.pixels().size(); ++i) {
    ASSERT_EQ(one.image.pixels()[i].x, two.image.pixels()[i].x) << "pixel " << i;
    lit += one.image.pixels()[i].x;
  }
  EXPECT_GT(lit, 0.0);
  EXPECT_GT(one.inside_photons, 0u);
  EXPECT_GT(one.counters.boundary.node_tests, 0u);
  // The same run with the mesh's operations free computes less: they are charged.
  parix::SimulationOptions free_mesh = test_support::published_machine(1);
  free_mesh.config.cycles_per_op["media_bvh_node"] = 0.0;
  free_mesh.config.cycles_per_op["media_triangle_test"] = 0.0;
  const ParallelMediaResult cheap = render_media_parallel(s, settings, 3, free_mesh);
  EXPECT_LT(cheap.run.mean_compute_seconds(), one.run.mean_compute_seconds());
  const machine::MachineConfig m = machine::published_machine_config();
  RenderCounters no_mesh = one.counters;
  no_mesh.boundary = {};
  EXPECT_GT(render_seconds(one.counters, s.k_nearest, m), render_seconds(no_mesh, s.k_nearest, m));
}

TEST(BunnyScenes, TheSphereScenesCountNoMeshWork) {
  MediaScene s = load_media_scene("exp1");
  s.photons_emitted = 2000, s.image.width = 8, s.image.height = 6;
  const PhotonPassResult r = trace_photons(s, 0, s.photons_emitted);
  EXPECT_FALSE(r.boundary.any());
  const SceneCaches caches = build_caches(s, r);
  apps::Image image(s.image.width, s.image.height);
  RenderCounters c;
  render_rows(s, caches, MarchSettings{Estimator::radiance, 2.0}, 1, 0, s.image.height, image, c);
  EXPECT_GT(c.surface_events, 0u);
  EXPECT_FALSE(c.boundary.any());
}

}  // namespace
}  // namespace gcsim::media
