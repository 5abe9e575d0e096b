#pragma once
// Baseline B1: Arvo and Kirk's ray classification, restricted (as in the paper) to primary rays.
// All primary rays leave the eye, so the five-dimensional ray space reduces to the two
// dimensions of direction, i.e. of image position. A quadtree of beams over the image is built
// lazily as rays arrive: a beam's candidate list is the part of its parent's list whose boxes meet
// the beam (four planes through the eye), and a beam with few candidates, or only a few pixels
// wide, is a leaf whose candidates are sorted by distance from the eye. A ray tests candidates in
// that order and stops at the first whose box lies beyond its nearest hit.
#include <cstdint>
#include <memory>
#include <vector>

#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/common/geometry/hit.hpp"
#include "apps/common/geometry/primitive_intersection.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {

class RayClassifier {
 public:
  static constexpr int kMaxCandidatesPerLeaf = 8;
  static constexpr int kMinBeamPixels = 2;

  RayClassifier(const Scene& scene, const Bvh& bvh, const Camera& camera);
  void trace(int x, int y, const Ray& ray, Hit& hit, TestTally& tally, TraceCounters& counters);

 private:
  struct Beam {
    int x0, y0, size;
    std::vector<std::int32_t> candidates;  // primitives
    std::vector<float> distance;           // leaves: box distance from the eye, ascending
    int child[4] = {-1, -1, -1, -1};
    bool leaf = false;
  };
  int make_beam(int parent, int x0, int y0, int size, TraceCounters& counters);
  void finish(Beam& b, TraceCounters& counters);

  const Scene& scene_;
  const Bvh& bvh_;
  const Camera& camera_;
  std::vector<Beam> beams_;
};

}  // namespace gcsim::raytrace
