#pragma once
// Nearest hits of the primary rays of one subregion (tile) with any of the paper's algorithms.
// A tracer keeps per-row state (the two planes shared along a row of subregions, 2.2.1) and the
// subtree of the last subregion, so tiles should be traced row by row, left to right.
#include <cstdint>
#include <memory>
#include <vector>

#include "apps/raytrace/algorithm.hpp"
#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/common/geometry/hit.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/occlusion_check.hpp"
#include "apps/raytrace/ray_classification.hpp"
#include "apps/raytrace/region_schedule.hpp"
#include "apps/raytrace/subtree.hpp"

namespace gcsim::raytrace {

class PrimaryTracer {
 public:
  // shared_pairs: the tree's child pairs for the row filter, shared by every tracer of one render
  // (null: this tracer prepares its own when its algorithm filters rows).
  PrimaryTracer(const Scene& scene, const Bvh& bvh, const Camera& camera, Algorithm algorithm,
                const PreparedChildPairs* shared_pairs = nullptr);

  // Hits of the pixels of [x0, x1) x [y0, y1), row-major in `hits`. The row's two planes are
  // counted in `counters` when the tile starts a new row; with `row_counters`, they are counted
  // there instead, for every tile (what its row costs), and the caller decides whether the row
  // is new to it (tile_prefetch.hpp: a tile rendered ahead does not know its node's last row).
  void trace_tile(int x0, int y0, int x1, int y1, std::vector<Hit>& hits, TraceCounters& counters,
                  TraceCounters* row_counters = nullptr);

  Algorithm algorithm() const { return algorithm_; }
  // false: every ray walks alone (traverse_ordered), for measuring the single-ray core; the same
  // hits and counts either way.
  void use_packets(bool packets) { packets_ = packets; }

 private:
  struct Region;
  struct Pixel { int x, y; };
  using Rect = RegionRect;
  void trace_pixel(int x, int y, Hit& hit, TestTally& tally, TraceCounters& counters);
  // The ordered traversal's tree (A2, A3, A4), or null: the algorithms traced in packets.
  const PackedTree* packet_tree() const;
  // trace_pixel for each pixel, the hit stored at (y - y0) * width + (x - x0) of `hits`; in
  // packets of eight in the order given where the algorithm allows (same hits and counts).
  void trace_pixels(const std::vector<Pixel>& pixels, int x0, int y0, int width, std::vector<Hit>& hits, TestTally& tally,
                    TraceCounters& counters);
  void trace_uniform_regions(Region& r, int height, TestTally& tally, TraceCounters& counters);
  const RegionSchedule& schedule_for(int width, int height);
  bool fill_if_uniform(Region& r, const Rect& q, TestTally& tally, TraceCounters& counters);
  float farthest_possible_hit(int prim, const Region& r, int rx0, int ry0, int rx1, int ry1) const;

  const Scene& scene_;
  const Bvh& bvh_;
  const Camera& camera_;
  Algorithm algorithm_;
  bool packets_ = true;
  int row_y0_ = -1, row_y1_ = -1;
  TraceCounters row_cost_;  // what filtering the current row by its two planes counted
  std::unique_ptr<PreparedChildPairs> own_pairs_;  // when none was shared
  const PreparedChildPairs* pairs_ = nullptr;      // what every row's filter copies of the BVH's nodes
  PlaneFilteredTree row_;
  Subtree subtree_;
  std::unique_ptr<RayClassifier> classifier_;
  std::unique_ptr<OcclusionCheck> occlusion_;  // A4's
  std::vector<Pixel> pixels_;      // scratch: the pixels a tile or a level of regions traces
  std::vector<RegionSchedule> schedules_;  // A4's halving, per tile shape met so far
  std::vector<char> traced_;               // scratch: A4's pixels of the tile already hit or filled
  std::vector<char> reached_, halved_;     // scratch: A4's regions of a level reached, and halved
};

}  // namespace gcsim::raytrace
