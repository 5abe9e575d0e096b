#pragma once
// Exposure for the PNG of a radiance image. The media images span orders of magnitude (a glowing object
// next to faint fog), so a fixed exposure leaves them black or clipped. Auto exposure maps a high
// percentile of the lit pixels to the white point, and the extended Reinhard curve
//   y = x (1 + x / w²) / (1 + x)
// (y = 1 at x = w, y ≈ x for faint values) compresses the bright object so the fog keeps its detail.
#include "apps/common/image.hpp"

namespace gcsim::apps {

struct ToneMap {
  double percentile = 0.99;  // of the pixels with luminance > 0
  double white = 4.0;        // the scaled value shown as full white
};

// The exposure that maps the percentile of the positive pixel values to the white point; 1 for an
// all-black image.
double auto_exposure(const Image& image, const ToneMap& t = {});

// A copy with every value scaled by `exposure` and passed through the extended Reinhard curve.
Image tone_mapped(const Image& image, double exposure, const ToneMap& t = {});

}  // namespace gcsim::apps
