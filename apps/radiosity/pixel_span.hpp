#pragma once
// Which pixel centres of one hemicube row a projected element covers. The element's vertices sit
// on a grid of 1/256 pixel and pixel centres on it too, so every edge function is an integer, and
// along a row it is linear in the pixel: each edge keeps a half-line of pixels, and the pixels of
// the row the element takes are one interval, found with one integer division per edge instead of
// every edge tested at every pixel. covers_pixel is the per-pixel test both answer as.
#include <array>
#include <cstdint>

#include "apps/radiosity/hemicube.hpp"

namespace gcsim::radiosity {

inline constexpr double kSubpixel = 256;  // projected vertices live on a grid of 1/256 pixel

// The vertex after i of a polygon of n, without the integer division of (i + 1) % n (edge loops
// run per pixel and per row).
constexpr int next_vertex(int i, int n) { return i + 1 < n ? i + 1 : 0; }

// Whether the point (px, py), in pixels, is inside `poly`: on the inner side of every edge; on an
// edge, of two polygons sharing it (opposite directions) exactly one takes the point.
bool covers_point(const ProjectedElement& poly, double px, double py);
inline bool covers_pixel(const ProjectedElement& poly, int i, int j) { return covers_point(poly, i + 0.5, j + 0.5); }

struct PixelSpan {
  int begin = 0, end = 0;  // pixels begin .. end - 1 (empty when end <= begin)
};

// One element's edges made ready for its rows: at(j, i0, i1) is covered_span(poly, j, i0, i1).
class RowSpans {
 public:
  explicit RowSpans(const ProjectedElement& poly);
  PixelSpan at(int j, int i0, int i1) const;

 private:
  struct Edge {
    std::int64_t slope_j, offset, step_i;  // the edge function at pixel (i, j): slope_j j + offset - step_i i
    bool takes_ties;                       // whether a pixel centre on the edge is inside
  };
  int count_;
  std::array<Edge, 12> edges_;
};

// The pixels i in [i0, i1) of row j with covers_pixel(poly, i, j), exactly.
PixelSpan covered_span(const ProjectedElement& poly, int j, int i0, int i1);

}  // namespace gcsim::radiosity
