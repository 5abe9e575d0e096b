#pragma once
// Resources checked before the work: what a run will hold on each simulated node and
// on the host is compared with what there is before anything is allocated, so that an argument
// too large fails at once with the amount needed instead of after minutes or by exhausting the host.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "machine/node_memory.hpp"

namespace gcsim::pipeline {

// The host has not the memory a run needs.
class HostMemoryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Memory of one kind one node holds ("scene", "image", ...).
struct MemoryNeed {
  std::string kind;
  std::int64_t bytes = 0;
};

// The host's available memory: MemAvailable of /proc/meminfo, else free pages (sysconf); -1 when
// neither can be read.
std::int64_t host_available_bytes();

// Throws HostMemoryError "WHAT needs about X of host memory; this host has Y available" when
// bytes exceed the host's available memory (nothing when it cannot be read).
void check_host_memory(std::int64_t bytes, std::string_view what);

// Throws parix::OutOfMemoryError (the runtime's own report: processor, what it would hold by kind,
// the node's memory) when `needs` exceed `capacity` bytes; with MemoryLimit::warn, nothing.
void check_node_memory(const std::vector<MemoryNeed>& needs, int processor, std::int64_t capacity,
                       machine::MemoryLimit limit);

// a * b, saturating at INT64_MAX instead of overflowing (sizes from the command line).
std::int64_t saturating_product(std::int64_t a, std::int64_t b);

}  // namespace gcsim::pipeline
