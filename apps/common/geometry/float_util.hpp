#pragma once
// Floating-point helpers for conservative geometry: the gamma(n) bound on n rounding errors
// (Higham), and stepping a float by one unit in the last place.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace gcsim::geometry {

inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Bound on the relative error after n floating-point operations: n*eps / (1 - n*eps).
constexpr float gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }
// The same for arithmetic in T (float or double).
template <class T>
constexpr T gamma_of(int n) {
  constexpr T eps = std::numeric_limits<T>::epsilon() * T(0.5);
  return (n * eps) / (1 - n * eps);
}

// Component-wise |v| without branches (glm::abs compiles to compare-and-branch).
template <class V>
inline V abs_components(V v) {
  for (int i = 0; i < V::length(); ++i) v[i] = std::fabs(v[i]);
  return v;
}

// std::nextafter(v, +-inf) in line: libm's is a call, and the occlusion check's threshold takes
// three per region. Same answer for every float (tested): NaN and the infinity stepped towards
// stay, zeros of either sign step to the smallest denormal, the rest move their bits by one.
inline float next_float_up(float v) {
  if (!(v < kInfinity)) return v;  // NaN or +inf
  if (v == 0.0f) return std::numeric_limits<float>::denorm_min();
  const auto bits = std::bit_cast<std::uint32_t>(v);
  return std::bit_cast<float>(v > 0.0f ? bits + 1 : bits - 1);
}
inline float next_float_down(float v) { return -next_float_up(-v); }

// The largest float x with std::sqrt(x) <= limit (NaN for a NaN limit, -inf below zero): as
// sqrt is correctly rounded and so never decreases, std::sqrt(s) > limit exactly when
// s > largest_with_sqrt_at_most(limit), for every float s. One threshold per limit spares a
// square root per comparison.
inline float largest_with_sqrt_at_most(float limit) {
  if (std::isnan(limit)) return limit;
  if (limit < 0.0f) return -kInfinity;
  float x = limit * limit;  // within an ulp or two of the answer
  while (x > 0.0f && std::sqrt(x) > limit) x = next_float_down(x);
  while (x < kInfinity && std::sqrt(next_float_up(x)) <= limit) x = next_float_up(x);
  return x;
}

}  // namespace gcsim::geometry
