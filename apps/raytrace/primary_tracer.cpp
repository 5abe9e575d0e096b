#include "apps/raytrace/primary_tracer.hpp"

#include <algorithm>
#include <cstdint>

#include "apps/common/geometry/packet_traversal.hpp"
#include "apps/common/geometry/traversal.hpp"
#include "apps/raytrace/geometry_names.hpp"

namespace gcsim::raytrace {

namespace {

// f(x, y) for the pixels of [x0, x1) x [y0, y1) in 4 x 2 blocks, row-major within and between
// them: the order that makes neighbours of a packet.
template <class F>
void in_blocks(int x0, int y0, int x1, int y1, F&& f) {
  for (int by = y0; by < y1; by += 2)
    for (int bx = x0; bx < x1; bx += 4)
      for (int y = by; y < std::min(by + 2, y1); ++y)
        for (int x = bx; x < std::min(bx + 4, x1); ++x) f(x, y);
}


}  // namespace

// Hits of one tile while the uniformity test fills it in (A4).
struct PrimaryTracer::Region {
  int x0, y0, width;
  std::vector<Hit>* hits;
  std::vector<char>& traced;
  Hit& at(int x, int y) { return (*hits)[std::size_t(y - y0) * width + (x - x0)]; }
  char& done(int x, int y) { return traced[std::size_t(y - y0) * width + (x - x0)]; }
};

PrimaryTracer::PrimaryTracer(const Scene& scene, const Bvh& bvh, const Camera& camera, Algorithm algorithm,
                             const PreparedChildPairs* shared_pairs)
    : scene_(scene), bvh_(bvh), camera_(camera), algorithm_(algorithm), pairs_(shared_pairs) {
  if (algorithm == Algorithm::B1) classifier_ = std::make_unique<RayClassifier>(scene, bvh, camera);
  if (algorithm == Algorithm::A4) occlusion_ = std::make_unique<OcclusionCheck>(scene, bvh, camera);
  if (uses_subtree(algorithm) && !pairs_) {
    own_pairs_ = std::make_unique<PreparedChildPairs>(bvh);
    pairs_ = own_pairs_.get();
  }
}

void PrimaryTracer::trace_pixel(int x, int y, Hit& hit, TestTally& tally, TraceCounters& counters) {
  const Ray ray = camera_.pixel_ray(x, y);
  hit = Hit{};
  switch (algorithm_) {
    case Algorithm::A1: traverse_unordered(scene_, bvh_.packed, ray, hit, tally); break;
    case Algorithm::A2: traverse_ordered(scene_, bvh_.packed, ray, hit, tally); break;
    case Algorithm::A2p:
      traverse_unordered(scene_, subtree_.packed, ray, hit, tally);
      break;
    case Algorithm::A3:
    case Algorithm::A4:
      traverse_ordered(scene_, subtree_.packed, ray, hit, tally);
      break;
    case Algorithm::B1: classifier_->trace(x, y, ray, hit, tally, counters); break;
    case Algorithm::brute: intersect_brute_force(scene_, ray, hit, tally); break;
  }
}

namespace {
bool packet_capable(Algorithm a) { return a == Algorithm::A2 || a == Algorithm::A3 || a == Algorithm::A4; }
}  // namespace

const PackedTree* PrimaryTracer::packet_tree() const {
  if (!packets_) return nullptr;
  switch (algorithm_) {
    case Algorithm::A2: return &bvh_.packed;
    case Algorithm::A3:
    case Algorithm::A4: return &subtree_.packed;
    default: return nullptr;
  }
}

void PrimaryTracer::trace_pixels(const std::vector<Pixel>& pixels, int x0, int y0, int width, std::vector<Hit>& hits,
                                 TestTally& tally, TraceCounters& counters) {
  auto hit_of = [&](const Pixel& p) -> Hit& { return hits[std::size_t(p.y - y0) * width + (p.x - x0)]; };
  const PackedTree* tree = packet_tree();
  if (!tree && !packets_ && packet_capable(algorithm_)) {
    // One ray at a time, the rays still made four at once (the same rays as pixel_ray).
    const PackedTree& single = algorithm_ == Algorithm::A2 ? bvh_.packed : subtree_.packed;
    Ray rays[kPacketLanes];
    int xs[kPacketLanes], ys[kPacketLanes];
    for (std::size_t first = 0; first < pixels.size(); first += kPacketLanes) {
      const int n = int(std::min<std::size_t>(kPacketLanes, pixels.size() - first));
      for (int i = 0; i < n; ++i) xs[i] = pixels[first + i].x, ys[i] = pixels[first + i].y;
      camera_.pixel_rays(xs, ys, n, rays);
      Hit lane_hits[kPacketLanes];
      traverse_ordered_rays(scene_, single, rays, n, lane_hits, tally);
      for (int i = 0; i < n; ++i) hit_of(pixels[first + i]) = lane_hits[i];
    }
    return;
  }
  if (!tree) {
    for (const Pixel& p : pixels) trace_pixel(p.x, p.y, hit_of(p), tally, counters);
    return;
  }
  Ray rays[kPacketLanes];
  TestTally lane_tallies[kPacketLanes];  // only their sum is needed: summed once at the end
  for (std::size_t first = 0; first < pixels.size(); first += kPacketLanes) {
    const int n = int(std::min<std::size_t>(kPacketLanes, pixels.size() - first));
    Hit lane_hits[kPacketLanes];
    int xs[kPacketLanes], ys[kPacketLanes];
    for (int i = 0; i < n; ++i) xs[i] = pixels[first + i].x, ys[i] = pixels[first + i].y;
    camera_.pixel_rays(xs, ys, n, rays);
    traverse_ordered_packet(scene_, *tree, rays, (1u << n) - 1, lane_hits, lane_tallies);
    for (int i = 0; i < n; ++i) hit_of(pixels[first + i]) = lane_hits[i];
  }
  for (const TestTally& t : lane_tallies) {
    tally.boxes += t.boxes;
    tally.spheres += t.spheres;
    tally.triangles += t.triangles;
    tally.sorts += t.sorts;
  }
}

void PrimaryTracer::trace_tile(int x0, int y0, int x1, int y1, std::vector<Hit>& hits, TraceCounters& counters,
                               TraceCounters* row_counters) {
  const int w = x1 - x0, h = y1 - y0;
  hits.assign(std::size_t(w) * h, Hit{});
  TestTally tally;
  if (uses_subtree(algorithm_)) {
    if (y0 != row_y0_ || y1 != row_y1_) {  // a new row of subregions: its two shared planes
      row_cost_ = TraceCounters{};
      filter_by_two_planes(bvh_, camera_.row_plane(y0), flipped(camera_.row_plane(y1)), row_, row_cost_, pairs_);
      row_y0_ = y0;
      row_y1_ = y1;
      if (!row_counters) counters += row_cost_;
    }
    if (row_counters) *row_counters = row_cost_;
    subtree_from_filtered(row_, camera_.column_plane(x0), flipped(camera_.column_plane(x1)), subtree_, counters);
  }
  if (algorithm_ == Algorithm::A4 && !subtree_.empty) {
    traced_.assign(std::size_t(w) * h, 0);
    Region r{x0, y0, w, &hits, traced_};
    trace_uniform_regions(r, h, tally, counters);
  } else if (uses_subtree(algorithm_) && subtree_.empty) {
    // Nothing meets the subregion: every pixel keeps its empty hit, and no ray is even made.
  } else {
    pixels_.clear();
    if (packet_tree()) {
      in_blocks(x0, y0, x1, y1, [&](int x, int y) { pixels_.push_back({x, y}); });
    } else {  // B1's beams grow with the rays traced: keep its order
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) pixels_.push_back({x, y});
    }
    trace_pixels(pixels_, x0, y0, w, hits, tally, counters);
  }
  counters.primary_rays += std::int64_t(w) * h;
  counters.primary_box_tests += tally.boxes;
  counters.primary_prim_tests += tally.prims();
  counters.sphere_tests += tally.spheres;
  counters.triangle_tests += tally.triangles;
  counters.child_sorts += tally.sorts;
}

// Section 2.2.3 on the tile. The corner rays of a region are traced; if they all hit the same
// primitive P and nothing in the subtree can lie in front of P inside the region, every pixel sees
// P. Otherwise the region is halved along its longer side, down to regions whose pixels are all
// corners. The halves are taken a level at a time, not depth first: which pixels get traced, and
// what each counts, does not depend on the order (sibling regions share no pixel), and a level's
// new corners are traced in packets. A corner that a filled region holds is already done.
void PrimaryTracer::trace_uniform_regions(Region& r, int height, TestTally& tally, TraceCounters& counters) {
  const RegionSchedule& schedule = schedule_for(r.width, height);
  reached_.assign(1, 1);
  for (std::size_t l = 0; l < schedule.levels().size(); ++l) {
    const RegionLevel& level = schedule.levels()[l];
    if (l > 0) {  // a region is reached when the region it halves was reached and not filled
      reached_.resize(level.rects.size());
      bool any = false;
      for (std::size_t i = 0; i < level.rects.size(); ++i) any |= (reached_[i] = halved_[level.parent[i]]) != 0;
      if (!any) return;
    }
    pixels_.clear();
    for (const PixelOffset& c : level.new_corners) {
      char& done = r.done(r.x0 + c.x, r.y0 + c.y);
      if (!done) pixels_.push_back({r.x0 + c.x, r.y0 + c.y});
      done = 1;
    }
    trace_pixels(pixels_, r.x0, r.y0, r.width, *r.hits, tally, counters);
    halved_.assign(level.rects.size(), 0);
    for (std::size_t i = 0; i < level.rects.size(); ++i) {
      if (!reached_[i]) continue;
      const Rect& q = level.rects[i];
      halved_[i] = !fill_if_uniform(r, {r.x0 + q.x0, r.y0 + q.y0, r.x0 + q.x1, r.y0 + q.y1}, tally, counters);
    }
  }
}

const RegionSchedule& PrimaryTracer::schedule_for(int width, int height) {
  for (const RegionSchedule& s : schedules_)
    if (s.width() == width && s.height() == height) return s;
  return schedules_.emplace_back(width, height);
}

// The uniformity test of q, whose corners are traced; fills q in when it is uniform.
bool PrimaryTracer::fill_if_uniform(Region& r, const Rect& q, TestTally& tally, TraceCounters& counters) {
  const int rx0 = q.x0, ry0 = q.y0, rx1 = q.x1, ry1 = q.y1;
  const int w = rx1 - rx0 + 1, h = ry1 - ry0 + 1;
  if (w <= 2 && h <= 2) return false;  // every pixel is a corner
  const int cx[4] = {rx0, rx1, rx0, rx1}, cy[4] = {ry0, ry0, ry1, ry1};
  ++counters.uniformity_tests;
  const int p = r.at(rx0, ry0).prim;
  bool same = p >= 0;
  for (int i = 1; i < 4 && same; ++i) same = r.at(cx[i], cy[i]).prim == p;
  if (!same || !occlusion_->nothing_in_front(subtree_, p, farthest_possible_hit(p, r, rx0, ry0, rx1, ry1), rx0, ry0,
                                             rx1, ry1, counters.uniformity_box_checks))
    return false;
  ++counters.uniform_regions;
  Ray rays[kPacketLanes];
  int xs[kPacketLanes], ys[kPacketLanes];
  for (int y = ry0; y <= ry1; ++y)
    for (int x = rx0; x <= rx1;) {
      // The row's pixels not yet traced, their rays made a few at once (the same rays as pixel_ray).
      int n = 0;
      for (; x <= rx1 && n < kPacketLanes; ++x)
        if (!r.done(x, y)) xs[n] = x, ys[n] = y, ++n;
      camera_.pixel_rays(xs, ys, n, rays);
      for (int i = 0; i < n; ++i) {
        // Only P needs testing; its hit gives the distance and barycentrics for shading.
        Hit& hit = r.at(xs[i], y);
        hit = Hit{};
        test_primitive_quickly(scene_, p, rays[i], hit, tally);
        // Within rounding distance of P's edge a neighbour may tie or win in float: trace fully.
        const bool near_edge = !scene_.is_sphere(p) && std::min({hit.b1, hit.b2, 1.0f - hit.b1 - hit.b2}) < 1e-4f;
        if (!hit.valid() || near_edge) trace_pixel(xs[i], y, hit, tally, counters);
        else ++counters.uniform_pixels;
        r.done(xs[i], y) = 1;
      }
    }
  return true;
}

// An upper bound of the distance at which any ray of the region meets P. For a triangle the hits
// of the region's rays are convex combinations of the corner hits, and distance from the eye is
// convex, so the farthest corner bounds them; a sphere's bound depends on the sphere alone.
float PrimaryTracer::farthest_possible_hit(int prim, const Region& r, int rx0, int ry0, int rx1, int ry1) const {
  if (scene_.is_sphere(prim)) return occlusion_->sphere_distance_bound(prim);
  auto& rr = const_cast<Region&>(r);
  const float d = std::max({rr.at(rx0, ry0).t, rr.at(rx1, ry0).t, rr.at(rx0, ry1).t, rr.at(rx1, ry1).t});
  return d * (1.0f + 1e-5f);
}

}  // namespace gcsim::raytrace
