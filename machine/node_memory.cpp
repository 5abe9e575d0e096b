#include "machine/node_memory.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace gcsim::machine {

MemoryLimit parse_memory_limit(std::string_view name) {
  if (name == "enforce") return MemoryLimit::enforce;
  if (name == "warn") return MemoryLimit::warn;
  throw std::invalid_argument(fmt::format("memory limit '{}': expected enforce or warn", name));
}

NodeMemory::Kind NodeMemory::kind(std::string_view name) {
  for (Kind k = 0; k < kinds_.size(); ++k)
    if (kinds_[k] == name) return k;
  kinds_.emplace_back(name);
  held_.push_back(0);  // holding nothing: breakdown() leaves it out
  return kinds_.size() - 1;
}

std::string NodeMemory::breakdown() const {
  std::vector<std::pair<std::int64_t, std::string_view>> kinds;
  for (Kind k = 0; k < kinds_.size(); ++k)
    if (held_[k] > 0) kinds.emplace_back(held_[k], kinds_[k]);
  // Largest first; equal sizes by name.
  std::sort(kinds.begin(), kinds.end(),
            [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  std::string out;
  for (const auto& [bytes, kind] : kinds) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", kind, format_bytes(bytes));
  return out.empty() ? "nothing" : out;
}

std::string NodeMemory::report(int processor, std::int64_t asked, std::string_view kind) const {
  if (asked <= 0) {
    return fmt::format("processor {}: node memory over its limit: holds {} ({}); the node has {}", processor,
                       format_bytes(used_), breakdown(), format_bytes(capacity_));
  }
  const std::string holding =
      used_ > 0 ? fmt::format("while holding {} ({})", format_bytes(used_), breakdown()) : std::string("alone");
  return fmt::format("processor {}: out of node memory: {} {} asked {}; the node has {}", processor, kind,
                     format_bytes(asked), holding, format_bytes(capacity_));
}

std::string format_bytes(std::int64_t bytes) {
  if (bytes < 0) return fmt::format("-{}", format_bytes(-bytes));
  const double b = static_cast<double>(bytes);
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  if (b < 1024.0 * 1024) return fmt::format("{:.1f} KB", b / 1024);
  if (b < 1024.0 * 1024 * 1024) return fmt::format("{:.1f} MB", b / (1024.0 * 1024));
  return fmt::format("{:.1f} GB", b / (1024.0 * 1024 * 1024));
}

}  // namespace gcsim::machine
