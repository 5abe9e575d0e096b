#pragma once
// Pixels travel between nodes as 8-bit sRGB, three bytes each, as a frame buffer holds them
// (a float triple would quadruple the traffic into node 0). The curve is the one write_png uses,
// so decoding and writing again gives back exactly the bytes that were sent.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace gcsim::raytrace {

inline std::uint8_t encode_srgb8(float linear) {
  if (!std::isfinite(linear)) linear = 0.0f;
  const float v = std::clamp(linear, 0.0f, 1.0f);
  const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

inline float decode_srgb8(std::uint8_t code) {
  const float s = code / 255.0f;
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

}  // namespace gcsim::raytrace
