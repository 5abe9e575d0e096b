#pragma once
// Floating-point helpers for conservative geometry: the gamma(n) bound on n rounding errors
// (Higham), and stepping a float by one unit in the last place.
#include <cmath>
#include <limits>

namespace gcsim::raytrace {

inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Bound on the relative error after n floating-point operations: n*eps / (1 - n*eps).
constexpr float gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

inline float next_float_up(float v) { return std::nextafter(v, kInfinity); }
inline float next_float_down(float v) { return std::nextafter(v, -kInfinity); }

}  // namespace gcsim::raytrace
