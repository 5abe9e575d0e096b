#include "apps/media/tone_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gcsim::media {

double auto_exposure(const apps::Image& image, const ToneMap& t) {
  std::vector<float> lit;
  for (const glm::vec3& c : image.pixels())
    if (c.x > 0.0f && std::isfinite(c.x)) lit.push_back(c.x);
  if (lit.empty()) return 1.0;
  const auto at = static_cast<std::size_t>(std::clamp(t.percentile, 0.0, 1.0) * double(lit.size() - 1));
  std::nth_element(lit.begin(), lit.begin() + static_cast<std::ptrdiff_t>(at), lit.end());
  return t.white / lit[at];
}

apps::Image tone_mapped(const apps::Image& image, double exposure, const ToneMap& t) {
  const double w2 = t.white * t.white;
  apps::Image out(image.width(), image.height());
  for (std::size_t i = 0; i < image.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = std::max(0.0, double(image.pixels()[i][c]) * exposure);
      out.pixels()[i][c] = static_cast<float>(x * (1.0 + x / w2) / (1.0 + x));
    }
  return out;
}

}  // namespace gcsim::media
