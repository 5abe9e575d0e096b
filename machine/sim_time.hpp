#pragma once
// Simulated time: an integer count of picoseconds. Never a double, so that a run is
// deterministic and a long run does not lose resolution (int64 ps covers 106 days).
#include <cmath>
#include <cstdint>

namespace gcsim::machine {

using SimTime = std::int64_t;

inline constexpr SimTime kPicosecond = 1;
inline constexpr SimTime kNanosecond = 1'000;
inline constexpr SimTime kMicrosecond = 1'000'000;
inline constexpr SimTime kMillisecond = 1'000'000'000;
inline constexpr SimTime kSecond = 1'000'000'000'000;

// Rounds up so that a non-zero cost never becomes free.
inline SimTime from_seconds(double s) { return static_cast<SimTime>(std::ceil(s * 1e12)); }
inline double to_seconds(SimTime t) { return static_cast<double>(t) * 1e-12; }
inline double to_milliseconds(SimTime t) { return static_cast<double>(t) * 1e-9; }
inline double to_microseconds(SimTime t) { return static_cast<double>(t) * 1e-6; }

}  // namespace gcsim::machine
