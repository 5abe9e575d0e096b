#pragma once
// Closed-form form factors to check the hemicube against (see e.g. Howell's catalogue), and the
// small scenes that pose each case.
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// Differential area at `point` with unit `normal` to a whole polygon (unoccluded, in front):
// Lambert's contour formula F = 1/(2 pi) * sum_i gamma_i * n . (R_i x R_i+1) / |R_i x R_i+1|.
double point_to_polygon_form_factor(const Vec3& point, const Vec3& normal, const Polygon& polygon);
// Two directly opposed parallel rectangles a x b at distance c, area to area.
double parallel_rectangles_form_factor(double a, double b, double c);
// Two rectangles sharing an edge of length l at a right angle; from the one of width w to the one
// of height h, area to area.
double perpendicular_rectangles_form_factor(double l, double w, double h);
// Differential area to a coaxial parallel disc of radius r at distance h: r^2 / (h^2 + r^2).
double point_to_disc_form_factor(double r, double h);

// The test scenes. Patch 0 is the one whose hemicube is measured; `receiver_patch` receives.
// `subdivisions` splits the first patch into n x n patches (area averages) where it applies.
enum class FormFactorCase { parallel_squares, perpendicular_squares, patch_to_disc };
struct FormFactorSetup {
  Scene scene;
  int receiver_patch;          // index of the receiving patch
  double exact_point;          // closed form from the centre of patch 0
  double exact_area;           // closed form area to area (the disc case: the ideal disc, r^2/(h^2+r^2))
};
FormFactorSetup form_factor_setup(FormFactorCase c, double scale = 1.0, int subdivisions = 1);
const char* to_string(FormFactorCase c);

}  // namespace gcsim::radiosity
