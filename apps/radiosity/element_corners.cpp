#include "apps/radiosity/element_corners.hpp"

namespace gcsim::radiosity {

std::vector<std::array<Rgb, 4>> element_corner_radiosity(const Scene& scene, const std::vector<Rgb>& b) {
  std::vector<std::vector<int>> users(scene.vertices.size());
  for (int e = 0; e < int(scene.elements.size()); ++e)
    for (int k = 0; k < scene.elements[e].count; ++k) users[scene.elements[e].vertex[k]].push_back(e);
  auto corner_value = [&](int e, int v) {
    Rgb sum(0.0);
    double area = 0;
    for (int u : users[v])
      if (glm::dot(scene.elements[u].normal, scene.elements[e].normal) > 0.999 &&
          scene.patches[scene.elements[u].patch].surface == scene.patches[scene.elements[e].patch].surface) {
        sum += b[u] * scene.elements[u].area;
        area += scene.elements[u].area;
      }
    return area > 0 ? sum / area : b[e];
  };
  std::vector<std::array<Rgb, 4>> corners(scene.elements.size(), std::array<Rgb, 4>{});
  for (int e = 0; e < int(scene.elements.size()); ++e)
    for (int k = 0; k < scene.elements[e].count; ++k) corners[e][k] = corner_value(e, scene.elements[e].vertex[k]);
  return corners;
}

}  // namespace gcsim::radiosity
