#pragma once
// Small scenes for the radiosity tests.
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity::testing {

// A closed cube of side `size`, faces looking inwards, each split into n x n patches of m x m
// elements, every surface with reflectance rho and exitance e.
Scene closed_box(double size, int n, int m, double rho, double e);
// A unit room (scaled by `scale`) lit by a small ceiling light, with a block on the floor and a thin
// panel hovering `gap` above the floor (nearly coplanar when gap is tiny).
Scene lit_room(double scale = 1.0, double gap = 0.05, double rho = 0.6);

}  // namespace gcsim::radiosity::testing
