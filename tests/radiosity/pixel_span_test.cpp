// The Z-buffer's row spans against its per-pixel test, on the cases where one pixel decides: vertices
// and edges through pixel centres, horizontal and vertical edges, edges shared by two polygons,
// slivers, both windings, and random polygons on the 1/256 grid. Every row, every pixel, exactly.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "apps/radiosity/pixel_span.hpp"

namespace gcsim::radiosity {
namespace {

// A polygon from vertices in units of 1/256 pixel, with its winding's sign as project_from sets it.
ProjectedElement polygon(const std::vector<std::array<double, 2>>& v) {
  ProjectedElement p{};
  p.count = int(v.size());
  double area2 = 0;
  for (int i = 0; i < p.count; ++i) {
    p.p[i] = v[std::size_t(i)];
    const auto& a = v[std::size_t(i)];
    const auto& b = v[std::size_t(next_vertex(i, p.count))];
    area2 += a[0] * b[1] - a[1] * b[0];
  }
  p.edge_sign = area2 > 0 ? 1.0 : -1.0;
  return p;
}

// Every row of a 40 x 40 window: the span holds exactly the pixels the per-pixel test takes.
int expect_span_is_the_pixel_test(const ProjectedElement& p, int i0 = 0, int i1 = 40) {
  int covered = 0;
  for (int j = -2; j < 42; ++j) {
    const PixelSpan s = covered_span(p, j, i0, i1);
    for (int i = i0; i < i1; ++i) {
      const bool in_span = i >= s.begin && i < s.end;
      EXPECT_EQ(in_span, covers_pixel(p, i, j)) << "pixel " << i << ", " << j;
      covered += in_span;
    }
  }
  return covered;
}

constexpr double kPx = kSubpixel;       // one pixel
constexpr double kCentre = kSubpixel / 2;  // a pixel centre's offset

TEST(PixelSpan, ASquareOnPixelCentresTakesItsLowerLeftEdgesOnly) {
  // Corners on the centres of pixels 2 and 6: edges through centres, taken on one side only.
  const double lo = 2 * kPx + kCentre, hi = 6 * kPx + kCentre;
  for (bool ccw : {true, false}) {
    std::vector<std::array<double, 2>> v{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
    if (!ccw) std::swap(v[1], v[3]);
    EXPECT_EQ(expect_span_is_the_pixel_test(polygon(v)), 16) << (ccw ? "counter-clockwise" : "clockwise");
  }
}

TEST(PixelSpan, TwoTrianglesSharingADiagonalTakeEachPixelOnce) {
  const double a = 1 * kPx + kCentre, b = 30 * kPx + kCentre;
  const ProjectedElement lower = polygon({{a, a}, {b, a}, {b, b}}), upper = polygon({{a, a}, {b, b}, {a, b}});
  const ProjectedElement whole = polygon({{a, a}, {b, a}, {b, b}, {a, b}});
  EXPECT_EQ(expect_span_is_the_pixel_test(lower) + expect_span_is_the_pixel_test(upper),
            expect_span_is_the_pixel_test(whole));
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) EXPECT_FALSE(covers_pixel(lower, i, j) && covers_pixel(upper, i, j));
}

TEST(PixelSpan, SliversAndPointsTakeWhatThePixelTestTakes) {
  const double c = 10 * kPx + kCentre;
  expect_span_is_the_pixel_test(polygon({{c, c}, {c + 20 * kPx, c + 1}, {c + 20 * kPx, c + 2}}));  // thinner than a pixel
  expect_span_is_the_pixel_test(polygon({{c, c - 5 * kPx}, {c + 1, c - 5 * kPx}, {c + 1, c + 5 * kPx}}));  // upright
  EXPECT_EQ(expect_span_is_the_pixel_test(polygon({{c - 1, c - 1}, {c + 1, c - 1}, {c, c + 1}})), 1);  // around one centre
}

TEST(PixelSpan, TheWindowClipsTheSpan) {
  const ProjectedElement p = polygon({{0, 0}, {40 * kPx, 0}, {40 * kPx, 40 * kPx}, {0, 40 * kPx}});
  EXPECT_EQ(expect_span_is_the_pixel_test(p, 7, 19), 12 * 40);
  EXPECT_EQ(covered_span(p, 3, 20, 10).end - covered_span(p, 3, 20, 10).begin, 0);
}

TEST(PixelSpan, RandomPolygonsOnTheGridAgreeEverywhere) {
  std::mt19937 rng(7);
  // Coordinates on whole pixels, centres and 1/256 steps, beyond the window too.
  std::uniform_int_distribution<int> at(-3 * 256, 43 * 256), pick(0, 2);
  for (int n = 0; n < 400; ++n) {
    std::vector<std::array<double, 2>> v;
    const int count = 3 + n % 2;
    for (int k = 0; k < count; ++k) {
      double x = at(rng), y = at(rng);
      if (pick(rng) == 0) x = std::floor(x / kPx) * kPx + kCentre;  // on a centre's column
      if (pick(rng) == 0) y = std::floor(y / kPx) * kPx + kCentre;  // on a centre's row
      v.push_back({x, y});
    }
    if (n % 7 == 0) v[1][1] = v[0][1];  // a horizontal edge
    expect_span_is_the_pixel_test(polygon(v));
    if (::testing::Test::HasFailure()) break;
  }
}

}  // namespace
}  // namespace gcsim::radiosity
