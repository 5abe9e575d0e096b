#include "apps/raytrace/ray_classification.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "apps/raytrace/plane_classification.hpp"

namespace gcsim::raytrace {

RayClassifier::RayClassifier(const Scene& scene, const Bvh& bvh, const Camera& camera)
    : scene_(scene), bvh_(bvh), camera_(camera) {
  int size = 1;
  while (size < std::max(camera.width(), camera.height())) size *= 2;
  TraceCounters unused;
  make_beam(-1, 0, 0, size, unused);
}

int RayClassifier::make_beam(int parent, int x0, int y0, int size, TraceCounters& counters) {
  Beam b;
  b.x0 = x0;
  b.y0 = y0;
  b.size = size;
  const int x1 = std::min(x0 + size, camera_.width()), y1 = std::min(y0 + size, camera_.height());
  const Plane planes[4] = {camera_.column_plane(x0), flipped(camera_.column_plane(x1)), camera_.row_plane(y0),
                           flipped(camera_.row_plane(y1))};
  auto keep = [&](int prim) {
    for (const Plane& p : planes) {
      ++counters.plane_tests;
      if (classify(bvh_.prim_bounds[prim], p) == Side::outside) return false;
    }
    return true;
  };
  if (parent < 0) {
    // The root holds every primitive: classifying against the image's pyramid is done lazily
    // by its children.
    b.candidates.resize(scene_.prim_count());
    std::iota(b.candidates.begin(), b.candidates.end(), 0);
  } else {
    for (std::int32_t p : beams_[parent].candidates)
      if (keep(p)) b.candidates.push_back(p);
  }
  ++counters.beams;
  if (static_cast<int>(b.candidates.size()) <= kMaxCandidatesPerLeaf || size <= kMinBeamPixels) finish(b, counters);
  beams_.push_back(std::move(b));
  return static_cast<int>(beams_.size() - 1);
}

void RayClassifier::finish(Beam& b, TraceCounters& counters) {
  const glm::vec3 eye = camera_.eye();
  std::vector<std::pair<float, std::int32_t>> order;
  for (std::int32_t p : b.candidates) order.push_back({bvh_.prim_bounds[p].distance_to(eye), p});
  std::sort(order.begin(), order.end());
  const auto n = static_cast<std::int64_t>(order.size());
  counters.candidate_sort_entries += n > 1 ? n * static_cast<std::int64_t>(std::ceil(std::log2(double(n)))) : n;
  b.candidates.clear();
  for (auto& [d, p] : order) {
    b.distance.push_back(d);
    b.candidates.push_back(p);
  }
  b.leaf = true;
}

void RayClassifier::trace(int x, int y, const Ray& ray, Hit& hit, TestTally& tally, TraceCounters& counters) {
  int at = 0;
  while (!beams_[at].leaf) {
    const int half = beams_[at].size / 2;
    const int qx = x >= beams_[at].x0 + half, qy = y >= beams_[at].y0 + half;
    const int q = qy * 2 + qx;
    if (beams_[at].child[q] < 0) {
      const Beam& b = beams_[at];
      const int c = make_beam(at, b.x0 + qx * half, b.y0 + qy * half, half, counters);
      beams_[at].child[q] = c;
    }
    at = beams_[at].child[q];
  }
  const Beam& leaf = beams_[at];
  for (std::size_t i = 0; i < leaf.candidates.size(); ++i) {
    if (leaf.distance[i] > hit.t) break;  // every later candidate starts farther than the hit
    test_primitive(scene_, leaf.candidates[i], ray, hit, tally);
  }
}

}  // namespace gcsim::raytrace
