#pragma once
// Error measures between luminance images (the x channel) of the same size.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "apps/common/image.hpp"

namespace gcsim::media {

inline void require_same_size(const apps::Image& a, const apps::Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) throw std::invalid_argument("images of different sizes");
}

inline double mean_value(const apps::Image& a) {
  double s = 0.0;
  for (const glm::vec3& c : a.pixels()) s += c.x;
  return a.pixels().empty() ? 0.0 : s / double(a.pixels().size());
}

inline double rmse(const apps::Image& a, const apps::Image& b) {
  require_same_size(a, b);
  double s = 0.0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const double d = double(a.pixels()[i].x) - double(b.pixels()[i].x);
    s += d * d;
  }
  return a.pixels().empty() ? 0.0 : std::sqrt(s / double(a.pixels().size()));
}

// The pixel-wise mean of images of the same size.
inline apps::Image mean_image(const std::vector<apps::Image>& images) {
  apps::Image out(images.at(0).width(), images.at(0).height());
  for (const apps::Image& im : images) {
    require_same_size(out, im);
    for (std::size_t i = 0; i < out.pixels().size(); ++i) out.pixels()[i] += im.pixels()[i] / float(images.size());
  }
  return out;
}

// Noise spread over the image: per pixel, the relative standard deviation of repeated renders about the
// reference, sqrt(mean_r (x_r − ref)²) / ref, over the pixels whose reference is at least `lit` × the
// mean; returns its 95th percentile over its median (1 would be perfectly even noise; 0 if no pixel).
inline double relative_noise_spread(const std::vector<apps::Image>& repeats, const apps::Image& reference,
                                    double lit = 0.05) {
  const double threshold = lit * mean_value(reference);
  std::vector<double> rel;
  for (std::size_t i = 0; i < reference.pixels().size(); ++i) {
    const double ref = reference.pixels()[i].x;
    if (ref <= threshold || ref <= 0.0) continue;
    double s = 0.0;
    for (const apps::Image& r : repeats) s += std::pow(double(r.pixels()[i].x) - ref, 2);
    rel.push_back(std::sqrt(s / double(repeats.size())) / ref);
  }
  if (rel.empty()) return 0.0;
  auto quantile = [&rel](double q) {
    auto at = rel.begin() + static_cast<std::ptrdiff_t>(q * double(rel.size() - 1));
    std::nth_element(rel.begin(), at, rel.end());
    return *at;
  };
  const double median = quantile(0.5);
  return median > 0.0 ? quantile(0.95) / median : 0.0;
}

}  // namespace gcsim::media
