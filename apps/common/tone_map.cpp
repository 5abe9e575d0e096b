#include "apps/common/tone_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "apps/common/quantile.hpp"

namespace gcsim::apps {

double auto_exposure(const Image& image, const ToneMap& t) {
  std::vector<double> lit;
  for (const glm::vec3& c : image.pixels())
    if (c.x > 0.0f && std::isfinite(c.x)) lit.push_back(c.x);
  if (lit.empty()) return 1.0;
  return t.white / quantile(lit, t.percentile);
}

Image tone_mapped(const Image& image, double exposure, const ToneMap& t) {
  const double w2 = t.white * t.white;
  Image out(image.width(), image.height());
  for (std::size_t i = 0; i < image.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = std::max(0.0, double(image.pixels()[i][c]) * exposure);
      out.pixels()[i][c] = static_cast<float>(x * (1.0 + x / w2) / (1.0 + x));
    }
  return out;
}

}  // namespace gcsim::apps
