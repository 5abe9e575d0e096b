#include "apps/radiosity/pixel_span.hpp"

#include <algorithm>
#include <cmath>

namespace gcsim::radiosity {

namespace {

// ceil(a / b) for b > 0, |a| and b below 2^50: the double quotient is within 2^-3 of a / b, so its
// ceiling is off by at most one, which the integer products settle (no 64-bit integer division).
std::int64_t ceil_div(std::int64_t a, std::int64_t b) {
  std::int64_t q = std::int64_t(std::ceil(double(a) / double(b)));
  if (q * b < a) ++q;
  else if ((q - 1) * b >= a) --q;
  return q;
}

}  // namespace

bool covers_point(const ProjectedElement& poly, double px, double py) {
  const double x = px * kSubpixel, y = py * kSubpixel;
  for (int i = 0; i < poly.count; ++i) {
    const auto& a = poly.p[i];
    const auto& b = poly.p[next_vertex(i, poly.count)];
    const double dx = (b[0] - a[0]) * poly.edge_sign, dy = (b[1] - a[1]) * poly.edge_sign;
    const double e = dx * (y - a[1]) - dy * (x - a[0]);
    if (e < 0) return false;
    if (e == 0 && !(dy < 0 || (dy == 0 && dx > 0))) return false;
  }
  return true;
}

RowSpans::RowSpans(const ProjectedElement& poly) : count_(poly.count) {
  // Pixel (i, j)'s centre is (256 i + 128, 256 j + 128) on the vertex grid, and an edge's function
  // there is e = dx (y - ay) - dy (x - ax) = c(j) - 256 dy i with c(j) = 256 dx j + c0: integers.
  const std::int64_t sign = poly.edge_sign > 0 ? 1 : -1;
  for (int k = 0; k < count_; ++k) {
    const auto& a = poly.p[k];
    const auto& b = poly.p[next_vertex(k, poly.count)];
    const std::int64_t ax = std::int64_t(a[0]), ay = std::int64_t(a[1]);
    const std::int64_t dx = (std::int64_t(b[0]) - ax) * sign, dy = (std::int64_t(b[1]) - ay) * sign;
    edges_[std::size_t(k)] = {256 * dx, dx * (128 - ay) - dy * (128 - ax), 256 * dy, dy < 0 || (dy == 0 && dx > 0)};
  }
}

PixelSpan RowSpans::at(int j, int i0, int i1) const {
  std::int64_t lo = i0, hi = i1;
  for (int k = 0; k < count_ && lo < hi; ++k) {
    const Edge& e = edges_[std::size_t(k)];
    const std::int64_t c = e.slope_j * j + e.offset;  // e at pixel i: c - step_i i
    if (e.step_i > 0) hi = std::min(hi, ceil_div(c, e.step_i));  // e > 0: an edge going up takes no ties
    else if (e.step_i < 0) lo = std::max(lo, ceil_div(-c, -e.step_i));  // e >= 0
    else if (!(c > 0 || (c == 0 && e.takes_ties))) hi = lo;  // level: the same at every pixel
  }
  return {int(lo), int(std::max(lo, hi))};
}

PixelSpan covered_span(const ProjectedElement& poly, int j, int i0, int i1) { return RowSpans(poly).at(j, i0, i1); }

}  // namespace gcsim::radiosity
