#pragma once
// Where a shooting patch's hemicubes sit. The thesis puts one hemicube at the patch
// centre, which treats the whole patch as a point: exact far away, but a patch as large as its
// distance to a receiver is badly misjudged (two facing unit squares one unit apart: +20%; the
// elements along a closed box's edges: -18% to +12%). A shooter whose size exceeds `ratio` times
// the distance from its centre to the nearest receiving element is split into n x n parts of its
// bilinear parametrisation, n a power of two up to `max_per_side`; each part shoots from its own
// centre with a weight of its share of the area (the weights sum to 1, so energy is conserved).
#include <memory>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

struct ShooterSample {
  Vec3 point;
  double weight;  // share of the patch's area
};

// Distance from `p` to the nearest point of a convex polygon.
double distance_to_polygon(const Vec3& p, const Polygon& polygon);

// Samples per side for every patch: 1, or a power of two <= max_per_side where the patch's
// diameter exceeds ratio x its centre's distance to the nearest element in front of it.
std::vector<int> shooter_samples_per_side(const Scene& scene, double ratio, int max_per_side);

// shooter_samples_per_side computed once for all the replicas of a run (patches x elements
// distance tests each: at 4096 replicas of CORNELL they were 60 % of a short run's host time). One
// entry, recomputed when asked for another setting or scene (its address, counts and extent, in
// case a scene is freed and another made in its place). Not thread-safe: replicas are made on the
// simulation's thread.
class SamplesPerSideMemo {
 public:
  std::shared_ptr<const std::vector<int>> get(const Scene& scene, double ratio, int max_per_side);
  int computed() const { return computed_; }

 private:
  const Scene* scene_ = nullptr;
  std::size_t patches_ = 0, elements_ = 0;
  double extent_ = 0, ratio_ = 0;
  int max_per_side_ = 0;
  std::shared_ptr<const std::vector<int>> table_;
  int computed_ = 0;
};

// The n x n sample points of a patch (n = 1: its centre, weight 1).
std::vector<ShooterSample> shooter_samples(const ScenePatch& patch, int per_side);

}  // namespace gcsim::radiosity
