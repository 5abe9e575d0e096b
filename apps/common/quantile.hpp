#pragma once
// The q-quantile of a sample, as image exposure and the media error measures read it.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace gcsim::apps {

// The q-quantile of non-empty `values` (the element at rank q (n − 1), rounded down); reorders them.
inline double quantile(std::vector<double>& values, double q) {
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(std::clamp(q, 0.0, 1.0) * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

}  // namespace gcsim::apps
