#pragma once
// Small scenes for the radiosity tests.
#include "apps/radiosity/hard_case_scenes.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity::testing {

// The furnace box of hard_case_scenes.hpp (a closed cube, faces looking inwards).
using radiosity::closed_box;
// A unit room (scaled by `scale`) lit by a small ceiling light, with a block on the floor and a thin
// panel hovering `gap` above the floor (nearly coplanar when gap is tiny).
Scene lit_room(double scale = 1.0, double gap = 0.05, double rho = 0.6);

}  // namespace gcsim::radiosity::testing
