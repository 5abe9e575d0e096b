// Hemicube form factors against closed forms, sums in closed environments, and hard geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "apps/radiosity/analytic_form_factors.hpp"
#include "apps/radiosity/delta_form_factors.hpp"
#include "apps/radiosity/hemicube.hpp"
#include "apps/radiosity/pixel_span.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

double patch_sum(const std::vector<double>& row, const Scene& s, int patch) {
  double f = 0;
  const ScenePatch& p = s.patches[patch];
  for (int e = p.first_element; e < p.first_element + p.element_count; ++e) f += row[e];
  return f;
}

double hemicube_point(FormFactorCase c, int res, double scale = 1.0) {
  FormFactorSetup setup = form_factor_setup(c, scale, 1);
  HemicubeOptions o;
  o.resolution = res;
  o.max_shooter_samples = 1;  // the hemicube at the patch centre: the point form factor
  HemicubeRenderer r(setup.scene, o);
  OpCounts ops;
  return patch_sum(r.form_factor_row(0, ops), setup.scene, setup.receiver_patch);
}

TEST(ClosedForms, KnownValues) {
  EXPECT_NEAR(parallel_rectangles_form_factor(1, 1, 1), 0.19982, 1e-5);
  EXPECT_NEAR(perpendicular_rectangles_form_factor(1, 1, 1), 0.20004, 1e-5);
  EXPECT_NEAR(point_to_disc_form_factor(1, 1), 0.5, 1e-15);
  // Lambert's contour formula agrees with the disc formula for a fine polygon.
  Polygon square;
  square.count = 4;
  square.v = {Vec3{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}};
  EXPECT_NEAR(point_to_polygon_form_factor({0, 0, 0}, {0, 0, 1}, square), 0.2394, 1e-4);
}

// The tolerance tightens with resolution: 16 -> 3%, 64 -> 1%, 256 -> 0.3%.
TEST(HemicubeFormFactor, ApproachesClosedFormsAsResolutionGrows) {
  const std::pair<int, double> tolerance[] = {{16, 0.03}, {64, 0.01}, {256, 0.003}};
  for (FormFactorCase c : {FormFactorCase::parallel_squares, FormFactorCase::perpendicular_squares,
                           FormFactorCase::patch_to_disc}) {
    double exact = form_factor_setup(c, 1.0, 1).exact_point;
    for (auto [res, tol] : tolerance) {
      double err = std::abs(hemicube_point(c, res) - exact) / exact;
      EXPECT_LT(err, tol) << to_string(c) << " at " << res;
    }
  }
}

TEST(HemicubeFormFactor, AreaAverageMatchesAreaToAreaClosedForm) {
  for (FormFactorCase c : {FormFactorCase::parallel_squares, FormFactorCase::perpendicular_squares}) {
    const int n = 4;
    FormFactorSetup s = form_factor_setup(c, 1.0, n);
    HemicubeOptions o;
    o.resolution = 64;
    HemicubeRenderer r(s.scene, o);
    OpCounts ops;
    double sum = 0;
    for (int p = 0; p < n * n; ++p) sum += patch_sum(r.form_factor_row(p, ops), s.scene, s.receiver_patch);
    EXPECT_NEAR(sum / (n * n), s.exact_area, 0.02 * s.exact_area) << to_string(c);
  }
}

TEST(HemicubeFormFactor, ClosedBoxRowsSumToOne) {
  Scene box = testing::closed_box(1.0, 2, 2, 0.5, 1.0);
  HemicubeOptions o;
  o.resolution = 32;
  HemicubeRenderer r(box, o);
  OpCounts ops;
  for (int p = 0; p < int(box.patches.size()); ++p) {
    auto row = r.form_factor_row(p, ops);
    double sum = 0;
    for (double f : row) {
      EXPECT_GE(f, 0);
      sum += f;
    }
    EXPECT_NEAR(sum, 1.0, 1e-9) << "patch " << p;
    // A patch sees nothing of its own wall.
    EXPECT_EQ(patch_sum(row, box, p), 0.0);
  }
}

TEST(HemicubeFormFactor, ScaleInvariant) {
  for (FormFactorCase c : {FormFactorCase::parallel_squares, FormFactorCase::perpendicular_squares,
                           FormFactorCase::patch_to_disc}) {
    double unit = hemicube_point(c, 64);
    EXPECT_NEAR(hemicube_point(c, 64, 1e-3), unit, 1e-6 * unit) << to_string(c);
    EXPECT_NEAR(hemicube_point(c, 64, 1e3), unit, 1e-6 * unit) << to_string(c);
  }
}

// The perpendicular square touches the source along an edge; seen from the source's centre a single
// element spans the top face and a side face. Both parts must be counted.
TEST(HemicubeFormFactor, ElementAcrossFaceBoundariesIsCountedOnEveryFace) {
  FormFactorSetup s = form_factor_setup(FormFactorCase::perpendicular_squares, 1.0, 1);
  HemicubeOptions o;
  o.resolution = 64;
  o.max_shooter_samples = 1;
  o.cells_per_side = 2;  // cells: 4 top, then 2 per side face
  HemicubeRenderer r(s.scene, o);
  OpCounts ops;
  r.project(0, ops);
  double top = 0, sides = 0;
  for (int c = 0; c < r.cell_count(); ++c) {
    auto cf = r.cell_form_factors(c, ops);
    double v = 0;
    for (double x : cf.value) v += x;
    (c < 4 ? top : sides) += v;
  }
  EXPECT_GT(top, 0.02);
  EXPECT_GT(sides, 0.02);
  EXPECT_NEAR(top + sides, s.exact_point, 0.02 * s.exact_point);
}

TEST(HemicubeFormFactor, HierarchicalAgreesWithFixed) {
  for (FormFactorCase c : {FormFactorCase::parallel_squares, FormFactorCase::perpendicular_squares,
                           FormFactorCase::patch_to_disc}) {
    FormFactorSetup s = form_factor_setup(c, 1.0, 1);
    HemicubeOptions fixed, hier;
    fixed.resolution = hier.resolution = 128;
    fixed.max_shooter_samples = hier.max_shooter_samples = 1;
    hier.hierarchical_levels = 3;
    OpCounts a, b;
    HemicubeRenderer rf(s.scene, fixed), rh(s.scene, hier);
    double ff = patch_sum(rf.form_factor_row(0, a), s.scene, s.receiver_patch);
    double fh = patch_sum(rh.form_factor_row(0, b), s.scene, s.receiver_patch);
    EXPECT_NEAR(fh, ff, 0.01 * ff) << to_string(c);
    EXPECT_NEAR(fh, s.exact_point, 0.01 * s.exact_point) << to_string(c);
  }
}


// The Z-buffer as defined, one pixel at a time: of the elements whose projection covers the pixel's
// centre, the nearest (the first of equals) gives it its delta form factor, added in the renderer's
// order (cell by cell, sample by sample, row by row). The renderer's spans, ray tables and runs must
// give the same row to the last bit.
std::vector<double> row_by_definition(const HemicubeRenderer& r, const Scene& scene, const HemicubeOptions& o) {
  const HemicubeProjection& pr = *r.projection();
  const int res = o.resolution / pr.samples_per_side;
  const auto dff = shared_delta_form_factors(res);
  std::vector<double> row(scene.elements.size(), 0.0);
  for (const HemicubeCell& c : hemicube_cells(res, o.cells_per_side)) {
    std::vector<double> acc(scene.elements.size(), 0.0);
    for (std::size_t k = 0; k < pr.samples.size(); ++k)
      for (int j = c.j0; j < c.j1; ++j)
        for (int i = c.i0; i < c.i1; ++i) {
          const glm::dvec3 ray{(i + 0.5) * 2 / res - 1, c.face == kTopFace ? (j + 0.5) * 2 / res - 1 : (j + 0.5) * 2 / res, 1.0};
          double best = std::numeric_limits<double>::infinity();
          int item = -1;
          for (const ProjectedElement& p : pr.faces[k][std::size_t(c.face)]) {
            if (!covers_pixel(p, i, j)) continue;
            const double den = glm::dot(p.plane_n, ray), t = den == 0 ? -1.0 : p.plane_k / den;
            if (t > 0 && t < best) best = t, item = p.front ? p.element : -2;
          }
          const double w = pr.samples[k].weight, f = dff->at(c.face, i, j);
          if (item >= 0) acc[std::size_t(item)] += w == 1.0 ? f : w * f;
        }
    for (std::size_t e = 0; e < row.size(); ++e) row[e] += acc[e];
  }
  return row;
}

TEST(HemicubeFormFactor, ZBufferIsThePerPixelDefinitionBitForBit) {
  // A panel 1e-4 above the floor (nearly coplanar), a block, a small light; near-field samples on.
  const Scene room = testing::lit_room(1.0, 1e-4);
  HemicubeOptions o;
  o.resolution = 64;
  o.max_shooter_samples = 2;
  HemicubeRenderer r(room, o);
  int compared = 0;
  for (int shooter = 0; shooter < int(room.patches.size()); shooter += 3) {
    OpCounts ops;
    const std::vector<double> fast = r.form_factor_row(shooter, ops);
    const std::vector<double> slow = row_by_definition(r, room, o);
    for (std::size_t e = 0; e < fast.size(); ++e) ASSERT_EQ(fast[e], slow[e]) << "shooter " << shooter << ", element " << e;
    compared += r.projection()->samples_per_side > 1;
  }
  EXPECT_GT(compared, 0);  // some shooters shot from several points
}

}  // namespace
}  // namespace gcsim::radiosity
