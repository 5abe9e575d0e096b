#pragma once
// The radiosity at each corner of each element, for display (thesis section 3.5.1, step 3): the
// area-weighted mean over the elements sharing the vertex that lie in the same plane and have the
// same surface, so box edges and the colour fields of pictures stay crisp. The Gouraud renderer
// and the unified renderer's view pass both interpolate these.
#include <array>
#include <vector>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// One entry per element, corners in the element's vertex order (the unused fourth of a triangle
// is zero).
std::vector<std::array<Rgb, 4>> element_corner_radiosity(const Scene& scene, const std::vector<Rgb>& element_radiosity);

}  // namespace gcsim::radiosity
