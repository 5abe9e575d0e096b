#pragma once
// The kernel-throughput benchmark: every processor sends to its right neighbour and receives from
// its left, `iterations` times, over persistent links.
#include <cstdint>

#include "parix/processor.hpp"

namespace gcsim::programs {

void ring_exchange(parix::Processor& p, int iterations, std::int64_t bytes);

}  // namespace gcsim::programs
