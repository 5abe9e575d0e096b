#include "apps/pipeline/resource_check.hpp"

#include <unistd.h>

#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "parix/processor.hpp"

namespace gcsim::pipeline {

std::int64_t host_available_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream in(line);
    std::string key;
    std::int64_t kb = 0;
    if (in >> key >> kb && key == "MemAvailable:") return kb * 1024;
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return std::int64_t(pages) * page;
  return -1;
}

void check_host_memory(std::int64_t bytes, std::string_view what) {
  const std::int64_t available = host_available_bytes();
  if (available < 0 || bytes <= available) return;
  throw HostMemoryError(fmt::format("{} needs about {} of host memory; this host has {} available", what,
                                    machine::format_bytes(bytes), machine::format_bytes(available)));
}

void check_node_memory(const std::vector<MemoryNeed>& needs, int processor, std::int64_t capacity,
                       machine::MemoryLimit limit) {
  machine::NodeMemory node(capacity, limit);
  for (const MemoryNeed& need : needs)
    if (!node.use(need.bytes, need.kind)) throw parix::OutOfMemoryError(node.report(processor, need.bytes, need.kind));
}

std::int64_t saturating_product(std::int64_t a, std::int64_t b) {
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  if (a <= 0 || b <= 0) return 0;
  return a > kMax / b ? kMax : a * b;
}

}  // namespace gcsim::pipeline
