#include "apps/media/media_scene.hpp"

namespace gcsim::media {

MediaScene small_scene() {
  MediaScene s;
  s.name = "small";
  s.fog_box = {{-2, -1.5, -2}, {2, 1.5, 2}, {1, 1, 1}};
  s.outside = {1.0, 0.3, 0.0, Phase::isotropic()};          // experiment 1's outside medium
  s.inside = {8.0, 6.4, 0.0, Phase::schlick(0.5)};         // a thinner, bright version of its inside
  s.object = std::make_shared<SphereBoundary>(glm::dvec3(0.0, -0.2, 0.3), 0.8);
  s.light = {{-1.2, 1.0, -0.6}, 3.0};
  s.camera = {{0, 0.2, -3.9}, {0, -0.1, 0}, {0, 1, 0}, 50.0, 64, 48};
  return s;
}

}  // namespace gcsim::media
