#pragma once
// Displays a radiosity solution (thesis section 3.5.1, step 3): element radiosities are averaged at
// the vertices and interpolated across each element (Gouraud), hidden surfaces removed by Z-buffer.
// Vertex values average only elements in the same plane with the same surface, so box edges and
// the colour fields of pictures stay crisp.
#include <vector>

#include "apps/common/image.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

struct RenderOptions {
  int width = 512;
  int height = 512;
  double exposure = 0;  // 0: automatic (the 97th percentile of lit, non-emitting pixels maps to 0.85)
};

// The exposure the automatic setting would choose for this solution and view.
double auto_exposure(const Scene& scene, const std::vector<Rgb>& element_radiosity, const Camera& camera,
                     const RenderOptions& options);

apps::Image render_gouraud(const Scene& scene, const std::vector<Rgb>& element_radiosity, const Camera& camera,
                           const RenderOptions& options);

}  // namespace gcsim::radiosity
