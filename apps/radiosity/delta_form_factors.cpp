#include "apps/radiosity/delta_form_factors.hpp"

#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::radiosity {

DeltaFormFactors::DeltaFormFactors(int r) : r_(r) {
  if (r < 2 || r % 2 != 0)
    throw std::invalid_argument(fmt::format("hemicube resolution must be even and at least 2, got {}", r));
  const double cell = 2.0 / r, dA = cell * cell, pi = std::numbers::pi;
  for (int f = 0; f < kHemicubeFaces; ++f) {
    int h = height(f);
    dff_[f].resize(std::size_t(r) * h);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < r; ++i) {
        double x = -1 + (i + 0.5) * cell;
        double v;
        if (f == kTopFace) {
          double y = -1 + (j + 0.5) * cell;
          v = dA / (pi * (x * x + y * y + 1) * (x * x + y * y + 1));  // eq. 3.19
        } else {
          double z = (j + 0.5) * cell;
          v = z * dA / (pi * (x * x + z * z + 1) * (x * x + z * z + 1));  // eqs. 3.20, 3.21
        }
        dff_[f][std::size_t(j) * r + i] = v;
        raw_total_ += v;
      }
  }
  // The discrete sum misses 1 by O(1/R^2); scaling it to exactly 1 makes a closed environment
  // conserve energy exactly, whatever the resolution.
  for (auto& face : dff_)
    for (double& v : face) v /= raw_total_;
  for (int f = 0; f < kHemicubeFaces; ++f) {
    int w = r, h = height(f);
    sat_[f].assign(std::size_t(w + 1) * (h + 1), 0.0);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        sat_[f][std::size_t(j + 1) * (w + 1) + i + 1] = dff_[f][std::size_t(j) * w + i] +
                                                         sat_[f][std::size_t(j) * (w + 1) + i + 1] +
                                                         sat_[f][std::size_t(j + 1) * (w + 1) + i] -
                                                         sat_[f][std::size_t(j) * (w + 1) + i];
  }
}

double DeltaFormFactors::rect_sum(int f, int i0, int j0, int i1, int j1) const {
  const int w = r_ + 1;
  const auto& s = sat_[f];
  return s[std::size_t(j1) * w + i1] - s[std::size_t(j0) * w + i1] - s[std::size_t(j1) * w + i0] +
         s[std::size_t(j0) * w + i0];
}

std::vector<HemicubeCell> hemicube_cells(int r, int t) {
  if (t < 2 || t % 2 != 0) throw std::invalid_argument(fmt::format("cells per side must be even and >= 2, got {}", t));
  if (r < t) throw std::invalid_argument(fmt::format("hemicube resolution {} is below the cells per side {}", r, t));
  std::vector<HemicubeCell> cells;
  for (int f = 0; f < kHemicubeFaces; ++f) {
    int rows = f == kTopFace ? t : t / 2, h = f == kTopFace ? r : r / 2;
    for (int cj = 0; cj < rows; ++cj)
      for (int ci = 0; ci < t; ++ci)
        cells.push_back({f, ci * r / t, cj * h / rows, (ci + 1) * r / t, (cj + 1) * h / rows});
  }
  return cells;
}

std::shared_ptr<const DeltaFormFactors> shared_delta_form_factors(int resolution) {
  static std::mutex lock;
  static std::map<int, std::weak_ptr<const DeltaFormFactors>> tables;
  std::lock_guard<std::mutex> held(lock);
  std::weak_ptr<const DeltaFormFactors>& slot = tables[resolution];
  if (auto alive = slot.lock()) return alive;
  auto made = std::make_shared<const DeltaFormFactors>(resolution);
  slot = made;
  return made;
}

}  // namespace gcsim::radiosity
