#pragma once
// The tiles a sample of the view renders, for `gcsim plan`'s view and media samples alike (the one
// place that picks them; ParallelRenderJob::sample_tiles hands them out).
#include <vector>

#include "apps/raytrace/render.hpp"

namespace gcsim::raytrace {

// One run of `run` consecutive tiles in `stride` (stride <= 1: every tile), in index order. On
// diagonals: the run's position shifts by one from a row of tiles to the next, so every row and
// every column of tiles is sampled alike and a medium or mirror covering a few of them is met about
// as often as in the whole image (every k-th row of tiles put example.toml's marching at 2.9 s
// against 1.4 s). Runs rather than single tiles so that a node's tiles share their row planes as in
// the whole image (single tiles rebuilt them for every tile: +9 % on CORNELL's view).
std::vector<int> sampled_tiles(const Tiling& tiling, int stride, int run);

}  // namespace gcsim::raytrace
