#pragma once
// Optional yardstick for `gcsim bench raytrace`: the same primary rays through Intel Embree 3, one
// ray at a time (rtcIntersect1) and in coherent packets of 8 (rtcIntersect8: 4 x 2 pixels), one
// thread, when gcsim was built with Debian's libembree-dev. Never used by tests or simulated time.
#include <cstdint>
#include <optional>

#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

struct EmbreeTiming {
  double seconds_per_frame;          // rtcIntersect1
  std::int64_t hits;                 // pixels with a hit, to compare with ours
  double packet8_seconds_per_frame;  // rtcIntersect8 on 4 x 2 pixel blocks
  std::int64_t packet8_hits;
};

bool embree_available();
// Best of `repeat` frames; empty when gcsim was built without Embree.
std::optional<EmbreeTiming> time_embree_primary_rays(const Scene& scene, const Camera& camera, int repeat);

}  // namespace gcsim::raytrace
