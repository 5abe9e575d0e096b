#pragma once
// Error measures between luminance images (the x channel) of the same size.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "apps/common/image.hpp"
#include "apps/common/quantile.hpp"

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

using apps::quantile;

// Per pixel, the relative standard deviation of repeated renders: the sample standard deviation about
// their own mean (so the reference's noise does not add a floor that is the same for every estimator)
// over the reference, for the pixels whose reference is at least `lit` x the image mean; 0 elsewhere.
inline apps::Image relative_noise_map(const std::vector<apps::Image>& repeats, const apps::Image& reference,
                                      double lit = 0.05) {
  if (repeats.size() < 2) throw std::invalid_argument("a noise map needs at least two renders");
  const double threshold = lit * mean_value(reference);
  apps::Image out(reference.width(), reference.height());
  for (std::size_t i = 0; i < reference.pixels().size(); ++i) {
    const double ref = reference.pixels()[i].x;
    if (ref <= threshold || ref <= 0.0) continue;
    double mean = 0.0, s = 0.0;
    for (const apps::Image& r : repeats) mean += r.pixels()[i].x;
    mean /= double(repeats.size());
    for (const apps::Image& r : repeats) s += std::pow(double(r.pixels()[i].x) - mean, 2);
    out.pixels()[i] = glm::vec3(static_cast<float>(std::sqrt(s / double(repeats.size() - 1)) / ref));
  }
  return out;
}

// Noise spread over the image: the 95th percentile of relative_noise_map's lit pixels over their median
// (1 would be perfectly even noise; 0 if no pixel is lit or none varies).
inline double relative_noise_spread(const std::vector<apps::Image>& repeats, const apps::Image& reference,
                                    double lit = 0.05) {
  const apps::Image map = relative_noise_map(repeats, reference, lit);
  const double threshold = lit * mean_value(reference);
  std::vector<double> rel;
  for (std::size_t i = 0; i < reference.pixels().size(); ++i)
    if (reference.pixels()[i].x > threshold && reference.pixels()[i].x > 0.0) rel.push_back(map.pixels()[i].x);
  if (rel.empty()) return 0.0;
  const double median = quantile(rel, 0.5);
  return median > 0.0 ? quantile(rel, 0.95) / median : 0.0;
}

}  // namespace gcsim::media
