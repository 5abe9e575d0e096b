#pragma once
// Scenes with closed-form radiosities, for tests and `gcsim accuracy radiosity` table 4: the cases
// where one-point shooting from the patch centre is furthest off (shooters large relative to their
// distance to the receivers).
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// Emitter (exitance 1, black) at z = 0 facing +z, receiver (grey, reflectance rho) at z = d facing
// -z; unit squares, one patch and one element each. The receiver's exact radiosity is
// rho * F(unit square -> unit square at distance d) (parallel_rectangles_form_factor).
Scene facing_unit_squares(double d, double rho);

// A closed cube of side s, every face n x n patches of m x m elements, all reflectance rho and
// exitance e: every element's exact radiosity is e / (1 - rho) (the furnace test).
Scene closed_box(double s, int n, int m, double rho, double e);

}  // namespace gcsim::radiosity
