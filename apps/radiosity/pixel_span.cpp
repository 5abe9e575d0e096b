#include "apps/radiosity/pixel_span.hpp"

#include <algorithm>
#include <cstdint>

namespace gcsim::radiosity {

namespace {

// ceil(a / b) for b > 0 (integer division truncates toward zero).
std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return a >= 0 ? (a + b - 1) / b : -((-a) / b); }

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

PixelSpan covered_span(const ProjectedElement& poly, int j, int i0, int i1) {
  // Pixel i's centre is x = 256 i + 128 on the vertex grid, and y = 256 j + 128; an edge's function
  // at pixel i is e(i) = c - 256 dy i, all in integers (|coordinates| < 2^21, products < 2^43).
  const std::int64_t y = std::int64_t(j) * 256 + 128, sign = poly.edge_sign > 0 ? 1 : -1;
  std::int64_t lo = i0, hi = i1;
  for (int k = 0; k < poly.count && lo < hi; ++k) {
    const auto& a = poly.p[k];
    const auto& b = poly.p[next_vertex(k, poly.count)];
    const std::int64_t ax = std::int64_t(a[0]), ay = std::int64_t(a[1]);
    const std::int64_t dx = (std::int64_t(b[0]) - ax) * sign, dy = (std::int64_t(b[1]) - ay) * sign;
    const std::int64_t c = dx * (y - ay) - dy * (128 - ax);
    if (dy == 0) {  // the same at every pixel: e > 0, or on the edge and it runs toward +x
      if (!(c > 0 || (c == 0 && dx > 0))) hi = lo;
    } else if (dy > 0) {  // e(i) > 0 (an edge going up does not take its ties): i < c / 256 dy
      hi = std::min(hi, ceil_div(c, 256 * dy));
    } else {  // e(i) >= 0: i >= -c / 256 |dy|
      lo = std::max(lo, ceil_div(-c, -256 * dy));
    }
  }
  return {int(lo), int(std::max(lo, hi))};
}

}  // namespace gcsim::radiosity
