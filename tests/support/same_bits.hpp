#pragma once
// Bit-for-bit equality of two floats (+0 and -0 differ, a NaN equals itself): what the tests of
// kernels that must agree exactly with their reference compare.
#include <cstring>

namespace gcsim::test_support {

inline bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace gcsim::test_support
