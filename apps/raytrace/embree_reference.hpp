#pragma once
// Optional yardstick for `gcsim bench raytrace`: the same primary rays through Intel Embree 3
// (rtcIntersect1, one thread), when gcsim was built with Debian's libembree-dev. Never used by
// tests or simulated time.
#include <cstdint>
#include <optional>

#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/scene.hpp"

namespace gcsim::raytrace {

struct EmbreeTiming {
  double seconds_per_frame;
  std::int64_t hits;  // pixels with a hit, to compare with ours
};

bool embree_available();
// Best of `repeat` frames; empty when gcsim was built without Embree.
std::optional<EmbreeTiming> time_embree_primary_rays(const Scene& scene, const Camera& camera, int repeat);

}  // namespace gcsim::raytrace
