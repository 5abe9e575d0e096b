#pragma once
// Where a shooting patch's hemicubes sit (issue 13). The thesis puts one hemicube at the patch
// centre, which treats the whole patch as a point: exact far away, but a patch as large as its
// distance to a receiver is badly misjudged (two facing unit squares one unit apart: +20%; the
// elements along a closed box's edges: -18% to +12%). A near shooter is split into n x n parts of
// its bilinear parametrisation, n a power of two up to `max_per_side`; each part shoots from its
// own centre with a weight of its share of the area (the weights sum to 1, so energy is conserved).
//
// How many: the n x n points are a midpoint rule for the area-to-element form factors, whose error
// falls as 1/n^2, so the change from n to 2n points estimates the error at n (about 3/4 of it).
// Each shooter takes the smallest n whose change, summed over the elements near it, is at most
// `tolerance` of its energy, using the analytic unoccluded point-to-polygon form factor. The
// error, not the geometry alone, decides: a patch meeting a wall at a right angle is nearer to it
// than two facing squares are to each other, yet its form factors vary far less over its area.
//
// What it may cost: every sample projects every element in front of the shooter again, while the
// pixel work stays that of one hemicube (each sample's hemicube has resolution / n). Beyond 2 x 2
// points (always allowed), n is capped so that the projections of all n^2 samples cost at most a
// quarter of what the pixels of one hemicube cost (HemicubeRenderer passes 3 r^2 / 4): a scene of
// few elements near each other (the facing squares) is sampled finely, a scene of many (CORNELL)
// keeps at most 2 x 2 points where it needs them.
#include <cstdint>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

struct ShooterSample {
  Vec3 point;
  double weight;  // share of the patch's area
};

// Distance from `p` to the nearest point of a convex polygon.
double distance_to_polygon(const Vec3& p, const Polygon& polygon);

// Samples per side for every patch: the smallest power of two n <= max_per_side for which going to
// 2n changes sum_j F(patch -> j) by at most `tolerance` over the front-facing elements j within
// kNearFieldReach diameters of the patch (farther ones: one point errs by well under 1%), and for
// which, if n > 2, n^2 x (elements in front) x kProjectionPixels stays within `pixel_budget`.
inline constexpr double kNearFieldReach = 4.0;
// One element projected onto the five faces costs about 50 pixel tests (the GC's costs in
// configs/gc-powerplus.toml: polygon_project 1500 cycles a face, hemicube_pixel 150).
inline constexpr std::int64_t kProjectionPixels = 50;
std::vector<int> shooter_samples_per_side(const Scene& scene, double tolerance, int max_per_side,
                                          std::int64_t pixel_budget);

// Unoccluded form factor from a point with normal n to the part of a convex polygon in front of it.
double point_form_factor_in_front(const Vec3& x, const Vec3& n, const Polygon& polygon);

// The n x n sample points of a patch (n = 1: its centre, weight 1).
std::vector<ShooterSample> shooter_samples(const ScenePatch& patch, int per_side);

}  // namespace gcsim::radiosity
